"""Findings about a piece of a call point at that piece, the call is related information."""

import os

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

HERE = os.path.dirname(__file__)


def generate_launch_description():
    robot_arguments = {
        'robot_name': 'r1',
        'use_sim_tme': LaunchConfiguration('use_sim_time'),  # expect: LV204
    }
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        Node(
            package='demo_nodes_cpp',
            executable='talker',
            name='talker',
            parameters=[{
                'use_sim_time': LaunchConfiguration('use_sim_time'),
                'frame_id': LaunchConfiguration('frame'),  # expect: LV201
            }],
        ),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(os.path.join(HERE, 'robot.launch.py')),
            launch_arguments=robot_arguments.items(),
        ),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(os.path.join(HERE, 'robot.launch.py')),
            launch_arguments=[
                ('robot_name', 'r2'),
                ('namespce', 'second'),  # expect: LV204
            ],
        ),
    ])
