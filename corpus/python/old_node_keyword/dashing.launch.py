from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    # node_executable/node_name were removed after Eloquent
    return LaunchDescription([
        Node(package='demo_nodes_cpp', node_executable='talker',  # expect: LV002
             node_name='talker', output='screen'),
    ])
