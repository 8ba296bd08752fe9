# Nodes launched without name= run under the names their code gives them.
from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import ComposableNodeContainer, Node, PushRosNamespace
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    return LaunchDescription([
        # chatter_cpp's main calls its node "talker": both are /talker
        Node(package='chatter_cpp', executable='talker'),
        Node(package='chatter_cpp', executable='talker'),  # expect: LV101
        # two packages, one name: rclpy's Talker is "talker" too, in the same namespace
        Node(package='chatter_cpp', executable='talker', namespace='robot'),
        Node(package='chatter_py', executable='talker', namespace='robot'),  # expect: LV101
        # a released package: its shipped model knows the name its code gives
        Node(package='robot_state_publisher', executable='robot_state_publisher'),
        GroupAction([
            PushRosNamespace('/'),
            Node(package='robot_state_publisher', executable='robot_state_publisher'),  # expect: LV101
        ]),
        # a component without name= is called as its constructor calls it
        ComposableNodeContainer(
            name='container', namespace='', package='rclcpp_components',
            executable='component_container',
            composable_node_descriptions=[
                ComposableNode(package='chatter_cpp', plugin='chatter_cpp::Relay'),
                ComposableNode(package='chatter_cpp', plugin='chatter_cpp::Relay'),  # expect: LV101
            ]),
    ])
