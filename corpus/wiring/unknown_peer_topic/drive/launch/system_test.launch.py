# nav2_system_tests' way: the parameter file comes from the environment, so where the
# relay publishes is unknown here; this launch cannot say the two are apart
import os

from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import AnyLaunchDescriptionSource


def generate_launch_description():
    here = os.path.dirname(os.path.abspath(__file__))
    return LaunchDescription([
        IncludeLaunchDescription(
            AnyLaunchDescriptionSource(os.path.join(here, 'drive.launch.xml')),
            launch_arguments={'params_file': os.getenv('PARAMS_FILE', '')}.items()),
    ])
