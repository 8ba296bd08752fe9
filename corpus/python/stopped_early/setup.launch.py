# rtabmap.launch.py's launch_setup raised (a model lacked a private method) before reading
# most of its 70 arguments, and every one of them was reported as unused. What a body that
# stopped early would have read is unknown: absence rules stay silent on such a launch.
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def launch_setup(context):
    rate = float(LaunchConfiguration('rate').perform(context))
    if rate > 100:
        raise ValueError('rate too high')  # expect: LV002
    return [Node(package='rtabmap_slam', executable='rtabmap', name='rtabmap',
                 parameters=[{'rate': rate,
                              'frame': LaunchConfiguration('frame_id').perform(context)}])]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('rate', default_value='200'),
        DeclareLaunchArgument('frame_id', default_value='base_link'),  # expect-not: LV202
        OpaqueFunction(function=launch_setup),
    ])
