import os

from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from vendor_helpers import robot_config

CONFIG = robot_config()


def generate_launch_description():
    return LaunchDescription([
        IncludeLaunchDescription(  # expect-not: LV208
            PythonLaunchDescriptionSource(os.path.join(os.path.dirname(__file__),
                                                       'needs_robot.launch.py')),
            launch_arguments=CONFIG.arguments.items()),
    ])
