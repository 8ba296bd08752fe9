from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot'),
        # the second include inherits robot:=alpha (includes are not scoped)
        Node(package='demo_nodes_cpp', executable='talker', name='talker',  # expect: LV101
             namespace=LaunchConfiguration('robot')),
    ])
