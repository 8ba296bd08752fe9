import os

from ament_index_python.packages import get_package_share_directory
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.conditions import IfCondition, UnlessCondition
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration


def generate_launch_description():
    launch_dir = os.path.join(get_package_share_directory('my_robot_bringup'), 'launch')
    use_sim = LaunchConfiguration('use_sim')
    return LaunchDescription([
        DeclareLaunchArgument('use_sim', default_value='false'),
        DeclareLaunchArgument('robot_name', default_value='rover'),
        DeclareLaunchArgument('with_spare', default_value='false'),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource([launch_dir, '/driver.launch.py']),
            condition=UnlessCondition(use_sim),
            launch_arguments={'robot_name': LaunchConfiguration('robot_name')}.items()),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(os.path.join(launch_dir, 'sim.launch.py')),
            condition=IfCondition(use_sim),
            launch_arguments={'robot_name': LaunchConfiguration('robot_name'),
                              'world': 'warehouse'}.items()),
        # a typo: robot_name stays unset (the includes before do not count for the check)
        IncludeLaunchDescription(  # expect: LV208
            PythonLaunchDescriptionSource(os.path.join(launch_dir, 'driver.launch.py')),
            condition=IfCondition(LaunchConfiguration('with_spare')),
            launch_arguments={'robot_nmae': 'spare'}.items()),  # expect: LV204
    ])
