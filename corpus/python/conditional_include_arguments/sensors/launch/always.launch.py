# A value launch rejects on an include that always runs fails whatever the arguments.
import os

from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource


def generate_launch_description():
    camera = os.path.join(os.path.dirname(__file__), 'camera.launch.py')
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(camera),
                                 launch_arguments={'rate': 2.5}.items()),  # expect: LV002
    ])
