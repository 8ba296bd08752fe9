import os

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, IncludeLaunchDescription, OpaqueFunction
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import LaunchConfiguration

HERE = os.path.dirname(os.path.abspath(__file__))


def include_sensors(context, sensors_file, *, extra=()):
    robot = LaunchConfiguration('robot').perform(context)
    sensors = context.perform_substitution(LaunchConfiguration('sensors')).split(',')
    actions = []
    for sensor in sensors + list(extra):
        actions.append(IncludeLaunchDescription(
            PythonLaunchDescriptionSource(os.path.join(HERE, sensors_file)),
            launch_arguments={'robot': robot, 'sensor': sensor, 'rate': '10'}.items()))  # expect: LV204
    return actions


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='rover'),
        DeclareLaunchArgument('sensors', default_value='lidar,camera'),
        OpaqueFunction(function=include_sensors, args=['sensor.launch.py'],
                       kwargs={'extra': ['lidar']}),
    ])
