"""navigation2's pattern: push the namespace only when one is given (twin of the XML case)."""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node, PushRosNamespace


def generate_launch_description():
    namespace = LaunchConfiguration('namespace')
    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value=''),
        GroupAction([
            PushRosNamespace(
                namespace=namespace,
                condition=IfCondition(PythonExpression(['"', namespace, '" != ""'])),
            ),
            Node(package='demo_nodes_cpp', executable='talker', name='talker'),
            Node(package='demo_nodes_cpp', executable='listener', name='listener'),
        ]),
        Node(package='demo_nodes_py', executable='talker', name='talker'),  # expect: LV101
        Node(package='demo_nodes_py', executable='listener', name='listener',  # expect-not: LV101
             namespace='/robot'),
    ])
