from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # ros_arguments come before the remappings: their rule for chatter wins
        Node(package="chat_cpp", executable="talker", name="talker",
             ros_arguments=["-r", "chatter:=/first"],
             remappings=[("chatter", "/second")]),
    ])
