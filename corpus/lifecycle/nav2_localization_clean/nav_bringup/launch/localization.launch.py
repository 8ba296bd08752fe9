"""nav2-style localization: the manager configures, then activates, map_server and amcl."""
import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushROSNamespace


def generate_launch_description():
    share = get_package_share_directory('nav_bringup')
    params = os.path.join(share, 'params', 'localization.yaml')
    namespace = LaunchConfiguration('namespace')
    lifecycle_nodes = ['map_server', 'amcl']
    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value=''),
        GroupAction([
            PushROSNamespace(namespace),
            Node(package='nav2_map_server', executable='map_server', name='map_server',
                 parameters=[params]),
            Node(package='nav2_amcl', executable='amcl', name='amcl', parameters=[params]),
            # expect-not: LV505 LV503 LV504
            Node(package='nav2_lifecycle_manager', executable='lifecycle_manager',
                 name='lifecycle_manager_localization',
                 parameters=[{'autostart': True, 'node_names': lifecycle_nodes}]),
        ]),
    ])
