from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, GroupAction
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushROSNamespace, SetParameter, SetRemap


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('use_sim_time', default_value='false'),
        DeclareLaunchArgument('robot', default_value='tb3'),
        SetParameter(name='use_sim_time', value=LaunchConfiguration('use_sim_time')),
        GroupAction([
            PushROSNamespace(LaunchConfiguration('robot')),
            SetRemap(src='/tf', dst='tf'),
            SetRemap(src='/tf_static', dst='tf_static'),
            SetRemap(src='cmd_vel', dst='cmd vel'),  # expect: LV102
            Node(package='demo_nodes_cpp', executable='talker', name='driver'),
            Node(package='demo_nodes_cpp', executable='listener', name='odometry',
                 remappings=[('odom', 'odometry/filtered')]),
        ]),
        # outside the group: /driver, not /tb3/driver
        Node(package='demo_nodes_cpp', executable='talker', name='driver'),  # expect-not: LV101
    ])
