"""The same controller, its parameters as it declares them."""
import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    config = os.path.join(os.path.dirname(__file__), '..', 'config')
    return LaunchDescription([
        Node(package='base_control', executable='base_controller',  # expect-not: LV408
             parameters=[os.path.join(config, 'base_fixed.yaml')]),
    ])
