"""A robot whose controllers are released packages: their parameters come from models."""
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    controllers = PathJoinSubstitution(
        [FindPackageShare('diffbot'), 'config', 'controllers.yaml'])
    arm = PathJoinSubstitution([FindPackageShare('diffbot'), 'config', 'arm_manager.yaml'])
    nav2 = PathJoinSubstitution([FindPackageShare('diffbot'), 'config', 'nav2_params.yaml'])
    return LaunchDescription([
        Node(package='controller_manager', executable='ros2_control_node',
             parameters=[{'robot_description': '<robot name="diffbot"/>'}, controllers]),
        Node(package='controller_manager', executable='spawner',  # expect: LV408
             arguments=['base_controller']),
        Node(package='controller_manager', executable='spawner',  # expect-not: LV408
             arguments=['rear_controller']),
        # a second manager: its NodeOptions take any name, and it reads lock_memory
        # without declaring it; update_rat is read by nothing
        Node(package='controller_manager', executable='ros2_control_node', namespace='arm',
             parameters=[{'robot_description': '<robot name="arm"/>'}, arm]),
        # nav2's servers, judged with the plugins navigation2 ships
        Node(package='nav2_amcl', executable='amcl', name='amcl', parameters=[nav2]),
        Node(package='nav2_controller', executable='controller_server', parameters=[nav2]),
        Node(package='nav2_behaviors', executable='behavior_server', parameters=[nav2]),
    ])
