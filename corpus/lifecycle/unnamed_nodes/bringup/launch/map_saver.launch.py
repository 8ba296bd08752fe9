"""nav2's map_saver_server.launch.py: the server is started without name= and names itself
'map_saver' in code that is not in this workspace (map_tools ships only its parameters).
What it is called is unknown, so no claim that 'map_saver' is never launched."""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='map_tools', executable='map_saver_server'),
        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager',  # expect-not: LV505
             name='lifecycle_manager_map',
             parameters=[{'autostart': True, 'node_names': ['map_saver']}]),
    ])
