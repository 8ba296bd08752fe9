# Launch sets an include's arguments as configurations (SetLaunchConfiguration) before the
# included file runs: a value that reads a configuration nothing sets raises
# "launch configuration 'simulation_config_file' does not exist" at the include, and the
# included file never runs (IncludeLaunchDescription.execute).
import os

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration


def generate_launch_description():
    bridges = os.path.join(os.path.dirname(__file__), 'bridges.launch.py')
    return LaunchDescription([
        DeclareLaunchArgument('create_bridges', default_value='true'),
        # bug: nothing declares or sets simulation_config_file in this file
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(bridges),
            launch_arguments={
                'simulation_config_file': LaunchConfiguration('simulation_config_file'),  # expect: LV201
            }.items(),
            condition=IfCondition(LaunchConfiguration('create_bridges'))),
    ])
