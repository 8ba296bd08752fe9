"""One dict for two nodes: each name is for whichever node declares it."""
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    # baud_rate is the driver's, max_velocity_x the controller's; baud_rat is nobody's
    shared = {'baud_rate': 9600, 'max_velocity_x': 0.5, 'baud_rat': 1}
    return LaunchDescription([
        Node(package='serial_driver', executable='driver',
             parameters=[shared]),  # expect: LV405
        Node(package='base_control', executable='base_controller',
             parameters=[shared, {'port': '/dev/ttyS0'}]),  # expect-not: LV405
    ])
