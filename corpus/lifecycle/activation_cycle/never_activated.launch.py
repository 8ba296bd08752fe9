"""The planner starts when the map server is active, but nothing ever activates it."""
from launch import LaunchDescription
from launch.actions import EmitEvent, RegisterEventHandler
from launch.events import matches_action
from launch_ros.actions import LifecycleNode, Node
from launch_ros.event_handlers import OnStateTransition
from launch_ros.events.lifecycle import ChangeState
from lifecycle_msgs.msg import Transition


def generate_launch_description():
    map_server = LifecycleNode(package='nav2_map_server', executable='map_server',
                               name='map_server', namespace='')
    configure = EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(map_server),
                                            transition_id=Transition.TRANSITION_CONFIGURE))
    return LaunchDescription([
        map_server,
        configure,
        # expect: LV503
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=map_server, goal_state='active',
            entities=[Node(package='planner', executable='planner', name='planner')])),
        # reached: the node does become inactive
        # expect-not: LV503
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=map_server, goal_state='inactive',
            entities=[Node(package='planner', executable='costmap', name='costmap')])),
    ])
