from launch_ros.actions import Node


def drivers(robot):
    return [Node(package='demo_nodes_cpp', executable='talker', name='driver',  # expect-not: LV101
                 namespace=robot)]
