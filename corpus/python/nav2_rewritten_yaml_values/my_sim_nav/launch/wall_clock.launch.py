"""The bug: the rewrite turns planner_server's use_sim_time off, whatever its block says.

planner_server's block says true; the rewrite gives every node of the file the launch's
false, while the robot's simulated drivers run on /clock.
"""

import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from nav2_common.launch import RewrittenYaml


def generate_launch_description():
    share = get_package_share_directory('my_sim_nav')
    configured_params = RewrittenYaml(
        source_file=os.path.join(share, 'params', 'nav2_params.yaml'),
        param_rewrites={'use_sim_time': LaunchConfiguration('use_sim_time')},
        convert_types=True)
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        Node(package='nav2_planner', executable='planner_server',  # expect: LV404
             name='planner_server', parameters=[configured_params]),
        Node(package='gazebo_ros', executable='gazebo_diff_drive', name='drive',
             parameters=[{'use_sim_time': True}]),
    ])
