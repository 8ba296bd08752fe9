# CTest launch files take their parameter file from the environment (nav2_system_tests):
# what the variable holds on the robot is unknown here, so no claim rests on its default.
import os

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    params = os.getenv('PARAMS_FILE', '')
    bt = os.environ.get('BT_NAVIGATOR_XML', '')
    return LaunchDescription([
        Node(package='nav2_bt_navigator', executable='bt_navigator',  # expect-not: LV302
             name='bt_navigator', parameters=[params, {'default_bt_xml_filename': bt}]),
        Node(package='nav2_amcl', executable='amcl', name='amcl',
             parameters=[os.path.join(os.path.dirname(__file__), 'config', 'amcl.yaml')]),  # expect: LV302
    ])
