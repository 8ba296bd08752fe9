from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument("log_level", default_value="info"),
        # rules in arguments' --ros-args section come first on the command line: they win;
        # --log-level's value is no rule, and the words after -- are the program's again
        Node(package="chat_cpp", executable="talker", name="talker",
             arguments=["--verbose", "-r", "chatter:=/not_a_rule", "--ros-args",
                        "--log-level", LaunchConfiguration("log_level"),
                        "-r", "chatter:=/zeroth", "--", "-r", "chatter:=/after"],
             ros_arguments=["-r", "chatter:=/first"]),
    ])
