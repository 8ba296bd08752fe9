from launch.actions import GroupAction
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushRosNamespace

DEFAULT_ROBOTS = ['r1', 'r2']


def robot_group(name, with_arm=False):
    actions = [
        PushRosNamespace(name),
        Node(package='demo_nodes_cpp', executable='talker', name='base_driver'),  # expect: LV101
    ]
    if with_arm:
        actions.append(Node(package='demo_nodes_cpp', executable='talker', name='arm_driver',  # expect: LV101
                            condition=IfCondition(LaunchConfiguration('use_arm'))))
    return GroupAction(actions)


def supervisor(robots):
    return Node(package='demo_nodes_cpp', executable='listener', name='supervisor',
                parameters=[{'robots': list(robots)}])
