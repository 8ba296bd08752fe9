# nav2's pattern: one switch from a helper module, nodes alone or composed, never both.
from launch import LaunchDescription
from launch.actions import GroupAction
from launch.conditions import IfCondition
from launch.substitutions import PythonExpression
from launch_ros.actions import Node
from vendor_helpers import ConfigAsBool


def generate_launch_description():
    composed = ConfigAsBool('use_composition')
    return LaunchDescription([
        GroupAction(condition=IfCondition(PythonExpression(['not ', composed])), actions=[
            Node(package='demo_nodes_cpp', executable='talker', name='talker'),
        ]),
        GroupAction(condition=IfCondition(composed), actions=[
            Node(package='demo_nodes_cpp', executable='talker', name='talker'),  # expect-not: LV101
        ]),
    ])
