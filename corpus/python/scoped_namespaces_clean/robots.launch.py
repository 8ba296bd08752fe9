from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushROSNamespace, PushRosNamespace


def talker():
    return Node(package='demo_nodes_cpp', executable='talker', name='talker')


def generate_launch_description():
    # The same node name in different scoped namespaces is fine.
    return LaunchDescription([
        GroupAction([
            PushRosNamespace('robot1'),
            talker(),
        ]),
        GroupAction([
            PushROSNamespace(namespace='robot2'),
            talker(),
            GroupAction([PushRosNamespace('arm'), talker()]),
        ]),
        talker(),
        Node(package='demo_nodes_cpp', executable='talker', name='talker',
             namespace='robot3'),
    ])
