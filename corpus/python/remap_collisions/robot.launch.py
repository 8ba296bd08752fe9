"""The Python twin of naming/remap_collisions (remappings point at their Node call)."""

from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, SetRemap


def generate_launch_description():
    return LaunchDescription([
        GroupAction([
            SetRemap(src='cmd_vel', dst='cmd_vel_nav'),
            Node(package='nav2_controller', executable='controller_server',  # expect: LV103
                 name='controller_server',
                 remappings=[('cmd_vel', 'cmd_vel_smoothed'), ('cmd_vel', 'cmd_vel_nav')]),
        ]),
        Node(package='demo_nodes_cpp', executable='talker', name='teleop',  # expect-not: LV103
             remappings=[('cmd_vel', 'cmd_vel_teleop')]),
        Node(package='demo_nodes_cpp', executable='talker', name='joystick',  # expect-not: LV103
             remappings=[('cmd_vel', 'cmd_vel_joy')]),
        Node(package='demo_nodes_cpp', executable='relay', name='relay',  # expect: LV103
             remappings=[('input', '/chatter'), ('output', 'chatter'),
                         ('other_node:input', '/elsewhere')]),
    ])
