# Descriptions built by a helper launchverify cannot see: what they hold is unknown, so
# nothing may be claimed of what they lack.
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from vendor_helpers import builder, robot_config

CONFIG = robot_config()


def generate_launch_description():
    ld = builder.base_description()  # expect-not: LV002
    for declaration in builder.declarations():
        ld.add_action(declaration)
    ld.add_action(DeclareLaunchArgument(CONFIG.argument_name, default_value='x'))
    ld.add_action(GroupAction(builder.actions()))
    ld.add_action(Node(package='demo_nodes_cpp', executable='talker',
                       namespace=LaunchConfiguration('robot_id')))  # expect-not: LV201
    return ld
