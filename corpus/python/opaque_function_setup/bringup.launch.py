from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def launch_setup(context, *args, **kwargs):
    count = int(LaunchConfiguration('robot_count').perform(context))
    prefix = LaunchConfiguration('prefix').perform(context)
    nodes = []
    for i in range(count):
        nodes.append(Node(package='demo_nodes_cpp', executable='talker', name='talker',
                          namespace=f'{prefix}{i}'))
    if context.launch_configurations.get('with_monitor', 'false') == 'true':
        nodes.append(Node(package='demo_nodes_cpp', executable='listener', name='monitor'))
    # the arm driver is started once per robot too, without a namespace
    nodes += [Node(package='demo_nodes_cpp', executable='talker', name='arm_driver')  # expect: LV101
              for _ in range(count)]
    return nodes


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot_count', default_value='2'),
        DeclareLaunchArgument('prefix', default_value='robot'),
        DeclareLaunchArgument('with_monitor', default_value='true'),
        DeclareLaunchArgument('unused_flag', default_value='false'),  # expect: LV202
        OpaqueFunction(function=launch_setup),
    ])
