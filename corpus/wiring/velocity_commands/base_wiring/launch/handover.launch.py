"""The follower takes over once the teleop session has ended: never both at once."""

from launch import LaunchDescription
from launch.actions import RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch_ros.actions import Node


def generate_launch_description():
    teleop = Node(package='base_wiring', executable='teleop')
    follower = Node(package='base_wiring', executable='follower')  # expect-not: LV604
    return LaunchDescription([
        teleop,
        RegisterEventHandler(OnProcessExit(target_action=teleop, on_exit=[follower])),
    ])
