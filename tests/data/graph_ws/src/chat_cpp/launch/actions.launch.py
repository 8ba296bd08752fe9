from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="chat_py", executable="counter", name="counter", namespace="left",
             remappings=[("peer/count", "/right/count")]),
        Node(package="chat_py", executable="counter", name="counter", namespace="right"),
        Node(package="demo_nodes_cpp", executable="talker"),
    ])
