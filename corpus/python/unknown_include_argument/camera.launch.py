from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('camera_rate', default_value='15'),
        Node(package='usb_cam', executable='usb_cam_node_exe', name='camera',
             parameters=[{'framerate': LaunchConfiguration('camera_rate')}]),
    ])
