import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    robot = os.environ.get('ROBOT_ID', 'robot_1').split('_')[1]
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='driver_' + robot),  # expect-not: LV102
    ])
