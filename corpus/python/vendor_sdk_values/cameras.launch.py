import some_vendor_sdk  # expect: LV003
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    # on the robot the SDK is installed and lists the connected cameras; here its values
    # are unknown, which is not an error of the launch file
    cameras = some_vendor_sdk.list_cameras()
    count = len(cameras)  # expect-not: LV002
    timeout = some_vendor_sdk.DEFAULT_TIMEOUT * 2  # expect-not: LV002
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name=f'camera_{i}',
             parameters=[{'timeout': timeout}])
        for i in range(count)
    ])
