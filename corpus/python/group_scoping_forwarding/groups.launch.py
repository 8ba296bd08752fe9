from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushRosNamespace


def generate_launch_description():
    talker = dict(package='demo_nodes_cpp', executable='talker', name='talker')
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='r1'),
        PushRosNamespace('fleet'),
        GroupAction([
            # forwarding=False also drops the pushed namespace: this is /talker
            Node(**talker),
        ], forwarding=False, launch_configurations={'robot': LaunchConfiguration('robot')}),
        Node(namespace='/', **talker),  # expect: LV101
        Node(**talker),  # /fleet/talker
        # scoped=False: the pushed namespace outlives the group
        GroupAction([PushRosNamespace('r1')], scoped=False),
        Node(**talker),  # /fleet/r1/talker
        Node(namespace='/fleet/r1', **talker),  # expect: LV101
    ])
