from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution
from launch_ros.actions import Node
from launch_ros.substitutions import FindPackageShare


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_node_cpp', executable='talker', name='talker'),  # expect-error: LV303
        # two edits from the released kobuki_core, but a real package built from source
        Node(package='kobuki_node', executable='kobuki_ros_node', name='kobuki'),  # expect-warning: LV303
        Node(package='demo_nodes_cpp', executable='listener', name='listener'),
        Node(package='acme_private_driver', executable='driver', name='driver'),  # expect: LV303
        Node(package='local_tools', executable='tool', name='tool'),
        IncludeLaunchDescription(PythonLaunchDescriptionSource(  # expect: LV303
            PathJoinSubstitution([FindPackageShare('local_tool'), 'launch', 'tool.launch.py']))),
    ])
