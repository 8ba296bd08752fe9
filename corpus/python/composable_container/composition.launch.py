from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes, Node
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    container = ComposableNodeContainer(
        name='image_container', namespace='camera',
        package='rclcpp_components', executable='component_container',
        composable_node_descriptions=[
            ComposableNode(package='image_proc', plugin='image_proc::RectifyNode',
                           name='rectify', namespace='camera'),
            ComposableNode(package='image_proc', plugin='image_proc::DebayerNode',
                           name='debayer', namespace='camera'),
        ],
    )
    return LaunchDescription([
        DeclareLaunchArgument('with_resize', default_value='true'),
        container,
        LoadComposableNodes(
            target_container=container,
            condition=IfCondition(LaunchConfiguration('with_resize')),
            composable_node_descriptions=[
                ComposableNode(package='image_proc', plugin='image_proc::ResizeNode',
                               name='resize', namespace='camera'),
                ComposableNode(  # expect: LV101
                    package='image_proc', plugin='image_proc::RectifyNode',
                    name='rectify', namespace='camera'),
            ],
        ),
        # a stand-alone node with the container's name
        Node(package='demo_nodes_cpp', executable='talker', name='image_container',  # expect: LV101
             namespace='camera'),
        Node(package='demo_nodes_cpp', executable='talker', name='rectify'),  # expect-not: LV101
    ])
