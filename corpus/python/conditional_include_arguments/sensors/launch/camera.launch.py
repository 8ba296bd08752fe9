from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('model', default_value='generic'),
        DeclareLaunchArgument('rate', default_value='30'),
        Node(package='demo_nodes_cpp', executable='talker', name='camera',
             parameters=[{'model': LaunchConfiguration('model'),
                          'rate': LaunchConfiguration('rate')}]),
    ])
