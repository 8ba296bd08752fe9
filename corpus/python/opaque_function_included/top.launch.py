import os

from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource


def generate_launch_description():
    # the top file launches the driver without setting "robot": the read fails (LV201)
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            os.path.join(os.path.dirname(__file__), 'driver.launch.py'))),
    ])
