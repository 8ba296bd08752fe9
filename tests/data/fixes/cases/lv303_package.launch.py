from launch import LaunchDescription
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    params = PathJoinSubstitution([FindPackageShare("demoo"), "config", "params.yaml"])
    return LaunchDescription([
        Node(package="demoo", executable="talker", name="talker", parameters=[params]),
    ])
