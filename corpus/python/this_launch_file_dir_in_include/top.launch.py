import os

from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import ThisLaunchFileDir

HERE = os.path.dirname(os.path.abspath(__file__))


def generate_launch_description():
    camera = os.path.join(HERE, 'robot', 'camera.launch.py')
    return LaunchDescription([
        # the include's arguments are performed in the included file's context:
        # ThisLaunchFileDir() is robot/, and robot/config/camera.yaml does not exist
        IncludeLaunchDescription(PythonLaunchDescriptionSource(camera), launch_arguments=[
            ('params', [ThisLaunchFileDir(), '/config/camera.yaml'])]),
        # os.path.join runs in this file: config/camera.yaml beside top.launch.py
        IncludeLaunchDescription(PythonLaunchDescriptionSource(camera), launch_arguments=[
            ('params', os.path.join(HERE, 'config', 'camera.yaml')),
            ('name', 'camera2')]),
    ])
