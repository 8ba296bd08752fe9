"""Helpers shared by the launch files of this folder."""

from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

SENSORS = ('front', 'rear')


def make_nodes(robot):
    nodes = [Node(package='demo_nodes_cpp', executable='talker', name=f'{side}_camera',
                  namespace=robot) for side in SENSORS]
    nodes.append(Node(package='demo_nodes_cpp', executable='listener', name='fusion',
                      namespace=robot,
                      parameters=[{'rate': LaunchConfiguration('fusion_rate')}]))
    return nodes


def make_logger():
    # no namespace: every robot's logger is /logger
    return Node(package='demo_nodes_cpp', executable='listener', name='logger')  # expect: LV101
