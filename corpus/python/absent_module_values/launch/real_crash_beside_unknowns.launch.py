# The vendor's values are unknown, but this file fails whatever they are.
from launch import LaunchDescription
from launch_ros.actions import Node
from vendor_helpers import robot_config

CONFIG = robot_config()


def generate_launch_description():
    names = [robot.name for robot in CONFIG.robots]
    return LaunchDescription([
        Node(package='demo_nodes_cpp', node_executable='talker', name=names),  # expect: LV002
    ])
