# launch keeps a default that is not text as str(value): True is 'True', which
# PythonExpression reads as Python's True.
from launch import LaunchDescription
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration, PythonExpression
from launch_ros.actions import Node


def generate_launch_description():
    use_gpu = LaunchConfiguration('use_gpu', default=True)
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='detector',
             condition=IfCondition(PythonExpression([use_gpu, ' and True']))),  # expect-not: LV002
    ])
