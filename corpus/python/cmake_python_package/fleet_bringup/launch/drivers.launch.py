# The trap: fleet_names and fleet_topics are installed by fleet_common's CMakeLists.txt
# (no setup.py): they are imported, not unknown, and the names they give are distinct.
from fleet_names.naming import driver_names  # expect-not: LV003
from fleet_topics import SCAN_TOPIC  # expect-not: LV003
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='listener', name=name,  # expect-not: LV101
             remappings=[('chatter', SCAN_TOPIC)])
        for name in driver_names()
    ])
