from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('camera', default_value='on'),
        DeclareLaunchArgument('headless', default_value='True'),
        Node(package='usb_cam', executable='usb_cam_node_exe', name='camera',
             condition=IfCondition(LaunchConfiguration('camera'))),  # expect: LV207
        # 'True' is fine: launch lowercases before comparing
        Node(package='rviz2', executable='rviz2', name='rviz',
             condition=UnlessCondition(LaunchConfiguration('headless'))),  # expect-not: LV207
        # a literal where LaunchConfiguration('headless') was meant: never a boolean
        Node(package='demo_nodes_cpp', executable='talker', name='talker',
             condition=IfCondition('headless')),  # expect: LV207
        DeclareLaunchArgument('use_sim', default_value='1'),
        Node(package='demo_nodes_cpp', executable='listener', name='listener',
             condition=IfCondition(LaunchConfiguration('use_sim'))),  # expect-not: LV207
    ])
