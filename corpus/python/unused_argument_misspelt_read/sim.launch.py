"""The Python twin of arguments/unused_argument_misspelt_read."""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # read only as a typo: LV201 says which name was meant, LV202 stays quiet
        DeclareLaunchArgument('gui', default_value='true'),  # expect-not: LV202
        # trap: genuinely unused, still reported
        DeclareLaunchArgument('world', default_value='empty.sdf'),  # expect: LV202
        Node(package='demo_nodes_cpp', executable='talker', name='viewer',
             condition=IfCondition(LaunchConfiguration('gu1'))),  # expect: LV201
    ])
