import os

from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource


def include(name, **arguments):
    path = os.path.join(os.path.dirname(__file__), name)
    return IncludeLaunchDescription(PythonLaunchDescriptionSource(path),
                                    launch_arguments=arguments.items())


def generate_launch_description():
    return LaunchDescription([
        include('robot.launch.py', robot='alpha'),
        include('robot.launch.py', robot='beta'),
        include('camera.launch.py'),
        include('camera.launch.py'),
    ])
