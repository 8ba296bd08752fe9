from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    debug = LaunchConfiguration('debug')
    return LaunchDescription([
        DeclareLaunchArgument('debug', default_value='false'),
        # declared under a condition: launch's pre-check does not require it
        DeclareLaunchArgument('log_file', condition=IfCondition(debug)),
        Node(package='demo_nodes_cpp', executable='listener', name='listener'),
        Node(package='demo_nodes_cpp', executable='talker', name='logger',
             condition=IfCondition(debug),
             parameters=[{'file': LaunchConfiguration('log_file')}]),
    ])
