import os

import xacro
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    share = get_package_share_directory('my_robot_description')
    doc = xacro.process_file(os.path.join(share, 'urdf', 'robot.urdf.xacro'),
                             mappings={'prefix': 'left_'})
    robot_description = {'robot_description': doc.toxml()}
    return LaunchDescription([
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             name='robot_state_publisher', output='screen', parameters=[robot_description]),
        Node(package='joint_state_publisher', executable='joint_state_publisher',  # expect: LV101
             name='robot_state_publisher'),
    ])
