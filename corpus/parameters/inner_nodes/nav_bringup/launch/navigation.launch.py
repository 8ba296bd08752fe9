import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    config = os.path.join(os.path.dirname(__file__), '..', 'config')
    params = os.path.join(config, 'navigation.yaml')
    return LaunchDescription([
        Node(package='nav2_controller', executable='controller_server',
             name='controller_server', parameters=[params]),
        Node(package='nav2_planner', executable='planner_server', name='planner_server',
             parameters=[params]),
        Node(package='nav2_bt_navigator', executable='bt_navigator', name='bt_navigator',
             parameters=[params]),
        Node(package='controller_manager', executable='ros2_control_node',
             parameters=[os.path.join(config, 'controllers.yaml')]),
    ])
