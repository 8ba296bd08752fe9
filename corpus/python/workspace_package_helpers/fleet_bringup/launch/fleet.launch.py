from fleet_tools.launch_utils import DEFAULT_ROBOTS, robot_group, supervisor
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument


def generate_launch_description():
    robots = DEFAULT_ROBOTS + ['r1']  # r1 twice: its group starts the same nodes again
    return LaunchDescription([
        DeclareLaunchArgument('use_arm', default_value='true'),
        *[robot_group(r, with_arm=True) for r in robots],
        supervisor(robots),
    ])
