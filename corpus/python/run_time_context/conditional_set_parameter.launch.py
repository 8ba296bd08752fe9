# SetParameter under a condition false by default reaches no node by default.
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, SetParameter


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('sim', default_value='false'),
        SetParameter('use_sim_time', True, condition=IfCondition(LaunchConfiguration('sim'))),
        Node(package='demo_nodes_cpp', executable='talker', name='driver'),
        Node(package='demo_nodes_cpp', executable='listener', name='logger',  # expect-not: LV404
             parameters=[{'use_sim_time': False}]),
    ])
