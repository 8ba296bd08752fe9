from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import Command, FindExecutable, LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.parameter_descriptions import ParameterValue
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    urdf = PathJoinSubstitution([FindPackageShare('my_robot'), 'urdf', 'robot.urdf.xacro'])
    robot_description = ParameterValue(
        Command([FindExecutable(name='xacro'), ' ', urdf, ' prefix:=',
                 LaunchConfiguration('prefix')]),
        value_type=str)
    # the finding points where the path is built (the file is controllers.yaml)
    controllers = PathJoinSubstitution([FindPackageShare('my_robot'), 'config',  # expect: LV302
                                        'controller.yaml'])
    return LaunchDescription([
        DeclareLaunchArgument('prefix', default_value=''),
        Node(package='robot_state_publisher', executable='robot_state_publisher',
             parameters=[{'robot_description': robot_description}]),
        Node(package='controller_manager', executable='ros2_control_node',
             parameters=[{'robot_description': robot_description}, controllers]),
        Node(package='controller_manager', executable='spawner',
             arguments=['joint_state_broadcaster', '--controller-manager', '/controller_manager']),
    ])
