"""The talker runs in simulation only."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        Node(package='demo', executable='talker', name='talker',
             condition=IfCondition(LaunchConfiguration('use_sim_time'))),  # a typo
    ])
