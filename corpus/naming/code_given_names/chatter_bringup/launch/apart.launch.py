# The same executables without name=, where their code's names do not collide (or may not).
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, UnlessCondition
from launch.substitutions import EnvironmentVariable, LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    sim = LaunchConfiguration('sim')
    return LaunchDescription([
        DeclareLaunchArgument('sim', default_value='false'),
        Node(package='chatter_cpp', executable='talker'),
        # the launch names it: /speaker
        Node(package='chatter_cpp', executable='talker', name='speaker'),  # expect-not: LV101
        # so does a __node remap on its command line, or among its remappings
        Node(package='chatter_cpp', executable='talker',
             ros_arguments=['-r', '__node:=talker_b']),  # expect-not: LV101
        Node(package='chatter_cpp', executable='talker',
             arguments=['--ros-args', '--remap', '__node:=talker_c']),  # expect-not: LV101
        Node(package='chatter_cpp', executable='talker',
             remappings=[('__node', 'talker_d')]),  # expect-not: LV101
        # other namespaces
        Node(package='chatter_cpp', executable='talker', namespace='left'),
        Node(package='chatter_cpp', executable='talker', namespace='right'),  # expect-not: LV101
        # a namespace from the robot's environment: not known
        Node(package='chatter_cpp', executable='talker',
             namespace=EnvironmentVariable('ROBOT', default_value='')),  # expect-not: LV101
        # never together
        Node(package='chatter_py', executable='talker', namespace='sim', condition=IfCondition(sim)),
        Node(package='chatter_cpp', executable='talker', namespace='sim',
             condition=UnlessCondition(sim)),  # expect-not: LV101
        # an executable with two nodes, and one whose name comes from its command line
        Node(package='chatter_cpp', executable='pair'),
        Node(package='chatter_cpp', executable='pair'),  # expect-not: LV101
        Node(package='chatter_cpp', executable='named_by_argument', arguments=['a']),
        Node(package='chatter_cpp', executable='named_by_argument', arguments=['b']),  # expect-not: LV101
    ])
