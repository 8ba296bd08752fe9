from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def driver(context):
    robot = LaunchConfiguration('robot').perform(context)  # expect: LV201
    return [Node(package='demo_nodes_cpp', executable='talker', name='driver', namespace=robot)]


def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=driver)])
