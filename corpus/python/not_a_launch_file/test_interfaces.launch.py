# A test script (robot_localization's test_se_node_interfaces.launch.py): its
# generate_launch_description takes the node type and is called by its own main(), so
# ros2 launch cannot start it. One info, nothing checked, not a TypeError as LV002.
import sys

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description(node_type):  # expect: LV003
    return LaunchDescription([
        Node(package='robot_localization', executable=node_type, name='se_node'),
    ])


def main(argv=sys.argv[1:]):
    return generate_launch_description(argv[0])
