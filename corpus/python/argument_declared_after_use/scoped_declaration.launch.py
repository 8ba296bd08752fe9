from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        # the group is scoped: 'frame' is forgotten when the group ends
        GroupAction([
            DeclareLaunchArgument('frame', default_value='base_link'),
            Node(package='demo_nodes_cpp', executable='talker', name='talker',
                 parameters=[{'frame_id': LaunchConfiguration('frame')}]),
        ]),
        Node(package='demo_nodes_cpp', executable='listener', name='listener',
             parameters=[{'frame_id': LaunchConfiguration('frame')}]),  # expect: LV201
    ])
