import os

from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import ThisLaunchFileDir


def generate_launch_description():
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(  # expect: LV302
            [ThisLaunchFileDir(), '/sensor.launch.py'])),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            [ThisLaunchFileDir(), '/sensors.launch.py'])),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            '/opt/ros/humble/share/some_pkg/launch/outside.launch.py')),
    ])
