from launch import LaunchDescription
from launch_ros.actions import Node

ROBOTS = {
    'alpha': {'x': 0.0, 'y': 0.0},
    'beta': {'x': 1.0, 'y': 0.0},
}


def generate_launch_description():
    ld = LaunchDescription()
    for name in ('alpha', 'beta', 'gamma'):
        pose = ROBOTS[name]  # expect: LV002
        ld.add_action(Node(package='demo_nodes_cpp', executable='talker', name='driver',
                           namespace=name, parameters=[pose]))
    return ld
