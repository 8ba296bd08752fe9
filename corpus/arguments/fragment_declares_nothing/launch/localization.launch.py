from launch import LaunchDescription
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    # declares no argument: every read is what its includer (in another repository) gives,
    # as neobotix's localization fragments are written
    params_file = LaunchConfiguration('params_file')  # expect-not: LV201
    namespace = LaunchConfiguration('namespace')  # expect-not: LV201
    use_sim_time = LaunchConfiguration('use_sim_time', default='false')
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='amcl', namespace=namespace,
             parameters=[params_file, {'use_sim_time': use_sim_time}]),
    ])
