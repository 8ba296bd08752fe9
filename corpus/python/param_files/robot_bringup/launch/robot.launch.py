"""The Python twin of parameters/param_files."""

import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import GroupAction
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node, PushRosNamespace
from launch_ros.descriptions import ParameterFile
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    config = os.path.join(get_package_share_directory('robot_bringup'), 'config')
    controllers = PathJoinSubstitution([FindPackageShare('robot_bringup'), 'config',
                                        'controllers.yaml'])
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='talker',
             parameters=[os.path.join(config, 'robot.yaml')]),
        GroupAction([
            PushRosNamespace('robot1'),
            Node(package='demo_nodes_cpp', executable='listener', name='listener',
                 parameters=[ParameterFile(os.path.join(config, 'robot.yaml'))]),
        ]),
        Node(package='usb_cam', executable='usb_cam_node_exe', name='camera',
             parameters=[os.path.join(config, 'camera.yaml')]),
        Node(package='demo_nodes_cpp', executable='talker', name='left_wheel',
             parameters=[controllers]),
        Node(package='demo_nodes_cpp', executable='talker', name='right_wheel',
             parameters=[controllers]),
    ])
