"""Activate sent with the node's start: the node is still unconfigured."""
from launch import LaunchDescription
from launch.actions import EmitEvent, RegisterEventHandler
from launch.event_handlers import OnProcessStart
from launch.events import matches_action
from launch_ros.actions import LifecycleNode
from launch_ros.events.lifecycle import ChangeState
from lifecycle_msgs.msg import Transition


def generate_launch_description():
    talker = LifecycleNode(package='lifecycle', executable='lifecycle_talker',
                           name='lc_talker', namespace='')
    return LaunchDescription([
        talker,
        RegisterEventHandler(OnProcessStart(
            target_action=talker,
            on_start=[EmitEvent(event=ChangeState(  # expect: LV504
                lifecycle_node_matcher=matches_action(talker),
                transition_id=Transition.TRANSITION_ACTIVATE))])),
    ])
