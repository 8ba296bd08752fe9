"""One node's domain set, its twin's left to the shell that runs the launch."""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='driver',
             additional_env={'ROS_DOMAIN_ID': '0'}),
        # the same name in domain 0 unless the caller exports another domain
        Node(package='demo_nodes_cpp', executable='talker', name='driver'),  # expect-warning: LV101
        Node(package='demo_nodes_cpp', executable='talker', name='logger',
             additional_env={'ROS_DOMAIN_ID': '5'}),
        # domain 5 against the default: apart unless the caller exports 5
        Node(package='demo_nodes_cpp', executable='talker', name='logger'),  # expect-not: LV101
    ])
