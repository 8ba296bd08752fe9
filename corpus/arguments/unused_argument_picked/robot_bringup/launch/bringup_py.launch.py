"""The same pick by name, written in Python."""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    kit_share = FindPackageShare([LaunchConfiguration('sensor_kit'), '_launch'])
    return LaunchDescription([
        DeclareLaunchArgument('sensor_kit', default_value='acme_kit'),
        IncludeLaunchDescription(
            PathJoinSubstitution([kit_share, 'launch', 'sensing.launch.xml']),
            launch_arguments={'calibration_file': '/opt/robot/calibration.yaml'}.items(),
        ),
    ])
