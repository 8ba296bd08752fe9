# perform_typed_substitution with the launch file's own int, float and list types: the
# values are known, so the loop below runs twice (and its two drivers clash), not
# "Unrecognized data type" (LV002).
from typing import List

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch.utilities import perform_typed_substitution
from launch_ros.actions import Node


def launch_setup(context):
    count = perform_typed_substitution(context, LaunchConfiguration('count'), int)  # expect-not: LV002
    rate = perform_typed_substitution(context, LaunchConfiguration('rate'), float)  # expect-not: LV002
    ids = perform_typed_substitution(context, LaunchConfiguration('ids'), List[int])  # expect-not: LV002
    return [Node(package='demo_nodes_cpp', executable='talker', name='driver',  # expect: LV101
                 parameters=[{'rate': rate, 'ids': ids}])
            for _ in range(count)]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('count', default_value='2'),
        DeclareLaunchArgument('rate', default_value='10.0'),
        DeclareLaunchArgument('ids', default_value='[1, 2]'),
        OpaqueFunction(function=launch_setup),
    ])
