# A vendor's helper module that is not installed here: on the robot it gives real values.
import json

from launch import LaunchDescription
from launch_ros.actions import Node
from vendor_helpers import robot_config

CONFIG = robot_config()


def generate_launch_description():
    namespace = '/'.join([CONFIG.prefix, 'robot'])  # expect-not: LV002
    extra = json.dumps(CONFIG.extra)  # expect-not: LV002
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', namespace=namespace,
             arguments=[extra]),
    ])
