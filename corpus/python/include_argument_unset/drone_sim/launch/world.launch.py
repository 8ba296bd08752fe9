# The configuration is declared only for a custom world: with the arguments as given
# (custom_world false) nothing sets it, and launch stops at the include that reads it.
import os

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration


def generate_launch_description():
    bridges = os.path.join(os.path.dirname(__file__), 'bridges.launch.py')
    custom = IfCondition(LaunchConfiguration('custom_world'))
    return LaunchDescription([
        DeclareLaunchArgument('custom_world', default_value='false'),
        DeclareLaunchArgument('world_file', default_value='world.yaml', condition=custom),
        # trap: read only where it is declared, under the same condition
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(bridges),
            launch_arguments={
                'simulation_config_file': LaunchConfiguration('world_file'),  # expect-not: LV201
            }.items(),
            condition=custom),
        # bug: read whatever custom_world is
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(bridges),
            launch_arguments={
                'simulation_config_file': LaunchConfiguration('world_file'),  # expect: LV201
            }.items()),
    ])
