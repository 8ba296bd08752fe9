"""The base controller with a parameter file that misspells and mistypes."""
import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    config = os.path.join(os.path.dirname(__file__), '..', 'config')
    return LaunchDescription([
        Node(package='base_control', executable='base_controller',
             parameters=[os.path.join(config, 'base.yaml')]),
        # allow_undeclared_parameters: anything goes
        Node(package='base_control', executable='flexible_node', name='flexible',
             parameters=[{'whatever': 1, 'rate': 20}]),  # expect-not: LV405
    ])
