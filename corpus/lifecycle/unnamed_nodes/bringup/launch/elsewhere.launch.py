"""A node from a package whose sources are not here could be called anything."""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='nav2_smoother', executable='smoother_server'),
        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager',  # expect-not: LV505
             name='lifecycle_manager_navigation',
             parameters=[{'autostart': True, 'node_names': ['smoother_server']}]),
    ])
