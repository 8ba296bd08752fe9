"""The sensor's launch file is found from an argument: every choice is tried."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    sensor = LaunchConfiguration('sensor')
    return LaunchDescription([
        DeclareLaunchArgument('sensor', default_value='velodyne',
                              choices=['velodyne', 'ouster']),
        IncludeLaunchDescription(PathJoinSubstitution(
            [FindPackageShare([sensor, '_sensor_launch']), 'launch', 'driver.launch.xml']),
            launch_arguments={'frame': 'lidar_link'}.items()),
    ])
