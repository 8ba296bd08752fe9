# Meant to be included: 'params_file' comes from its includer, bringup_distributed.py,
# whose name does not end in launch.py but which ros2 launch runs all the same.
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    # it declares its own arguments, so only its includer tells it is meant to be included
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        Node(package='demo_nodes_cpp', executable='talker', name='planner',
             parameters=[LaunchConfiguration('params_file'),  # expect-not: LV201
                         {'use_sim_time': LaunchConfiguration('use_sim_time')}]),
    ])
