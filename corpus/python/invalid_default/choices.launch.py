from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument(  # expect: LV203
            'robot_model', default_value='Burger', choices=['burger', 'waffle']),
        DeclareLaunchArgument('mode', default_value='sim', choices=['sim', 'real']),
        Node(package='demo_nodes_cpp', executable='talker',
             name=[LaunchConfiguration('robot_model'), '_', LaunchConfiguration('mode')]),
    ])
