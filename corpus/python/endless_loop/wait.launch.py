from launch import LaunchDescription
from launch_ros.actions import Node


def wait_for_hardware():
    while True:  # expect: LV002
        pass


def generate_launch_description():
    wait_for_hardware()
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='talker'),
    ])
