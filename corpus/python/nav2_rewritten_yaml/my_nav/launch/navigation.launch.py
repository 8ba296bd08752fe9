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
    params_file = LaunchConfiguration('params_file')
    configured_params = ParameterFile(
        RewrittenYaml(source_file=params_file, root_key=namespace,
                      param_rewrites={'use_sim_time': LaunchConfiguration('use_sim_time'),
                                      'autostart': LaunchConfiguration('autostart')},
                      convert_types=True),
        allow_substs=True)
    return LaunchDescription([
        DeclareLaunchArgument('namespace', default_value=''),
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        DeclareLaunchArgument('autostart', default_value='true'),
        DeclareLaunchArgument('params_file',
                              default_value=os.path.join(share, 'params', 'nav2_params.yaml')),
        DeclareLaunchArgument('map_file',  # expect: LV202
                              default_value=os.path.join(share, 'maps', 'map.yaml')),
        GroupAction([
            PushRosNamespace(namespace),
            Node(package='nav2_controller', executable='controller_server',
                 parameters=[configured_params], output='screen'),
            Node(package='nav2_planner', executable='planner_server', name='planner_server',
                 parameters=[configured_params]),
            Node(package='nav2_planner', executable='planner_server',  # expect: LV101
                 name='planner_server', parameters=[configured_params]),
        ]),
    ])
