import some_vendor_sdk  # expect: LV003
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    serial = some_vendor_sdk.first_device().serial
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='camera',
             parameters=[{'serial': str(serial)}]),
        Node(package='demo_nodes_cpp', executable='talker', name='camera'),  # expect: LV101
    ])
