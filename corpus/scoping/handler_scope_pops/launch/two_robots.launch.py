"""What an event handler starts runs in the scope launch has when the event comes.

launch visits the whole file first and handles events afterwards: by then each group has
popped its namespace, SetParameter, SetRemap and configurations (handlers capture none
of them, in humble, jazzy and rolling alike). The loader each spawner's exit starts runs
as /arm_loader, for both robots.
"""

import os

from launch import LaunchDescription
from launch.actions import GroupAction, IncludeLaunchDescription, RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node, PushRosNamespace


def generate_launch_description():
    spawner1 = Node(package='controller_manager', executable='spawner',
                    arguments=['joint_state_broadcaster'])
    spawner2 = Node(package='controller_manager', executable='spawner',
                    arguments=['joint_state_broadcaster'])
    return LaunchDescription([
        GroupAction([
            PushRosNamespace('robot1'),
            RegisterEventHandler(OnProcessExit(target_action=spawner1, on_exit=[
                Node(package='demo_nodes_cpp', executable='talker', name='arm_loader'),
            ])),
            spawner1,
        ]),
        GroupAction([
            PushRosNamespace('robot2'),
            RegisterEventHandler(OnProcessExit(target_action=spawner2, on_exit=[
                # expect: LV101
                Node(package='demo_nodes_cpp', executable='talker', name='arm_loader'),
            ])),
            spawner2,
        ]),
        # the same in an included file: the include's group is popped as well
        GroupAction([
            PushRosNamespace('robot3'),
            IncludeLaunchDescription(PythonLaunchDescriptionSource(
                os.path.join(os.path.dirname(__file__), 'arm.launch.py'))),
        ]),
    ])
