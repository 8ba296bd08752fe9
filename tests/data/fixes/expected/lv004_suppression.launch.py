from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    note = "# launchverify: ignore[LV101] is text here, not a comment"
    return LaunchDescription([
        Node(package='demo', executable='talker', name='talker', output=note),
        Node(package='demo', executable='listener', name='listener'),
    ])
