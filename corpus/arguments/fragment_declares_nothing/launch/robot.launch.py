from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    # an entry point: it declares its interface, and one read has no declaration
    return LaunchDescription([
        DeclareLaunchArgument('robot_name', default_value='r1'),
        Node(package='demo_nodes_cpp', executable='talker', name='talker',
             namespace=LaunchConfiguration('robot_name'),
             parameters=[{'port': LaunchConfiguration('serial_port')}]),  # expect: LV201
    ])
