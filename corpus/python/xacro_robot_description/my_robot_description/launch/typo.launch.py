import os

import xacro
from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    share = get_package_share_directory('my_robot_description')
    # the file is robot.urdf.xacro: xacro raises while the launch file loads
    doc = xacro.process_file(os.path.join(share, 'urdf', 'robot.xacro'))  # expect: LV002
    return LaunchDescription([
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{'robot_description': doc.toxml()}]),
    ])
