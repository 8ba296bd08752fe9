"""In simulation the manager is a simulator plugin: what it defines is not seen here."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('controllers_file'),
        # no ros2_control_node here: gz_ros2_control's manager defines the controllers
        Node(package='controller_manager', executable='spawner',  # expect-not: LV507
             arguments=['anything_at_all']),
        Node(package='controller_manager', executable='ros2_control_node',
             namespace='arm', parameters=[LaunchConfiguration('controllers_file')]),
        # a parameter file chosen by an argument may define it
        Node(package='controller_manager', executable='spawner',  # expect-not: LV507
             namespace='arm', arguments=['arm_controller']),
    ])
