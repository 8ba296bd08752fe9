"""nav2-like localization driven by launch itself, with handler labels rcl never publishes.

launch_ros compares OnStateTransition's labels with the event's by ==: 'configured' and
'Active' match nothing, so the activation and the planner they gate never happen.
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
    return LaunchDescription([
        map_server,
        amcl,
        change(map_server, Transition.TRANSITION_CONFIGURE),
        change(amcl, Transition.TRANSITION_CONFIGURE),
        # a configured node is 'inactive': this activation is never sent
        # expect: LV503
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=map_server,
            goal_state='configured',  # expect: LV508  # expect-not: LV504
            entities=[change(map_server, Transition.TRANSITION_ACTIVATE)])),
        # expect-not: LV503
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=amcl, goal_state='inactive',  # expect-not: LV504 LV508
            entities=[change(amcl, Transition.TRANSITION_ACTIVATE)])),
        # rcl's labels are lower case: the planner never starts
        # expect: LV503
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=amcl,
            goal_state='Active',  # expect: LV508  # expect-not: LV504
            entities=[Node(package='nav2_planner', executable='planner_server',
                           name='planner_server')])),
        # waits for map_server to become active, which only the 'configured' handler would
        # bring about: that handler is the finding, not this one
        # expect-not: LV503
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=map_server, goal_state='active',
            entities=[LogInfo(msg='map ready')])),
    ])
