import os

from launch import LaunchDescription
from launch_ros.actions import Node

HERE = os.path.dirname(os.path.abspath(__file__))


def generate_launch_description():
    # {path} is a set holding one path: launch_ros iterates it as the path's substitutions
    # and loads the file (neuronbot2's slam_toolbox launch writes it so)
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='talker',
             parameters=[{HERE + '/config/talker.yaml'}, {'use_sim_time': False}]),  # expect-not: LV302
        Node(package='demo_nodes_cpp', executable='listener', name='listener',
             parameters=[{HERE + '/config/listener.yaml'}]),  # expect: LV302
    ])
