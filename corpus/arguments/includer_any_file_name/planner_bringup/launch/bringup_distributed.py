# Checked like any launch file: a .py file in a launch folder defining
# generate_launch_description.
import os

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration


def generate_launch_description():
    here = os.path.dirname(__file__)
    return LaunchDescription([
        DeclareLaunchArgument('params_file', default_value=os.path.join(here, 'planner.yaml')),
        IncludeLaunchDescription(
            PythonLaunchDescriptionSource(os.path.join(here, 'planner_launch.py')),
            launch_arguments={'params_file': LaunchConfiguration('params_file'),
                              'default_bt_xml_filename': 'tree.xml'}.items()),  # expect: LV204
    ])
