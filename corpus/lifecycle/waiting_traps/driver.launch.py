"""Handlers that wait for what a launch does not drive: none of them is a deadlock."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, EmitEvent, LogInfo, RegisterEventHandler
from launch.conditions import IfCondition
from launch.events import Shutdown, matches_action
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import LifecycleNode
from launch_ros.event_handlers import OnStateTransition
from launch_ros.events.lifecycle import ChangeState
from lifecycle_msgs.msg import Transition


def generate_launch_description():
    auto_start = LaunchConfiguration('auto_start')
    sensor = LifecycleNode(package='ouster_ros', executable='os_driver', name='lidar',
                           namespace='sensors')
    remote = LifecycleNode(package='ouster_ros', executable='os_driver', name='remote',
                           namespace='sensors')
    return LaunchDescription([
        DeclareLaunchArgument('auto_start', default_value='true'),
        sensor,
        remote,
        EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(sensor),
                                    transition_id=Transition.TRANSITION_CONFIGURE),
                  condition=IfCondition(auto_start)),
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=sensor, goal_state='inactive',
            entities=[EmitEvent(event=ChangeState(
                lifecycle_node_matcher=matches_action(sensor),
                transition_id=Transition.TRANSITION_ACTIVATE))]),
            condition=IfCondition(auto_start)),
        # shutting down when the driver is finalized: waits for an end, not a bring-up
        # expect-not: LV503
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=sensor, goal_state='finalized',
            entities=[LogInfo(msg='driver finalized, shutting down'),
                      EmitEvent(event=Shutdown(reason='driver finalized'))])),
        # nothing in this launch moves 'remote': something outside drives it
        # expect-not: LV503
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=remote, goal_state='active',
            entities=[LogInfo(msg='remote lidar is active')])),
    ])
