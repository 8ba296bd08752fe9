from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from vendor_helpers import default_model


def generate_launch_description():
    return LaunchDescription([
        # one choice is the vendor's: 'a' may be it on the robot
        DeclareLaunchArgument('model', choices=['b', default_model()], default_value='a'),  # expect-not: LV203
        # every choice is known, and the default is none of them
        DeclareLaunchArgument('mode', choices=['fast', 'safe'], default_value='Fast'),  # expect: LV203
        Node(package='demo_nodes_cpp', executable='talker',
             parameters=[{'model': LaunchConfiguration('model'),
                          'mode': LaunchConfiguration('mode')}]),
    ])
