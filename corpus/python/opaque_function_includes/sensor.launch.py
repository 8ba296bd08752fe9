from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot'),
        DeclareLaunchArgument('sensor'),
        # 'lidar' is in the list twice: /rover/lidar_driver starts twice
        Node(package='demo_nodes_cpp', executable='talker',  # expect: LV101
             name=[LaunchConfiguration('sensor'), '_driver'],
             namespace=LaunchConfiguration('robot')),
    ])
