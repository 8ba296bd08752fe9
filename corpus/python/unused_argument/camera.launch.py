from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    # camera_name comes from the includer's scope: includes are not scoped
    return LaunchDescription([
        Node(package='usb_cam', executable='usb_cam_node_exe',
             name=LaunchConfiguration('camera_name', default='camera')),
    ])
