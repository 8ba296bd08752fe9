from launch import LaunchDescription
from launch_ros.actions import Node
from vendor_helpers import robot_config

CONFIG = robot_config()


def generate_launch_description():
    assert isinstance(CONFIG.robots, dict)  # expect-info: LV003
    return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker')])
