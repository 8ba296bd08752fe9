import os

from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node


def generate_launch_description():
    here = os.path.dirname(os.path.abspath(__file__))
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='b'),
        IncludeLaunchDescription(  # expect: LV301
            PythonLaunchDescriptionSource(os.path.join(here, 'a.launch.py'))),
    ])
