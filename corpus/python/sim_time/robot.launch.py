"""The Python twin of parameters/sim_time."""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.conditions import UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, SetParameter


def generate_launch_description():
    use_sim_time = LaunchConfiguration('use_sim_time')
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='true'),
        GroupAction([
            SetParameter('use_sim_time', use_sim_time),
            Node(package='nav2_planner', executable='planner_server', name='planner_server'),
            Node(package='nav2_controller', executable='controller_server',
                 name='controller_server'),
        ]),
        Node(package='acme_driver', executable='driver', name='driver',  # expect-not: LV404
             condition=UnlessCondition(use_sim_time), parameters=[{'use_sim_time': False}]),
        Node(package='tf2_ros', executable='static_transform_publisher',  # expect-not: LV404
             name='laser_tf', arguments=['--frame-id', 'base_link', '--child-frame-id', 'laser']),
        Node(package='rviz2', executable='rviz2', name='rviz'),  # expect: LV404
    ])
