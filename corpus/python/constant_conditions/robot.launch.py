"""The Python twin of conditions/constant_conditions."""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node


def generate_launch_description():
    use_sim = LaunchConfiguration('use_sim')
    mode = LaunchConfiguration('mode')
    return LaunchDescription([
        DeclareLaunchArgument('use_sim', default_value='false'),
        DeclareLaunchArgument('mode', default_value='slow', choices=['slow', 'safe']),
        Node(package='demo_nodes_cpp', executable='talker', name='always',
             condition=IfCondition('true')),  # expect: LV206
        Node(package='demo_nodes_cpp', executable='talker', name='disabled',
             condition=IfCondition('false')),  # expect-not: LV205
        GroupAction(condition=IfCondition(use_sim), actions=[
            Node(package='demo_nodes_cpp', executable='talker', name='repeated',
                 condition=IfCondition(use_sim)),  # expect: LV206
        ]),
        Node(package='demo_nodes_cpp', executable='talker', name='either',
             condition=IfCondition(PythonExpression(  # expect: LV206
                 ["'", mode, "' in ['slow', 'safe']"]))),
        Node(package='demo_nodes_cpp', executable='talker', name='depends',
             condition=IfCondition(use_sim)),  # expect-not: LV206
        Node(package='demo_nodes_cpp', executable='talker', name='not_false',
             condition=IfCondition(PythonExpression(  # expect-not: LV206
                 ["'", use_sim, "' != 'false'"]))),
    ])
