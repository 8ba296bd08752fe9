import os

from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution, ThisLaunchFileDir
from launch_ros.actions import Node, SetParametersFromFile


def generate_launch_description():
    config = os.path.join(os.path.dirname(__file__), 'config')
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='talker',
             parameters=[
                 os.path.join(config, 'talker.yaml'),
                 os.path.join(config, 'taker.yaml'),  # expect: LV302
             ]),
        SetParametersFromFile(  # expect: LV302
            PathJoinSubstitution([ThisLaunchFileDir(), 'config', 'global.yaml'])),
    ])
