from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    use_sim_time = LaunchConfiguration('use_sim_time')
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        Node(package='demo_nodes_cpp', executable='talker', name='talker',
             condition=IfCondition(LaunchConfiguration('use_sim_tme'))),  # expect: LV201
        Node(package='demo_nodes_cpp', executable='listener', name='listener',
             parameters=[{'use_sim_time': use_sim_time}]),
    ])
