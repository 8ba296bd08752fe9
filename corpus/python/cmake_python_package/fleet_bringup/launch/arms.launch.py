# The bug: only the imported helper tells that two nodes are called 'arm'.
from fleet_names.naming import arm_names
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name=name)  # expect: LV101
        for name in arm_names()
    ])
