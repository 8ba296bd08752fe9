"""RewrittenYaml gives use_sim_time the launch's value: the file's false is not what amcl gets.

The trap: amcl's block says false, the rewrite makes it true, like the simulator's clock
bridge: nothing to report.
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
        DeclareLaunchArgument('use_sim_time', default_value='true'),
        Node(package='nav2_amcl', executable='amcl', name='amcl',
             parameters=[configured_params]),
        Node(package='rviz2', executable='rviz2', name='rviz2',
             parameters=[{'use_sim_time': True}]),
    ])
