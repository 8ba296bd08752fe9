from launch import LaunchDescription
from launch_ros.actions import Node
from vendor_helpers import robot_config

CONFIG = robot_config()


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='driver',
             namespace=CONFIG.namespace),
        Node(package='demo_nodes_cpp', executable='talker', name='talker'),
        Node(package='demo_nodes_cpp', executable='listener', name='talker'),  # expect: LV101
    ])
