from launch import LaunchDescription
from launch_ros.actions import Node


def robot_launch(robot, sensors=()):
    nodes = [Node(package='demo_nodes_cpp', executable='talker', name='driver',
                  namespace=robot)]
    for sensor in sensors:
        nodes.append(Node(package='demo_nodes_cpp', executable='talker', name=sensor,  # expect: LV101
                          namespace=robot))
    return LaunchDescription(nodes)
