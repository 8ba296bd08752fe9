from launch_ros.actions import Node


def make_nodes(robot):
    return [Node(package='demo_nodes_cpp', executable='talker', name='driver',
                 namespace=robot)]
