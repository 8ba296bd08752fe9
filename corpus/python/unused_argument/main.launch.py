import os

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    here = os.path.dirname(__file__)
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false'),  # expect: LV202
        DeclareLaunchArgument('robot', default_value='r1'),
        DeclareLaunchArgument('with_camera', default_value='true'),
        DeclareLaunchArgument('camera_name', default_value='front'),
        Node(package='demo_nodes_cpp', executable='talker', name='talker',
             namespace=LaunchConfiguration('robot')),
        GroupAction(
            [IncludeLaunchDescription(
                PythonLaunchDescriptionSource(os.path.join(here, 'camera.launch.py')))],
            condition=IfCondition(LaunchConfiguration('with_camera')),
        ),
    ])
