# The buggy twin: the handler is registered exactly when its target cannot run.
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo, RegisterEventHandler
from launch.conditions import IfCondition, UnlessCondition
from launch.event_handlers import OnProcessStart
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    managed = LaunchConfiguration('use_lifecycle_manager')
    slam = Node(package='slam_toolbox', executable='sync_slam_toolbox_node', name='slam',
                condition=UnlessCondition(managed))
    return LaunchDescription([
        DeclareLaunchArgument('use_lifecycle_manager', default_value='false'),
        slam,
        RegisterEventHandler(  # expect: LV502
            OnProcessStart(target_action=slam, on_start=[LogInfo(msg='slam started')]),
            condition=IfCondition(managed)),
    ])
