import os

from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource


def generate_launch_description():
    robot = os.path.join(os.path.dirname(__file__), 'robot.launch.py')
    # argument values must be text: launch raises TypeError: 'bool' object is not iterable
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(robot),
                                 launch_arguments={'robot': 'r3',
                                                   'use_sim_time': True}.items()),  # expect: LV002
    ])
