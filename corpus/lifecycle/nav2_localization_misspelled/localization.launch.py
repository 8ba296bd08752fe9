"""One managed node misspelled: the manager waits for '/amlc' forever."""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='nav2_map_server', executable='map_server', name='map_server'),
        Node(package='nav2_amcl', executable='amcl', name='amcl'),
        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager',  # expect: LV505
             name='lifecycle_manager_localization',
             parameters=[{'autostart': True, 'node_names': ['map_server', 'amlc']}]),
    ])
