from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('simulated', default_value='false'),
        Node(package='demo_nodes_cpp', executable='talker', name='lidar'),
        Node(package='demo_nodes_cpp', executable='talker', name='real_lidar_watchdog',
             condition=UnlessCondition(LaunchConfiguration('simulated'))),  # expect-not: LV205
    ])
