"""The Python twin of conditions/path_sensitive_duplicates."""

import os

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.conditions import (IfCondition, LaunchConfigurationEquals,
                               LaunchConfigurationNotEquals, UnlessCondition)
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushRosNamespace


def generate_launch_description():
    use_sim = LaunchConfiguration('use_sim')
    here = os.path.dirname(__file__)
    return LaunchDescription([
        DeclareLaunchArgument('use_sim', default_value='false'),
        DeclareLaunchArgument('mode', default_value='nav', choices=['nav', 'mapping', 'idle']),
        DeclareLaunchArgument('namespace', default_value='robot1'),
        Node(package='demo_nodes_cpp', executable='talker', name='talker'),
        Node(package='demo_nodes_py', executable='talker', name='talker',  # expect: LV101
             condition=IfCondition(use_sim)),
        Node(package='demo_nodes_cpp', executable='listener', name='driver',
             condition=IfCondition(use_sim)),
        Node(package='demo_nodes_cpp', executable='listener', name='driver',  # expect-not: LV101
             condition=UnlessCondition(use_sim)),
        Node(package='demo_nodes_cpp', executable='talker', name='planner',
             condition=LaunchConfigurationEquals('mode', 'nav')),
        Node(package='demo_nodes_cpp', executable='talker', name='planner',  # expect-not: LV101
             condition=LaunchConfigurationEquals('mode', 'mapping')),
        Node(package='demo_nodes_cpp', executable='talker', name='mapper',
             condition=LaunchConfigurationEquals('mode', 'mapping')),
        Node(package='demo_nodes_cpp', executable='talker', name='mapper',  # expect: LV101
             condition=LaunchConfigurationNotEquals('mode', 'nav')),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(os.path.join(here, 'camera.launch.py')),
            condition=IfCondition(use_sim)),
        Node(package='usb_cam', executable='usb_cam_node_exe', name='camera',  # expect-not: LV101
             condition=UnlessCondition(use_sim)),
        GroupAction([
            PushRosNamespace(LaunchConfiguration('namespace')),
            Node(package='demo_nodes_cpp', executable='talker', name='talker'),  # expect-not: LV101
        ]),
        GroupAction([
            PushRosNamespace(LaunchConfiguration('mode')),
            Node(package='demo_nodes_cpp', executable='talker', name='status'),
        ]),
        Node(package='demo_nodes_cpp', executable='talker', name='status',  # expect: LV101
             namespace='mapping'),
    ])
