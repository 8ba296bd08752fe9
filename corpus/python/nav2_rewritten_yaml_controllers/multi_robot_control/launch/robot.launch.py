"""A controllers file moved under the robot's namespace by RewrittenYaml's root_key.

/robot1/controller_manager defines diff_drive_controller through the rewritten file: the
first spawner is right, the second misspells the controller.
"""

import os

from launch import LaunchDescription
from launch_ros.actions import Node
from nav2_common.launch import RewrittenYaml


def generate_launch_description():
    controllers = RewrittenYaml(
        source_file=os.path.join(os.path.dirname(__file__), '..', 'config', 'controllers.yaml'),
        root_key='robot1', param_rewrites={}, convert_types=True)
    return LaunchDescription([
        Node(package='controller_manager', executable='ros2_control_node', namespace='robot1',
             parameters=[controllers]),
        Node(package='controller_manager', executable='spawner', namespace='robot1',
             arguments=['diff_drive_controller', '-c', '/robot1/controller_manager']),
        Node(package='controller_manager', executable='spawner',  # expect: LV507
             namespace='robot1',
             arguments=['diff_drive_controler', '-c', '/robot1/controller_manager']),
    ])
