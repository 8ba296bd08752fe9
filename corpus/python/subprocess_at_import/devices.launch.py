import subprocess

from launch import LaunchDescription
from launch_ros.actions import Node

CAMERAS = subprocess.run(['ls', '/dev/v4l/by-id'],  # expect: LV003
                         capture_output=True, text=True).stdout.split()


def generate_launch_description():
    return LaunchDescription([
        Node(package='usb_cam', executable='usb_cam_node_exe', name=f'camera_{i}')
        for i, _ in enumerate(CAMERAS)
    ])
