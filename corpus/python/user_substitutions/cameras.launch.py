# A launch file's own Substitution subclass (rtabmap's ConditionalText): inside an
# OpaqueFunction the configurations have values, so its perform() gives the text launch
# would use, and the nodes it names are checked like any other.
from launch import LaunchDescription, Substitution
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


class ConditionalText(Substitution):
    def __init__(self, text_if, text_else, condition):
        self.text_if = text_if
        self.text_else = text_else
        self.condition = condition

    def perform(self, context):
        return self.text_if if self.condition in (True, 'true', 'True') else self.text_else


def setup(context):
    stereo = LaunchConfiguration('stereo').perform(context)
    return [
        Node(package='demo_nodes_cpp', executable='talker',
             name=ConditionalText('stereo_camera', 'rgbd_camera', stereo)),
        # distinct names whatever 'stereo' is: no clash
        Node(package='demo_nodes_cpp', executable='listener',  # expect-not: LV101
             name=ConditionalText('stereo_sync', 'rgbd_sync', stereo)),
        # the buggy twin: with stereo:=false (the default) both are rgbd_camera
        Node(package='demo_nodes_cpp', executable='listener',  # expect: LV101
             name=ConditionalText('left_camera', 'rgbd_camera', stereo)),
    ]


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('stereo', default_value='false'),
        OpaqueFunction(function=setup),  # expect-not: LV003
    ])
