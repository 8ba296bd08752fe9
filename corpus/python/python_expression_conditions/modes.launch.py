from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, ExecuteProcess
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node


def generate_launch_description():
    mode = LaunchConfiguration('mode')
    rate = LaunchConfiguration('rate')
    return LaunchDescription([
        DeclareLaunchArgument('mode', default_value='mapping', choices=['mapping', 'localization']),
        DeclareLaunchArgument('rate', default_value='10'),
        DeclareLaunchArgument('bag_name', default_value='run'),  # expect-not: LV202 (read as bag_nme)
        Node(package='slam_toolbox', executable='sync_slam_toolbox_node', name='slam',
             condition=IfCondition(PythonExpression(["'", mode, "' == 'mapping'"]))),
        Node(package='slam_toolbox', executable='localization_slam_toolbox_node',  # expect-not: LV101
             name='slam',
             condition=IfCondition(PythonExpression(["'", mode, "' == 'localization'"]))),
        Node(package='demo_nodes_cpp', executable='talker', name='fast_talker',
             condition=IfCondition(PythonExpression([rate, ' > 5']))),
        Node(package='demo_nodes_cpp', executable='talker', name='talker',
             parameters=[{'period': PythonExpression(['1.0 / ', rate])}]),
        ExecuteProcess(
            cmd=['ros2', 'bag', 'record', '-o', LaunchConfiguration('bag_nme'), '/scan'],  # expect: LV201
            condition=IfCondition(PythonExpression(["'", mode, "' == 'mapping'"]))),
        # the quotes are missing: eval("mapping == 'mapping'") raises NameError
        Node(package='demo_nodes_cpp', executable='listener', name='map_saver',
             condition=IfCondition(PythonExpression([mode, " == 'mapping'"]))),  # expect: LV002
    ])
