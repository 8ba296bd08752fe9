"""The Python twin of naming/remap_collisions (each remapping points at its own tuple)."""

from launch import LaunchDescription
from launch.actions import GroupAction
from launch_ros.actions import Node, SetRemap


def generate_launch_description():
    return LaunchDescription([
        GroupAction([
            SetRemap(src='cmd_vel', dst='cmd_vel_nav'),
            Node(package='nav2_controller', executable='controller_server',  # expect-not: LV103
                 name='controller_server',
                 remappings=[
                     # the group's rule comes first and wins
                     ('cmd_vel', 'cmd_vel_smoothed'),  # expect: LV103
                     # the same rule twice changes nothing
                     ('cmd_vel', 'cmd_vel_nav'),  # expect-not: LV103
                 ]),
        ]),
        Node(package='demo_nodes_cpp', executable='talker', name='teleop',  # expect-not: LV103
             remappings=[('cmd_vel', 'cmd_vel_teleop')]),
        Node(package='demo_nodes_cpp', executable='talker', name='joystick',  # expect-not: LV103
             remappings=[('cmd_vel', 'cmd_vel_joy')]),
        Node(package='demo_nodes_cpp', executable='relay', name='relay',  # expect-not: LV103
             remappings=[
                 ('input', '/chatter'),
                 # a relay reading and writing one topic loops forever
                 ('output', 'chatter'),  # expect: LV103
                 # a rule for another node of the process
                 ('other_node:input', '/elsewhere'),  # expect-not: LV103
             ]),
    ])
