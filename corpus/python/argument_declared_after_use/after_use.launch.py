from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    ld = LaunchDescription()
    # actions run in the order they are added: the node reads 'rate' before it is declared
    # (ros2 launch: launch configuration 'rate' does not exist)
    ld.add_action(Node(package='demo_nodes_cpp', executable='talker', name='talker',
                       parameters=[{'rate': LaunchConfiguration('rate')}]))  # expect: LV201
    ld.add_action(DeclareLaunchArgument('rate', default_value='10'))
    ld.add_action(Node(package='demo_nodes_cpp', executable='listener', name='listener',
                       parameters=[{'rate': LaunchConfiguration('rate')}]))
    return ld
