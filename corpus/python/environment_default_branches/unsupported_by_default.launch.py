"""A launch file that refuses a setting only the robot's environment can make."""
import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    if os.environ.get('ROBOT_KIND', 'arm') == 'arm':
        # fails only where the robot leaves ROBOT_KIND unset: not a fact
        raise RuntimeError('this launch starts rovers only')  # expect-not: LV002
    if os.environ.get('ROBOT_KIND', 'arm') not in ('arm', 'rover'):
        raise RuntimeError('unknown robot kind')  # expect-not: LV002 LV003
    return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker')])
