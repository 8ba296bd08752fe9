from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration, PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare
from launch_xml.launch_description_sources import XMLLaunchDescriptionSource


def generate_launch_description():
    arm_id = LaunchConfiguration('arm_id')
    return LaunchDescription([
        DeclareLaunchArgument('arm_id'),
        DeclareLaunchArgument('use_gripper', default_value='false'),
        Node(package='demo_nodes_cpp', executable='talker', name='arm_controller',
             namespace=arm_id),
        IncludeLaunchDescription(
            XMLLaunchDescriptionSource(PathJoinSubstitution(
                [FindPackageShare('arm_bringup'), 'launch', 'gripper.launch.xml'])),
            condition=IfCondition(LaunchConfiguration('use_gripper')),
            launch_arguments=[('ns', arm_id)]),
    ])
