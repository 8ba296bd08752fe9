from launch import LaunchDescription  # expect: LV001
from launch_ros.actions import Node


def generate_launch_descriptions():  # misspelled: ros2 launch cannot use this file
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='talker'),
    ])
