"""Components loaded into containers by name: launch_ros resolves the name from /."""
from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes, PushRosNamespace
from launch_ros.descriptions import ComposableNode


def rectify(name):
    return [ComposableNode(package='image_proc', plugin='image_proc::RectifyNode', name=name)]


def generate_launch_description():
    container = ComposableNodeContainer(
        name='container', namespace='', package='rclcpp_components',
        executable='component_container')
    return LaunchDescription([
        GroupAction([PushRosNamespace('camera'), container]),  # /camera/container
        # the pushed namespace does not apply to the load's target: it asks /container
        LoadComposableNodes(target_container='container',  # expect: LV506
                            composable_node_descriptions=rectify('rectify_a')),
        LoadComposableNodes(target_container='/camera/contianer',  # expect: LV506
                            composable_node_descriptions=rectify('rectify_b')),
        LoadComposableNodes(target_container='/camera/container',  # expect-not: LV506
                            composable_node_descriptions=rectify('rectify_c')),
        LoadComposableNodes(target_container='camera/container',  # expect-not: LV506
                            composable_node_descriptions=rectify('rectify_d')),
        # the action itself is the container, wherever it runs
        LoadComposableNodes(target_container=container,  # expect-not: LV506
                            composable_node_descriptions=rectify('rectify_e')),
        # a container no one here starts comes close to nothing: another launch's
        LoadComposableNodes(target_container='/perception/pipeline',  # expect-not: LV506
                            composable_node_descriptions=rectify('rectify_f')),
    ])
