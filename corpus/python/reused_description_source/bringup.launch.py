import os

from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource


def generate_launch_description():
    # a description source loads its file once and hands out the same LaunchDescription
    # (the same Node objects) to every include that uses it: the second include executes
    # the same Node again and launch raises
    # RuntimeError: ExecuteLocal action 'usb_cam_node_exe-2': executed more than once
    camera = PythonLaunchDescriptionSource(
        os.path.join(os.path.dirname(__file__), 'cameras.launch.py'))
    return LaunchDescription([
        IncludeLaunchDescription(camera, launch_arguments={'name': 'front'}.items()),
        IncludeLaunchDescription(camera, launch_arguments={'name': 'rear'}.items()),  # expect: LV002
    ])
