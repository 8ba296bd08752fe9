from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    container_name = LaunchConfiguration('container')
    return LaunchDescription([
        DeclareLaunchArgument('container', default_value='perception_container'),
        ComposableNodeContainer(
            name=container_name, namespace='', package='rclcpp_components',
            executable='component_container_mt', composable_node_descriptions=[]),
        LoadComposableNodes(
            target_container=container_name,
            composable_node_descriptions=[
                ComposableNode(package='depth_image_proc',
                               plugin='depth_image_proc::PointCloudXyzNode',
                               name='point_cloud', namespace='camera',
                               remappings=[('image_rect', 'depth/image_rect_raw')]),
                ComposableNode(package='image_proc', plugin='image_proc::RectifyNode',
                               name='rectify', namespace='camera'),
            ]),
        LoadComposableNodes(
            target_container=['/', container_name],
            composable_node_descriptions=[
                ComposableNode(package='image_proc',  # expect: LV101
                               plugin='image_proc::RectifyNode',
                               name='rectify', namespace='camera'),
                ComposableNode(package='image_proc', plugin='image_proc::RectifyNode',  # expect-not: LV101
                               name='rectify', namespace='camera_right'),
            ]),
    ])
