from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch_ros.actions import Node


# The same reads in a file another launch file of the workspace names (bringup.launch.py):
# it is meant to be included, and its includer sets 'camera_ns'; checked on its own, the
# read is not held against it.


def camera(context):
    ns = context.launch_configurations['camera_ns']  # expect-not: LV201  # expect-not: LV002
    return [Node(package='usb_cam', executable='usb_cam_node_exe', name='camera', namespace=ns)]


def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=camera)])
