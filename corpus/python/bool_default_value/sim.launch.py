from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # default_value must be text or substitutions: launch raises
        # TypeError: 'bool' object is not iterable
        DeclareLaunchArgument('use_sim_time', default_value=False),  # expect: LV002
        Node(package='demo_nodes_cpp', executable='talker', name='talker',
             parameters=[{'use_sim_time': LaunchConfiguration('use_sim_time')}]),
    ])
