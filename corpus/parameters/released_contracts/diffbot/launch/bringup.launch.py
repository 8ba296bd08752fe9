"""A robot whose controllers are released packages: their parameters come from models."""
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    controllers = PathJoinSubstitution(
        [FindPackageShare('diffbot'), 'config', 'controllers.yaml'])
    return LaunchDescription([
        Node(package='controller_manager', executable='ros2_control_node',
             parameters=[{'robot_description': '<robot name="diffbot"/>'}, controllers]),
        Node(package='controller_manager', executable='spawner',  # expect: LV408
             arguments=['base_controller']),
        Node(package='controller_manager', executable='spawner',  # expect-not: LV408
             arguments=['rear_controller']),
    ])
