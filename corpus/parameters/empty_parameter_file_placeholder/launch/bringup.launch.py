from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import ComposableNodeContainer, Node
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    # champ's template bringup: '' means "no map file unless the caller gives one"
    return LaunchDescription([
        DeclareLaunchArgument('joints_map_path', default_value=''),
        # a process node: launch_ros skips an empty path and starts the node without it
        Node(package='demo_nodes_cpp', executable='talker', name='controller',
             parameters=[LaunchConfiguration('joints_map_path'), {'use_sim_time': False}]),  # expect-not: LV302
        # a composable node: the loader opens the path, and '' fails
        ComposableNodeContainer(
            name='container', namespace='', package='rclcpp_components',
            executable='component_container',
            composable_node_descriptions=[
                ComposableNode(package='composition', plugin='composition::Talker',
                               name='estimator',
                               parameters=[LaunchConfiguration('joints_map_path')]),  # expect: LV302
            ]),
    ])
