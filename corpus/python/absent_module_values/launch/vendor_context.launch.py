# A context of the vendor's: what a substitution performs in it, and what a condition
# evaluates to, are unknown (not "perform() needs a LaunchContext", LV002), and the rest
# of the file is evaluated.
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, LogInfo
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from vendor_helpers import launch_context


def generate_launch_description():
    robot = LaunchConfiguration('robot', default='r1').perform(launch_context)  # expect-not: LV002
    simulated = IfCondition('true').evaluate(launch_context)  # expect-not: LV002
    return LaunchDescription([
        LogInfo(msg=[robot, ' simulated: ', str(simulated)]),
        DeclareLaunchArgument('robot_name', default_value='r1'),  # an entry point
        Node(package='demo_nodes_cpp', executable='talker', name=LaunchConfiguration('robot_name'),
             namespace=LaunchConfiguration('robot_id')),  # expect: LV201
    ])
