from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    config = FindPackageShare('rover_bringup')
    namespace = LaunchConfiguration('namespace')
    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value=''),
        Node(package='controller_manager', executable='ros2_control_node',
             namespace=namespace,
             parameters=[PathJoinSubstitution([config, 'config', 'controllers.yaml'])]),
        Node(package='rover_driver', executable='driver_node', namespace=namespace,
             parameters=[PathJoinSubstitution([config, 'config', 'driver.yaml'])]),
    ])
