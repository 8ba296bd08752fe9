from launch import LaunchDescription
from launch_ros.actions import Node
from vendor_helpers import robot_config

CONFIG = robot_config()


def generate_launch_description():
    if CONFIG.mode not in ('sim', 'real'):
        raise ValueError('mode must be sim or real')  # expect-info: LV003
    assert isinstance(CONFIG.robots, list)
    return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker')])
