import os

from launch import LaunchDescription
from launch_ros.actions import ComposableNodeContainer, Node
from launch_ros.descriptions import ComposableNode

HERE = os.path.dirname(__file__)


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='talker',
             parameters=[os.path.join(HERE, 'merged.yaml')]),
        Node(package='demo_nodes_cpp', executable='listener', name='listener',
             parameters=[os.path.join(HERE, 'merged.yaml'),
                         os.path.join(HERE, 'flat_node.yaml')]),
        ComposableNodeContainer(
            name='camera_container', namespace='', package='rclcpp_components',
            executable='component_container',
            composable_node_descriptions=[
                ComposableNode(package='image_proc', plugin='image_proc::RectifyNode',
                               name='camera',
                               parameters=[os.path.join(HERE, 'merged_component.yaml'),
                                           os.path.join(HERE, 'flat.yaml')]),
            ]),
    ])
