"""One robot's arm: the handler's node runs outside the includer's group."""

from launch import LaunchDescription
from launch.actions import RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch_ros.actions import Node


def generate_launch_description():
    spawner = Node(package='controller_manager', executable='spawner',
                   arguments=['arm_controller'])
    return LaunchDescription([
        RegisterEventHandler(OnProcessExit(target_action=spawner, on_exit=[
            Node(package='demo_nodes_cpp', executable='talker', name='arm_loader'),  # expect: LV101
        ])),
        spawner,
    ])
