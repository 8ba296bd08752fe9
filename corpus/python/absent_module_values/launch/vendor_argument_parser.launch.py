# Robotnik's pattern: a helper module (not installed here) declares the arguments into the
# description it was given; the launch file then reads them.
from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from vendor_helpers import ArgumentParser, ExtendedArgument


def generate_launch_description():
    ld = LaunchDescription()
    parser = ArgumentParser(ld)
    parser.add_arg(ExtendedArgument(name='robot_id', default_value='robot', use_env=True))
    robot_id = LaunchConfiguration('robot_id')  # expect-not: LV201
    ld.add_action(Node(package='demo_nodes_cpp', executable='talker', namespace=robot_id))
    return ld
