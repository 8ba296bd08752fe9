from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot_name', default_value='robot'),
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        Node(package='demo_nodes_cpp', executable='listener',
             name=LaunchConfiguration('robot_name'),
             parameters=[{'use_sim_time': LaunchConfiguration('use_sim_time')}]),
    ])
