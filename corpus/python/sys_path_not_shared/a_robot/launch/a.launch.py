import os
import sys

from launch import LaunchDescription

sys.path.append(os.path.dirname(os.path.abspath(__file__)))
from robot_helpers import drivers  # noqa: E402


def generate_launch_description():
    return LaunchDescription(drivers('alpha'))
