from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch_ros.actions import Node


def arms(context):
    robot = context.launch_configurations['robot']
    count = int(context.launch_configurations.get('arm_count', '1'))
    return [Node(package='demo_nodes_cpp', executable='talker', name=f'arm_{i}',  # expect: LV101 LV101
                 namespace=robot) for i in range(count)]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='solo'),
        DeclareLaunchArgument('arm_count', default_value='1'),
        OpaqueFunction(function=arms),
    ])
