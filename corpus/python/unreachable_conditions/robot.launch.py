"""The Python twin of conditions/unreachable_conditions."""

import os

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription
from launch.conditions import IfCondition, LaunchConfigurationEquals, UnlessCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node


def generate_launch_description():
    use_sim = LaunchConfiguration('use_sim')
    return LaunchDescription([
        DeclareLaunchArgument('use_sim', default_value='false'),
        DeclareLaunchArgument('robot', default_value='r1'),
        DeclareLaunchArgument('mode', default_value='slow', choices=['slow', 'safe']),
        GroupAction(condition=IfCondition(use_sim), actions=[
            Node(package='demo_nodes_cpp', executable='talker', name='sim_only'),
            # nested groups whose conditions contradict
            GroupAction(condition=UnlessCondition(use_sim), actions=[  # expect: LV205
                Node(package='demo_nodes_cpp', executable='talker', name='never'),
            ]),
            Node(package='demo_nodes_cpp', executable='listener', name='careful',
                 condition=LaunchConfigurationEquals('mode', 'safe')),  # expect-not: LV205
        ]),
        # a misspelt choice: 'fast' is not one of them
        Node(package='demo_nodes_cpp', executable='talker', name='fast',
             condition=LaunchConfigurationEquals('mode', 'fast')),  # expect: LV205
        Node(package='demo_nodes_cpp', executable='talker', name='a',
             condition=IfCondition(use_sim)),  # expect-not: LV205
        Node(package='demo_nodes_cpp', executable='talker', name='b',
             condition=UnlessCondition(use_sim)),  # expect-not: LV205
        Node(package='demo_nodes_cpp', executable='talker', name='second',
             condition=IfCondition(PythonExpression(  # expect-not: LV205
                 ["'", LaunchConfiguration('robot'), "' == 'r2'"]))),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(os.path.join(os.path.dirname(__file__),
                                                       'sensors.launch.py')),
            condition=IfCondition(use_sim),
            launch_arguments={'simulated': use_sim}.items()),
    ])
