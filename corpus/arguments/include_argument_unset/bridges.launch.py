# Included with the simulation's configuration file; checks its extension in Python.
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def bridges(context):
    config_file = LaunchConfiguration('simulation_config_file').perform(context)
    if not config_file.endswith(('.yaml', '.yml')):
        # trap: an includer that passes a configuration nothing sets stops at its include,
        # so this code never sees a value (and the file reached alone gets one from its
        # includer)
        raise ValueError('invalid configuration file extension')  # expect-not: LV002
    return [Node(package='ros_gz_bridge', executable='parameter_bridge', name='bridge',
                 parameters=[config_file])]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('simulation_config_file'),
        OpaqueFunction(function=bridges),
    ])
