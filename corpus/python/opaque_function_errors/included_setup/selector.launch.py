from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


# Checked on its own, the function stops at 'selector_param_path', which only the includer
# (bringup.launch.py) sets: the remappings it reads after that point are unseen, so the
# arguments they use are not called unused.


def setup(context):
    with open(LaunchConfiguration('selector_param_path').perform(context)) as f:
        f.read()
    return [Node(package='demo_nodes_cpp', executable='talker', name='selector',
                 remappings=[('~/out', LaunchConfiguration('output_topic'))])]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('output_topic', default_value='/selected'),  # expect-not: LV202
        OpaqueFunction(function=setup),
    ])
