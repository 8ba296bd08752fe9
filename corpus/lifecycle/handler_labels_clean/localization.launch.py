"""The twin of handler_labels_misspelled: the labels rcl publishes, and a bring-up that ends.

Configure at launch, activate when the node reaches 'inactive' (the end of configuring),
start the planner when amcl is 'active'.
"""
from launch import LaunchDescription
from launch.actions import EmitEvent, LogInfo, RegisterEventHandler
from launch.events import matches_action
from launch_ros.actions import LifecycleNode, Node
from launch_ros.event_handlers import OnStateTransition
from launch_ros.events.lifecycle import ChangeState
from lifecycle_msgs.msg import Transition


def change(node, transition):
    return EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(node),
                                       transition_id=transition))


def generate_launch_description():
    map_server = LifecycleNode(package='nav2_map_server', executable='map_server',
                               name='map_server', namespace='')
    amcl = LifecycleNode(package='nav2_amcl', executable='amcl', name='amcl', namespace='')
    on_amcl_inactive = OnStateTransition(
        target_lifecycle_node=amcl, start_state='configuring',  # expect-not: LV504 LV508
        goal_state='inactive',
        entities=[change(amcl, Transition.TRANSITION_ACTIVATE)])
    return LaunchDescription([
        map_server,
        amcl,
        change(map_server, Transition.TRANSITION_CONFIGURE),
        change(amcl, Transition.TRANSITION_CONFIGURE),
        # expect-not: LV503
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=map_server,
            goal_state='inactive',  # expect-not: LV504 LV508
            entities=[change(map_server, Transition.TRANSITION_ACTIVATE)])),
        # expect-not: LV503
        RegisterEventHandler(on_amcl_inactive),
        # expect-not: LV503
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=amcl,
            start_state='activating', goal_state='active',  # expect-not: LV504 LV508
            entities=[Node(package='nav2_planner', executable='planner_server',
                           name='planner_server')])),
        # expect-not: LV503
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=map_server, goal_state='active',
            entities=[LogInfo(msg='map ready')])),
        # fires on the way down, even on a failed shutdown
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=map_server, goal_state='finalized',  # expect-not: LV504 LV508
            entities=[LogInfo(msg='map server finalized')])),
        # a transition label: events carry one on rolling (ros2/rcl#1269), so with no
        # distribution given this may fire; --distro jazzy reports it (test_lifecycle.py)
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=map_server, transition='configure',  # expect-not: LV504 LV508
            entities=[LogInfo(msg='map server configuring')])),
    ])
