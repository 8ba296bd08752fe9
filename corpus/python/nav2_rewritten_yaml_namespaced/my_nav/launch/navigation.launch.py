"""RewrittenYaml with a root key: the node gets the file's blocks under /robot1."""

import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushRosNamespace
from launch_ros.descriptions import ParameterFile
from nav2_common.launch import RewrittenYaml


def generate_launch_description():
    share = get_package_share_directory('my_nav')
    namespace = LaunchConfiguration('namespace')
    configured_params = ParameterFile(
        RewrittenYaml(source_file=os.path.join(share, 'params', 'nav2_params.yaml'),
                      root_key=namespace, param_rewrites={}, convert_types=True),
        allow_substs=True)
    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value='robot1'),
        GroupAction([
            PushRosNamespace(namespace),
            # /robot1/planner_server gets the rewritten file, whose planner_server block
            # now sits under robot1: nothing is misplaced, and nothing is reported
            Node(package='nav2_planner', executable='planner_server', name='planner_server',
                 parameters=[configured_params]),
        ]),
    ])
