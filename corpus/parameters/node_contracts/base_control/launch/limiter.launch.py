"""A node whose parameters generate_parameter_library validates at start."""
import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    limiter = os.path.join(os.path.dirname(__file__), '..', 'config', 'limiter.yaml')
    return LaunchDescription([
        Node(package='base_control', executable='velocity_limiter', parameters=[limiter]),
        Node(package='base_control', executable='velocity_limiter', name='limiter_fixed',
             parameters=[limiter]),
        # input_topic has no default: the generated listener throws at start
        Node(package='base_control', executable='velocity_limiter',  # expect: LV408
             name='limiter_bare'),
    ])
