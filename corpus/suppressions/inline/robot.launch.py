from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='talker'),
        # launchverify: ignore[LV101]
        Node(package='demo_nodes_cpp', executable='talker', name='talker'),  # expect-not: LV101
        Node(package='demo_nodes_cpp', executable='talker', name='talker'),  # expect: LV101
        # launchverify: ignore[LV101]  # expect: LV004
        Node(package='demo_nodes_cpp', executable='listener', name='listener'),
    ])
