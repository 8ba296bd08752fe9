from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.conditions import (IfCondition, LaunchConfigurationEquals,
                               LaunchConfigurationNotEquals, UnlessCondition)
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    use_sim = LaunchConfiguration('use_sim')
    return LaunchDescription([
        DeclareLaunchArgument('use_sim', default_value='true'),
        DeclareLaunchArgument('robot', default_value='turtle'),
        GroupAction([Node(package='demo_nodes_cpp', executable='talker', name='driver')],
                    condition=IfCondition(use_sim)),
        GroupAction([Node(package='demo_nodes_cpp', executable='listener', name='driver')],
                    condition=UnlessCondition(use_sim)),
        Node(package='demo_nodes_cpp', executable='talker', name='arm',
             condition=LaunchConfigurationEquals('robot', 'turtle')),
        Node(package='demo_nodes_cpp', executable='talker', name='arm',  # expect-not: LV101
             condition=LaunchConfigurationNotEquals('robot', 'turtle')),
    ])
