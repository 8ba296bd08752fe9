from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    left = LaunchConfiguration('left')
    right = LaunchConfiguration('right')
    return LaunchDescription([
        DeclareLaunchArgument('left', default_value='camera'),
        DeclareLaunchArgument('right', default_value='camera'),
        Node(package='usb_cam', executable='usb_cam_node_exe', name=left),
        Node(package='usb_cam', executable='usb_cam_node_exe', name=right),  # expect: LV101
        Node(package='usb_cam', executable='usb_cam_node_exe', name=[left, '_rect']),
        Node(package='usb_cam', executable='usb_cam_node_exe',  # expect-not: LV101
             name=[right, '_raw']),
    ])
