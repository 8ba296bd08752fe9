from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


# This file reads configurations it never declares ('robot', 'camera_ns'), and no launch
# file of the workspace includes it: it is launched directly, and `ros2 launch` fails on
# those reads (LV201, the rule for them, rather than the SubstitutionFailure and KeyError
# as LV002). Were it included, its includer could set them (see included_setup/).


def driver(context):
    # declared as 'robot_name', read as 'robot': SubstitutionFailure when launched directly
    robot = LaunchConfiguration('robot').perform(context)  # expect: LV201  # expect-not: LV002
    return [Node(package='demo_nodes_cpp', executable='talker', name='driver', namespace=robot)]


def camera(context):
    ns = context.launch_configurations['camera_ns']  # expect: LV201  # expect-not: LV002
    return [Node(package='usb_cam', executable='usb_cam_node_exe', name='camera', namespace=ns)]


def monitor(context):
    ns = context.launch_configurations.get('monitor_ns', 'monitor')  # expect-not: LV002
    return [Node(package='demo_nodes_cpp', executable='listener', name='monitor', namespace=ns)]


def generate_launch_description():
    return LaunchDescription([
        # 'driver' stops at its failed read: what it would have read after is unseen, so
        # no claim that robot_name is unused
        DeclareLaunchArgument('robot_name', default_value='r1'),  # expect-not: LV202
        OpaqueFunction(function=driver),
        OpaqueFunction(function=camera),
        OpaqueFunction(function=monitor),
    ])
