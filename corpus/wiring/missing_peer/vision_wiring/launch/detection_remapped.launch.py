"""The same, with the private input remapped to the camera's output: connected."""

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='vision_wiring', executable='camera'),
        Node(package='vision_wiring', executable='detector',  # expect-not: LV602
             remappings=[('~/image_raw', '/image_raw')]),
    ])
