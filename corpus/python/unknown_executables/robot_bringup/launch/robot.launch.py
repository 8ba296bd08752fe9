"""The Python twin of files/unknown_executables."""

from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='cpp_pkg', executable='talker', name='talker'),  # expect-not: LV304
        Node(package='cpp_pkg', executable='listener', name='listener'),  # expect-not: LV304
        Node(package='cpp_pkg', executable='camera_node', name='camera'),  # expect-not: LV304
        Node(package='cpp_pkg', executable='monitor.py', name='monitor'),  # expect-not: LV304
        Node(package='cpp_pkg', executable='talkr', name='talker2'),  # expect: LV304
        Node(package='cpp_pkg', executable='benchmark', name='benchmark'),  # expect: LV304
        Node(package='py_pkg', executable='planner', name='planner'),  # expect-not: LV304
        Node(package='py_pkg', executable='helper.sh', name='helper'),  # expect-not: LV304
        Node(package='py_pkg', executable='execuotr', name='executor'),  # expect: LV304
        Node(package='macro_pkg', executable='anything', name='anything'),  # expect-not: LV304
        Node(package='demo_nodes_cpp', executable='talker', name='demo'),  # expect-not: LV304
    ])
