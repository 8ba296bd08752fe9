"""A launch file that picks its nodes by the ROS distribution, read with a default.

The graph follows the default's branch, as ros2 launch does on a machine that does not set
the variable (``$(env NAME default)`` reads the same way); a failure there is a fact only
if it also happens when the robot sets the variable otherwise.
"""
import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    distro = os.environ.get('ROS_DISTRO', 'humble')
    if distro == 'humble':
        nodes = [
            Node(package='demo_nodes_cpp', executable='talker', name='bridge'),
            Node(package='demo_nodes_cpp', executable='listener', name='bridge'),  # expect: LV101
        ]
    else:
        # taken only where the robot sets another distribution: not judged as the default
        nodes = [
            Node(package='demo_nodes_cpp', executable='talker', name='relay'),
            Node(package='demo_nodes_cpp', executable='listener', name='relay'),  # expect-not: LV101
        ]
    if os.getenv('USE_SIM_TIME', 'False').lower() == 'true':
        nodes.append(Node(package='demo_nodes_cpp', executable='talker', name='bridge'))  # expect-not: LV101
    return LaunchDescription(nodes)
