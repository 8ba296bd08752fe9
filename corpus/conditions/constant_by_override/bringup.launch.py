from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, SetLaunchConfiguration
from launch.conditions import LaunchConfigurationEquals, UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('mode', default_value='mapping', choices=['mapping', 'localization']),
        DeclareLaunchArgument('headless', default_value='false'),
        # forced after the declaration: mode:=localization is ignored
        SetLaunchConfiguration('mode', 'mapping'),
        Node(package='demo_nodes_cpp', executable='talker', name='mapper',
             condition=LaunchConfigurationEquals('mode', 'mapping')),  # expect: LV206
        Node(package='demo_nodes_cpp', executable='listener', name='viewer',
             condition=UnlessCondition(LaunchConfiguration('headless'))),  # expect-not: LV206
    ])
