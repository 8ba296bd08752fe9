# franka_ros2's slip: a LaunchConfiguration used as an argument *name*. launch performs it,
# so the included file receives an argument called by the IP address, not 'robot_ip'.
import os

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration


def generate_launch_description():
    robot_ip = LaunchConfiguration('robot_ip')
    return LaunchDescription([
        DeclareLaunchArgument('robot_ip'),
        IncludeLaunchDescription(  # expect: LV208  # expect-not: LV005
            PythonLaunchDescriptionSource(os.path.join(os.path.dirname(__file__),
                                                       'child.launch.py')),
            launch_arguments={robot_ip: robot_ip, 'use_fake_hardware': 'false'}.items()),  # expect: LV204
    ])
