from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('x_pose', default_value='0.0'),
        DeclareLaunchArgument('y_pose', default_value='0.0'),
        DeclareLaunchArgument('entity'),
        Node(package='ros_gz_sim', executable='create', name='spawn',  # expect-not: LV101
             arguments=['-name', LaunchConfiguration('entity'),
                        '-x', LaunchConfiguration('x_pose'),
                        '-y', LaunchConfiguration('y_pose')]),
        # absolute: every robot's include starts the same /clock_bridge
        Node(package='ros_gz_bridge', executable='parameter_bridge',  # expect: LV101
             name='clock_bridge', namespace='/',
             arguments=['/clock@rosgraph_msgs/msg/Clock[gz.msgs.Clock']),
    ])
