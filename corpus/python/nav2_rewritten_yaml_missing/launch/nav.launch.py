import os

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from launch_ros.descriptions import ParameterFile
from nav2_common.launch import RewrittenYaml

HERE = os.path.dirname(os.path.abspath(__file__))


def generate_launch_description():
    params = RewrittenYaml(
        source_file=LaunchConfiguration('params_file'),
        param_rewrites={'use_sim_time': LaunchConfiguration('use_sim_time')},
        convert_types=True)
    return LaunchDescription([
        # the file is params/nav2_params.yaml beside launch/, not inside it
        DeclareLaunchArgument('params_file',
                              default_value=os.path.join(HERE, 'nav2_params.yaml')),
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        Node(package='nav2_bt_navigator', executable='bt_navigator',
             name='bt_navigator',
             parameters=[ParameterFile(params, allow_substs=True)]),  # expect: LV302
    ])
