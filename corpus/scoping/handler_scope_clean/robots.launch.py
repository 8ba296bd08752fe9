"""Handlers' nodes in the scope of the event, where they stay apart.

A group's namespace does not reach what its handlers start (they run after the group has
popped it): a handler's node named like a node of the group's namespace is no duplicate,
and a handler that pushes its own namespace, or names one, keeps its nodes apart. A
configuration read there is the one the file's top level holds when the events come,
set after the groups here.
"""

from launch import LaunchDescription
from launch.actions import (DeclareLaunchArgument, GroupAction, RegisterEventHandler,
                            SetLaunchConfiguration)
from launch.event_handlers import OnProcessExit, OnProcessStart
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushRosNamespace


def generate_launch_description():
    spawner1 = Node(package='controller_manager', executable='spawner',
                    arguments=['joint_state_broadcaster'])
    spawner2 = Node(package='controller_manager', executable='spawner',
                    arguments=['joint_state_broadcaster'])
    return LaunchDescription([
        DeclareLaunchArgument('controller', default_value='arm_controller'),
        GroupAction([
            PushRosNamespace('robot1'),
            SetLaunchConfiguration('loader', 'robot1_loader'),
            RegisterEventHandler(OnProcessStart(target_action=spawner1, on_start=[
                # /driver: the group's namespace would make it /robot1/driver, as below
                Node(package='demo_nodes_cpp', executable='talker', name='driver'),  # expect-not: LV101
            ])),
            RegisterEventHandler(OnProcessExit(target_action=spawner1, on_exit=[
                GroupAction([
                    PushRosNamespace('robot1'),
                    Node(package='demo_nodes_cpp', executable='talker', name='arm_loader',  # expect-not: LV101
                         arguments=[LaunchConfiguration('controller')]),
                ]),
            ])),
            spawner1,
        ]),
        GroupAction([
            PushRosNamespace('robot2'),
            RegisterEventHandler(OnProcessExit(target_action=spawner2, on_exit=[
                Node(package='demo_nodes_cpp', executable='talker', name='arm_loader',  # expect-not: LV101
                     namespace='robot2', arguments=[LaunchConfiguration('controller')]),
                # 'loader' is robot1's group's: popped; the top level sets it below
                Node(package='demo_nodes_cpp', executable='talker',  # expect-not: LV101
                     name=LaunchConfiguration('loader')),  # expect-not: LV201
            ])),
            spawner2,
        ]),
        Node(package='demo_nodes_cpp', executable='listener', name='driver',  # expect-not: LV101
             namespace='robot1'),
        SetLaunchConfiguration('loader', 'top_loader'),
    ])
