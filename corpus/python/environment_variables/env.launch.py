import os

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, SetEnvironmentVariable
from launch.substitutions import EnvironmentVariable, LaunchConfiguration
from launch_ros.actions import Node

ROBOT_MODEL = os.environ.get('TURTLEBOT3_MODEL', 'burger')


def generate_launch_description():
    domain = os.environ.get('ROS_DOMAIN_ID', '0')
    return LaunchDescription([
        DeclareLaunchArgument('robot_name', default_value=EnvironmentVariable('ROBOT_NAME',
                                                                              default_value='bot')),
        SetEnvironmentVariable('RCUTILS_COLORIZED_OUTPUT', '1'),
        Node(package='demo_nodes_cpp', executable='talker', name='burger_driver',
             namespace=LaunchConfiguration('robot_name'),
             parameters=[{'domain': domain}]),
        # the same variable in the same place: equal whatever the robot sets
        Node(package='demo_nodes_cpp', executable='talker', name='burger_driver',  # expect: LV101
             namespace=EnvironmentVariable('ROBOT_NAME', default_value='bot')),
        # equal only while TURTLEBOT3_MODEL is unset, which the robot decides: no error
        Node(package='demo_nodes_cpp', executable='listener',  # expect-not: LV101
             name=f'{ROBOT_MODEL}_driver', namespace=LaunchConfiguration('robot_name')),
    ])
