# PAL's pattern: a configuration file named from a helper's suffix (the helper is not here).
import os

from launch import LaunchDescription
from launch_ros.actions import Node
from vendor_helpers import hardware_suffix


def generate_launch_description():
    config = os.path.join(os.path.dirname(__file__), '..', 'config',
                          'teleop' + hardware_suffix(arm='no-arm') + '.yaml')  # expect-not: LV002
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', parameters=[config]),
    ])
