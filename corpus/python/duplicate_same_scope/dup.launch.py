from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    sim = LaunchConfiguration('sim')
    return LaunchDescription([
        DeclareLaunchArgument('sim', default_value='false'),
        Node(package='demo_nodes_cpp', executable='talker', name='talker'),
        Node(package='demo_nodes_py', executable='talker', name='talker'),  # expect: LV101
        Node(package='demo_nodes_cpp', executable='listener', name='camera',
             condition=IfCondition(sim)),
        Node(package='demo_nodes_cpp', executable='listener', name='camera',  # expect-not: LV101
             condition=UnlessCondition(sim)),
        Node(package='demo_nodes_cpp', executable='listener', name='listener', namespace='/'),
        Node(  # expect: LV101
            package='demo_nodes_cpp',
            executable='listener',
            name='listener',
        ),
    ])
