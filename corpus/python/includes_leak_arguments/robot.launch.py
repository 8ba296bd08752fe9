from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='beta'),
        Node(package='demo_nodes_cpp', executable='talker', name='driver',  # expect: LV101
             namespace=LaunchConfiguration('robot')),
    ])
