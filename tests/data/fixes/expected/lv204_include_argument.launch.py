from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    sensors = PathJoinSubstitution([FindPackageShare('demo'), 'launch', 'sensors.launch.xml'])
    return LaunchDescription([
        IncludeLaunchDescription(sensors, launch_arguments={'robot_name': 'r2'}.items()),
    ])
