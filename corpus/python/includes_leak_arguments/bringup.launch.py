from pathlib import Path

from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource


def generate_launch_description():
    robot = str(Path(__file__).parent / 'robot.launch.py')
    # Includes are not scoped: the second include inherits robot:=alpha
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(robot),
                                 launch_arguments=[('robot', 'alpha')]),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(robot)),
    ])
