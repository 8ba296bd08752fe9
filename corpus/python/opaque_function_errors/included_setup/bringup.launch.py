import os

from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription, SetLaunchConfiguration
from launch.launch_description_sources import PythonLaunchDescriptionSource


def generate_launch_description():
    here = os.path.dirname(__file__)
    return LaunchDescription([
        SetLaunchConfiguration('camera_ns', 'front'),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            os.path.join(here, 'camera_setup.launch.py'))),
        SetLaunchConfiguration('selector_param_path', os.path.join(here, 'selector.yaml')),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            os.path.join(here, 'selector.launch.py'))),
    ])
