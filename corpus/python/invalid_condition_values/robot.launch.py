"""The Python twin of conditions/invalid_condition_values."""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, SetLaunchConfiguration
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import EqualsSubstitution, LaunchConfiguration, PythonExpression
from launch_ros.actions import Node


def generate_launch_description():
    lidar = LaunchConfiguration('lidar')
    return LaunchDescription([
        DeclareLaunchArgument('lidar', default_value='true', choices=['true', 'false', 'auto']),
        DeclareLaunchArgument('robot', default_value='mobile', choices=['mobile', 'arm']),
        DeclareLaunchArgument('use_sim', default_value='false'),
        DeclareLaunchArgument('camera_model', default_value='d435'),
        Node(package='demo_nodes_cpp', executable='talker', name='lidar_driver',
             condition=IfCondition(lidar)),  # expect: LV207
        Node(package='demo_nodes_cpp', executable='talker', name='base',
             condition=IfCondition(LaunchConfiguration('robot'))),  # expect: LV207
        Node(package='demo_nodes_cpp', executable='talker', name='lidar_auto',
             condition=IfCondition(EqualsSubstitution(lidar, 'auto'))),  # expect-not: LV207
        Node(package='demo_nodes_cpp', executable='talker', name='sim',
             condition=IfCondition(LaunchConfiguration('use_sim'))),  # expect-not: LV207
        GroupAction(condition=UnlessCondition(EqualsSubstitution(lidar, 'auto')), actions=[
            Node(package='demo_nodes_cpp', executable='talker', name='lidar_filter',
                 condition=IfCondition(lidar)),  # expect-not: LV207
        ]),
        SetLaunchConfiguration('enable_camera', PythonExpression(
            ["'", LaunchConfiguration('camera_model'), "' != ''"])),
        Node(package='demo_nodes_cpp', executable='talker', name='camera',
             condition=IfCondition(LaunchConfiguration('enable_camera'))),  # expect-not: LV207
    ])
