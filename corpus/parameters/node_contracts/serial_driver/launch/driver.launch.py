"""The driver given its parameters inline."""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='serial_driver', executable='driver', namespace='left',
             parameters=[{
                 'device': '/dev/ttyACM0',
                 'baud_rate': 57600.0,  # expect: LV406
                 'timeout': 1.0,
                 'extra': 'text',  # expect-not: LV406
                 'filters.enabled': False,
                 'filters.windw': 3,  # expect: LV405
             }]),
        # device is declared with a type only: unset, which the code may check for
        Node(package='serial_driver', executable='driver', namespace='right',  # expect-not: LV408
             parameters=[{'baud_rate': 9600}]),
    ])
