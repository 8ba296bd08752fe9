# slam_toolbox's online_sync_launch.py: the activation handler is registered only when
# autostart is on and no lifecycle manager drives the node. Checked on its own it is fine.
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo, RegisterEventHandler
from launch.conditions import IfCondition
from launch.event_handlers import OnProcessStart
from launch.substitutions import AndSubstitution, LaunchConfiguration, NotSubstitution
from launch_ros.actions import Node


def generate_launch_description():
    autostart = LaunchConfiguration('autostart')
    managed = LaunchConfiguration('use_lifecycle_manager')
    slam = Node(package='slam_toolbox', executable='sync_slam_toolbox_node', name='slam_toolbox',
                condition=IfCondition(NotSubstitution(managed)))
    return LaunchDescription([
        DeclareLaunchArgument('autostart', default_value='true'),
        DeclareLaunchArgument('use_lifecycle_manager', default_value='false'),
        slam,
        RegisterEventHandler(  # expect-not: LV502
            OnProcessStart(target_action=slam, on_start=[LogInfo(msg='slam started')]),
            condition=IfCondition(AndSubstitution(autostart, NotSubstitution(managed)))),
    ])
