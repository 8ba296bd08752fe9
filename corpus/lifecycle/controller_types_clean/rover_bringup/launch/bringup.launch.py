"""A rover's bring-up: every controller type exists, or cannot be known not to."""
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    controllers = PathJoinSubstitution(
        [FindPackageShare('rover_bringup'), 'config', 'controllers.yaml'])
    return LaunchDescription([
        # the default is misspelt, but the type is the caller's to give
        DeclareLaunchArgument('arm_type',
                              default_value='joint_trajectory_controller/JointTrajectoryControler'),
        Node(package='controller_manager', executable='ros2_control_node',
             parameters=[controllers,
                         {'mast_controller.type': LaunchConfiguration('arm_type')}]),
        Node(package='controller_manager', executable='spawner',  # expect-not: LV509
             arguments=['joint_state_broadcaster', 'base_controller', 'gripper_controller',
                        'gps_broadcaster', 'hub_motors', 'traction_controller', 'shaker',
                        'mast_controller']),
        Node(package='controller_manager', executable='spawner',  # expect-not: LV509
             arguments=['arm_controller', '--controller-type',
                        LaunchConfiguration('arm_type')]),
        Node(package='controller_manager', executable='spawner',  # expect-not: LV509
             arguments=['wrist_controller', '--controller-type',
                        'forward_command_controller/ForwardCommandController']),
    ])
