"""Nodes without name=: the controller names itself 'controller_server' in its code."""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='my_controller', executable='controller'),
        # the code of my_controller names no 'smoother_server': nothing launched has it
        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager',  # expect: LV505
             name='lifecycle_manager_navigation',
             parameters=[{'autostart': True,
                          'node_names': ['controller_server', 'smoother_server']}]),
    ])
