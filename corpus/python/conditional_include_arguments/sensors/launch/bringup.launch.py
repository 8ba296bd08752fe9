# Launch evaluates an include's arguments, and a node's fields, only once the action's
# condition held (IncludeLaunchDescription.execute, Node._perform_substitutions): what
# fails there fails only with arguments that make the condition true.
import os

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.conditions import IfCondition, LaunchConfigurationEquals
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node


def generate_launch_description():
    camera = os.path.join(os.path.dirname(__file__), 'camera.launch.py')
    sensor = LaunchConfiguration('sensor')
    return LaunchDescription([
        DeclareLaunchArgument('use_camera', default_value='false'),
        DeclareLaunchArgument('sensor', default_value='none'),
        DeclareLaunchArgument('mode', default_value='fast', choices=['fast', 'safe']),
        # trap: the value fails only where the condition is false (launch never evaluates it)
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(camera),
            launch_arguments={'model': PythonExpression(  # expect-not: LV002
                ["'oak' if '", sensor, "' == 'oakd' else int('none')"])}.items(),
            condition=LaunchConfigurationEquals('sensor', 'oakd')),
        # trap: a condition no value of `mode` makes true: the number is never normalized
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(camera),
            launch_arguments={'rate': 15}.items(),  # expect-not: LV002
            condition=LaunchConfigurationEquals('mode', 'slow')),  # expect: LV205
        # bug: with use_camera:=true launch raises TypeError ('int' object is not iterable)
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(camera),
            launch_arguments={'rate': 15}.items(),  # expect: LV002
            condition=IfCondition(LaunchConfiguration('use_camera'))),
        # bug: with sensor:=rs the expression is '1 / false', a NameError
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(camera),
            launch_arguments={'rate': PythonExpression(  # expect: LV002
                ['1 / ', LaunchConfiguration('use_camera')])}.items(),
            condition=LaunchConfigurationEquals('sensor', 'rs')),
        # trap and bug for a node's name, performed when the node executes
        Node(package='demo_nodes_cpp', executable='listener',
             name=PythonExpression(  # expect-not: LV002
                 ["'oak' if '", sensor, "' == 'oakd' else int('none')"]),
             condition=LaunchConfigurationEquals('sensor', 'oakd')),
        Node(package='demo_nodes_cpp', executable='listener', name=7,  # expect: LV002
             condition=IfCondition(LaunchConfiguration('use_camera'))),
        # trap: read only where the argument is declared, under the same condition
        DeclareLaunchArgument('oakd_model', default_value='OAK-D-LITE',
                              condition=LaunchConfigurationEquals('sensor', 'oakd')),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(camera),
            launch_arguments={'model': LaunchConfiguration('oakd_model')}.items(),  # expect-not: LV201
            condition=LaunchConfigurationEquals('sensor', 'oakd')),
        # bug: with sensor:=lidar launch reads a configuration nothing sets
        Node(package='demo_nodes_cpp', executable='listener', name='lidar',
             namespace=LaunchConfiguration('lidar_namespace'),  # expect: LV201
             condition=LaunchConfigurationEquals('sensor', 'lidar')),
    ])
