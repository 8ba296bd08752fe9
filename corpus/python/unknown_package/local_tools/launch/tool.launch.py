from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='local_tools', executable='tool', name='tool2'),
    ])
