import os
import sys

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument

# ros2 launch does not put the launch file's folder on sys.path: add it first
sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))
from my_helpers import make_logger, make_nodes  # noqa: E402


def generate_launch_description():
    ld = LaunchDescription([DeclareLaunchArgument('fusion_rate', default_value='10')])
    for robot in ('alpha', 'beta'):
        for node in make_nodes(robot):
            ld.add_action(node)
        ld.add_action(make_logger())
    return ld
