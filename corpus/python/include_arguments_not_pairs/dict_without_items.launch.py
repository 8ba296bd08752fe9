import os

from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource


def generate_launch_description():
    robot = os.path.join(os.path.dirname(__file__), 'robot.launch.py')
    # a dict iterates over its keys: launch unpacks 'robot' into (name, value) and raises
    # ValueError: too many values to unpack
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(robot),  # expect: LV002
                                 launch_arguments={'robot': 'r2'}),
    ])
