from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, ThisLaunchFileDir
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        DeclareLaunchArgument('robot', default_value='r1'),
        Node(package='demo_nodes_cpp', executable='talker', name='talker',
             namespace=LaunchConfiguration('robot'),
             parameters=[{'use_sim_time': LaunchConfiguration('use_sim_time')}]),
        # camera_rate is declared by a nested include: passing it from the top is fine
        IncludeLaunchDescription(PythonLaunchDescriptionSource(
            [ThisLaunchFileDir(), '/camera.launch.py'])),
    ])
