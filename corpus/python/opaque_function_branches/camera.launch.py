# An OpaqueFunction runs once, with the arguments' defaults: what it reads under a branch
# that another value takes (rs_compat:=true here) is unseen, but its code names it, so
# the argument is not called unused. An argument its code never names still is.
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def flag(context, name):
    return LaunchConfiguration(name).perform(context) == 'true'


def setup(context):
    parameters = {}
    if flag(context, 'rs_compat'):
        parameters['depth_profile'] = LaunchConfiguration('depth_profile').perform(context)
        parameters['publish_color'] = flag(context, 'enable_color')
    return [Node(package='demo_nodes_cpp', executable='talker', name='camera',
                 parameters=[parameters])]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('rs_compat', default_value='false'),
        DeclareLaunchArgument('depth_profile', default_value='1280,720,30'),  # expect-not: LV202
        DeclareLaunchArgument('enable_color', default_value='true'),  # expect-not: LV202
        DeclareLaunchArgument('enable_infra', default_value='false'),  # expect: LV202
        OpaqueFunction(function=setup),
    ])
