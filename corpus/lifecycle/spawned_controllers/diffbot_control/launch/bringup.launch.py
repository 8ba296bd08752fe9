"""A diff-drive robot: one manager, its controllers spawned by name."""
from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    controllers = PathJoinSubstitution(
        [FindPackageShare('diffbot_control'), 'config', 'controllers.yaml'])
    gripper = PathJoinSubstitution(
        [FindPackageShare('diffbot_control'), 'config', 'gripper.yaml'])
    return LaunchDescription([
        Node(package='controller_manager', executable='ros2_control_node',
             parameters=[controllers]),
        # the manager defines joint_state_broadcaster, not joint_states_broadcaster
        Node(package='controller_manager', executable='spawner',  # expect: LV507
             arguments=['joint_states_broadcaster']),
        Node(package='controller_manager', executable='spawner',  # expect-not: LV507
             arguments=['diffbot_base_controller', '-c', '/controller_manager']),
        # its type comes with the spawner's own parameter file
        Node(package='controller_manager', executable='spawner',  # expect-not: LV507
             arguments=['gripper_controller', '--param-file', gripper]),
        # or on its command line
        Node(package='controller_manager', executable='spawner',  # expect-not: LV507
             arguments=['arm_controller', '--controller-type',
                        'joint_trajectory_controller/JointTrajectoryController']),
    ])
