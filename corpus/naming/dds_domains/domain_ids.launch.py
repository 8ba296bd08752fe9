"""Domain ids the middleware refuses, or whose ports Linux may take."""
from launch import LaunchDescription
from launch.actions import GroupAction, SetEnvironmentVariable
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        GroupAction([
            SetEnvironmentVariable('ROS_DOMAIN_ID', '250'),  # expect: LV104
            Node(package='demo_nodes_cpp', executable='talker', name='a'),
        ]),
        GroupAction([
            SetEnvironmentVariable('ROS_DOMAIN_ID', 'robot1'),  # expect: LV104
            Node(package='demo_nodes_cpp', executable='talker', name='b'),
        ]),
        GroupAction([
            SetEnvironmentVariable('ROS_DOMAIN_ID', '150'),  # expect-warning: LV104
            Node(package='demo_nodes_cpp', executable='talker', name='c'),
        ]),
        GroupAction([
            SetEnvironmentVariable('ROS_DOMAIN_ID', '42'),  # expect-not: LV104
            Node(package='demo_nodes_cpp', executable='talker', name='d',
                 additional_env={'ROS_DOMAIN_ID': '230'}),  # expect-not: LV104
        ]),
    ])
