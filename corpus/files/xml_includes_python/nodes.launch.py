from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot'),
        # the second include would inherit robot:=alpha (includes are not scoped), but it
        # misses the required argument: launch raises there and starts no second talker
        Node(package='demo_nodes_cpp', executable='talker', name='talker',  # expect-not: LV101
             namespace=LaunchConfiguration('robot')),
    ])
