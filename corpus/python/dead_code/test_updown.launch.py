# nav2's test_updown_launch.py passes autostart:=False down to slam: the handler above is
# never registered under this root, whatever the user sets, so nothing is said about it
# here (it was reported as waiting for a node that cannot run where it is registered).
import os

from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource


def generate_launch_description():
    here = os.path.dirname(__file__)
    return LaunchDescription([
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(os.path.join(here, 'slam.launch.py')),
            launch_arguments={'autostart': 'False'}.items()),
    ])
