# A rate from the vendor's configuration, converted: its type on the robot is unknown here.
import os

from launch import LaunchDescription
from launch_ros.actions import Node
from vendor_helpers import robot_config

CONFIG = robot_config()
RATES = os.path.join(os.path.dirname(__file__), '..', 'config', 'rates.yaml')


def generate_launch_description():
    assert isinstance(3, int) and int('7') == 7 and float('2.5') == 2.5  # builtins still work
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='from_vendor',
             parameters=[RATES, {'rate': float(CONFIG.rate)}]),  # expect-not: LV403
        Node(package='demo_nodes_cpp', executable='talker', name='written',
             parameters=[RATES, {'rate': 2.5}]),  # expect: LV403
    ])
