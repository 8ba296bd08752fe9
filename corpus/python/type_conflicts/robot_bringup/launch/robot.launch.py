"""The Python twin of parameters/type_conflicts."""

import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node, SetParameter


def generate_launch_description():
    config = os.path.join(get_package_share_directory('robot_bringup'), 'config')
    return LaunchDescription([
        SetParameter(name='use_sim_time', value=True),
        # a parameter given in a dict points at its key
        Node(package='demo_nodes_cpp', executable='talker', name='controller', parameters=[
            os.path.join(config, 'controller.yaml'),
            {'max_vel': 1,  # expect: LV403
             'frame': 'base_link',  # expect-not: LV403
             'rate': 10.0,  # expect-not: LV403
             'limits': [3.0, 4.0]},  # expect-not: LV403
        ]),
        Node(package='demo_nodes_cpp', executable='listener', name='other',
             parameters=[{'max_vel': 1}]),  # expect-not: LV403
    ])
