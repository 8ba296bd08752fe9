# The arguments come from a loop over a helper's list: how many there are, and which, is
# unknown, so a read of one of them is no "never declared".
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from vendor_helpers import robot_config

CONFIG = robot_config()


def generate_launch_description():
    ld = LaunchDescription()
    for name, default in CONFIG.arguments:
        ld.add_action(DeclareLaunchArgument(name, default_value=default))
    ld.add_action(Node(package='demo_nodes_cpp', executable='talker',
                       namespace=LaunchConfiguration('robot_id')))  # expect-not: LV201
    return ld
