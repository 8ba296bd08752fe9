from launch import LaunchDescription
from launch.actions import (DeclareLaunchArgument, ExecuteProcess, LogInfo,
                            RegisterEventHandler, TimerAction)
from launch.event_handlers import OnProcessExit, OnProcessStart
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    spawn = Node(package='ros_gz_sim', executable='create', name='spawn_robot',
                 arguments=['-name', LaunchConfiguration('robot'), '-topic', 'robot_description'])
    load_controllers = ExecuteProcess(
        cmd=['ros2', 'control', 'load_controller', '--set-state', 'active',
             'joint_state_broadcaster'],
        output='screen')
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='bot'),
        spawn,
        RegisterEventHandler(OnProcessExit(
            target_action=spawn,
            on_exit=[load_controllers,
                     Node(package='controller_manager', executable='spawner',
                          name='spawner_diff_drive', arguments=['diff_drive_controller']),
                     LogInfo(msg='robot spawned')])),
        RegisterEventHandler(OnProcessStart(
            target_action=spawn,
            on_start=[Node(package='demo_nodes_cpp', executable='listener', name='watchdog')])),
        TimerAction(period=5.0, actions=[
            Node(package='demo_nodes_cpp', executable='talker', name='teleop'),
            # the watchdog is started by the OnProcessStart handler already
            Node(package='demo_nodes_cpp', executable='listener', name='watchdog'),  # expect: LV101
        ]),
        TimerAction(period='2', actions=[
            Node(package='demo_nodes_cpp', executable='talker', name='spawner_arm',
                 condition=None),
        ]),
    ])
