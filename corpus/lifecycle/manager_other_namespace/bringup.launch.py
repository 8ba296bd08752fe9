"""The manager runs in /robot1 but its nodes at the root: relative names miss them."""
from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, PushROSNamespace


def generate_launch_description():
    return LaunchDescription([
        Node(package='nav2_map_server', executable='map_server', name='map_server'),
        Node(package='nav2_amcl', executable='amcl', name='amcl'),
        GroupAction([
            PushROSNamespace('robot1'),
            Node(package='nav2_lifecycle_manager', executable='lifecycle_manager',  # expect: LV505 LV505
                 name='lifecycle_manager_localization',
                 parameters=[{'autostart': True, 'node_names': ['map_server', 'amcl']}]),
            # absolute names reach the nodes wherever the manager runs
            Node(package='nav2_lifecycle_manager', executable='lifecycle_manager',  # expect-not: LV505
                 name='lifecycle_manager_absolute',
                 parameters=[{'autostart': False, 'node_names': ['/map_server', '/amcl']}]),
        ]),
    ])
