from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushRosNamespace


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='talker', namespace='/fleet'),
        GroupAction([
            PushRosNamespace('robot'),
            # relative: /robot/fleet/talker
            Node(package='demo_nodes_cpp', executable='talker', name='talker',  # expect-not: LV101
                 namespace='fleet'),
            # absolute: ignores the pushed namespace, /fleet/talker again
            Node(package='demo_nodes_cpp', executable='talker', name='talker',  # expect: LV101
                 namespace='/fleet'),
            # a trailing slash is stripped: /robot/talker
            Node(package='demo_nodes_cpp', executable='talker', name='talker',
                 namespace='/robot/'),
            Node(package='demo_nodes_cpp', executable='listener', name='talker'),  # expect: LV101
        ]),
    ])
