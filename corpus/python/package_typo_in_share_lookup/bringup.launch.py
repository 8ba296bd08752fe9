import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node


def generate_launch_description():
    # raises PackageNotFoundError here, whether or not the result is used
    description_dir = get_package_share_directory('demo_node_cpp')  # expect: LV303
    urdf = os.path.join(description_dir, 'urdf', 'robot.urdf')
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='talker',
             parameters=[{'urdf_path': urdf}]),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            os.path.join(get_package_share_directory('demo_nodes_cpp'), 'launch',
                         'topics', 'talker_listener.launch.py'))),
    ])
