from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    use_sim = LaunchConfiguration('use_sim')
    return LaunchDescription([
        DeclareLaunchArgument('use_sim', default_value='false'),
        # Bugs: a shortened workspace package (did you mean 'acme_simulation'?) under a
        # condition false by default, and a private package that is nowhere.
        Node(package='acme_sim', executable='world', condition=IfCondition(use_sim)),  # expect-warning: LV303
        Node(package='acme_private_tools', executable='tool', name='tool'),  # expect-info: LV303
        # Twins: a workspace package spelled right, released packages not installed here.
        Node(package='acme_simulation', executable='world', name='world',  # expect-not: LV303
             condition=IfCondition(use_sim)),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(  # expect-not: LV303
            PathJoinSubstitution([FindPackageShare('ros_gz_sim'), 'launch', 'gz_sim.launch.py']))),
        Node(package='rviz2', executable='rviz2', name='rviz'),  # expect-not: LV303
        # A numbered sibling of a workspace package (acme_arm_10): another arm, not a typo.
        Node(package='acme_arm_1', executable='driver', name='arm'),  # expect-info: LV303
        # Another vendor's package beside a released one: neobotix's neo_gz_worlds is one
        # letter from LeoRover's leo_gz_worlds, in its vendor prefix: not a typo.
        Node(package='neo_gz_worlds', executable='world', name='neo'),  # expect-info: LV303
        # One letter from a released package elsewhere in the name: a typo.
        Node(package='leo_gz_world', executable='world', name='leo'),  # expect-error: LV303
    ])
