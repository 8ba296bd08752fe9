"""The detector's input is private (~/image_raw): it listens on /detector/image_raw."""

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='vision_wiring', executable='camera'),
        Node(package='vision_wiring', executable='detector'),  # expect-warning: LV602
    ])
