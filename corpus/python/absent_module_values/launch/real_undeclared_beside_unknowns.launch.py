# The twins: the helper is imported, but this description is never given to it.
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from vendor_helpers import robot_config

CONFIG = robot_config()


def generate_launch_description():
    spawner = Node(package='demo_nodes_cpp', executable='talker', name=CONFIG.name)
    return LaunchDescription([
        DeclareLaunchArgument('robot_name', default_value='r1'),  # an entry point
        Node(package='demo_nodes_cpp', executable='talker', name=LaunchConfiguration('robot_name'),
             namespace=LaunchConfiguration('robot_id')),  # expect: LV201
        RegisterEventHandler(OnProcessExit(  # expect: LV502
            target_action=spawner, on_exit=[Node(package='demo_nodes_cpp', executable='listener')])),
    ])
