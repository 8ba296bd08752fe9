from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

ROBOT_COUNT = 3


def generate_launch_description():
    ld = LaunchDescription([DeclareLaunchArgument('use_sim_time', default_value='true')])
    for i in range(ROBOT_COUNT):
        ld.add_action(Node(package='nav2_controller', executable='controller_server',
                           name='controller_server', namespace=f'robot{i}',  # expect-not: LV101
                           parameters=[{'use_sim_time': LaunchConfiguration('use_sim_time')}]))
        # every robot gets its own namespace, but the bridge forgot it:
        ld.add_action(Node(  # expect: LV101
            package='ros_gz_bridge', executable='parameter_bridge', name='bridge',
            arguments=[f'/model/robot{i}/cmd_vel@geometry_msgs/msg/Twist]gz.msgs.Twist']))
    return ld
