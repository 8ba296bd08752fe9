from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    launch_dir = PathJoinSubstitution([FindPackageShare('fleet_bringup'), 'launch'])
    robot = PythonLaunchDescriptionSource([launch_dir, '/robot.launch.py'])
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='r1'),
        IncludeLaunchDescription(robot),  # expect: LV208
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource([launch_dir, '/robot.launch.py']),
            launch_arguments={'robot_name': LaunchConfiguration('robot')}.items()),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource([launch_dir, '/optional.launch.py'])),
    ])
