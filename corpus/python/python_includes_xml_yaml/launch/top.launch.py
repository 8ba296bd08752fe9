import os

from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import AnyLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution, ThisLaunchFileDir
from launch_xml.launch_description_sources import XMLLaunchDescriptionSource
from launch_yaml.launch_description_sources import YAMLLaunchDescriptionSource


def generate_launch_description():
    here = os.path.dirname(__file__)
    return LaunchDescription([
        IncludeLaunchDescription(  # expect: LV208
            AnyLaunchDescriptionSource(os.path.join(here, 'camera.launch.xml'))),
        IncludeLaunchDescription(
            XMLLaunchDescriptionSource(os.path.join(here, 'camera.launch.xml')),
            launch_arguments={'camera_name': 'front'}.items()),
        IncludeLaunchDescription(
            YAMLLaunchDescriptionSource(
                PathJoinSubstitution([ThisLaunchFileDir(), 'lidar.launch.yaml'])),
            launch_arguments={'frame': 'laser', 'scan_rate': '10'}.items()),  # expect: LV204
        IncludeLaunchDescription(  # expect: LV302
            AnyLaunchDescriptionSource(os.path.join(here, 'imu.launch.xml'))),
    ])
