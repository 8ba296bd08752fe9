# The trap: the workspace's helper reads a file only the robot has, parses it, asks the
# user, and names an absent module's exceptions. Its code meets those unknowns as a
# launch file's does: nothing it does with them is a fact.
from fleet_names.simulator import ask_to_install, simulator_version
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    if simulator_version() is None:  # expect-not: LV002
        ask_to_install()
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='sim_clock'),
        Node(package='demo_nodes_cpp', executable='listener', name='sim_clock'),  # expect: LV101
    ])
