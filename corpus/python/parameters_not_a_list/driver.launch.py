from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    # parameters must be a list of dicts/files: launch_ros raises TypeError
    # ('Node' expected 'parameters' to be one of [list]), it does not look for a file 'rate'
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='driver',  # expect: LV002  # expect-not: LV302
             parameters={'rate': 10, 'frame_id': 'base_link'}),
    ])
