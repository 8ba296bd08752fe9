"""An arm's bring-up: each spawner's controller has a type that no package exports."""
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    controllers = PathJoinSubstitution(
        [FindPackageShare('arm_bringup'), 'config', 'controllers.yaml'])
    return LaunchDescription([
        Node(package='controller_manager', executable='ros2_control_node',
             parameters=[controllers]),
        Node(package='controller_manager', executable='spawner',
             arguments=['joint_state_broadcaster', 'base_controller', 'gripper_controller']),
        # the type on the spawner's command line, one letter short
        Node(package='controller_manager', executable='spawner',
             arguments=['arm_controller', '--controller-type',
                        'joint_trajectory_controller/JointTrajectoryControler']),  # expect: LV509
    ])
