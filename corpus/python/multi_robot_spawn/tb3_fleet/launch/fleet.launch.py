import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction, IncludeLaunchDescription, TimerAction
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushRosNamespace

ROBOTS = [
    {'name': 'tb3_0', 'x': '0.0', 'y': '0.0'},
    {'name': 'tb3_1', 'x': '1.0', 'y': '0.0'},
    {'name': 'tb3_2', 'x': '2.0', 'y': '0.0'},
]


def generate_launch_description():
    launch_dir = os.path.join(get_package_share_directory('tb3_fleet'), 'launch')
    ld = LaunchDescription([DeclareLaunchArgument('use_sim_time', default_value='true')])
    for index, robot in enumerate(ROBOTS):
        group = GroupAction([
            PushRosNamespace(robot['name']),
            Node(package='robot_state_publisher', executable='robot_state_publisher',
                 name='robot_state_publisher',
                 parameters=[{'use_sim_time': LaunchConfiguration('use_sim_time'),
                              'frame_prefix': robot['name'] + '/'}]),
            IncludeLaunchDescription(
                PythonLaunchDescriptionSource(os.path.join(launch_dir, 'spawn.launch.py')),
                launch_arguments={'x_pose': robot['x'], 'y_pose': robot['y'],
                                  'entity': robot['name']}.items()),
        ])
        # spawn one robot after the other
        ld.add_action(TimerAction(period=2.0 * index, actions=[group]))
    # rviz keeps wall-clock time while the simulated robots use sim time
    ld.add_action(Node(package='rviz2', executable='rviz2', name='rviz2'))  # expect: LV404
    return ld
