# MoveIt's planning pipelines from the vendor's list: 'ompl' may be one of them, so the
# default is no failure (an LV003 that stopped the evaluation before), and the rest of
# the file is evaluated.
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node
from moveit_configs_utils import MoveItConfigsBuilder
from vendor_helpers import PIPELINES


def generate_launch_description():
    config = MoveItConfigsBuilder('robot', package_name='robot_moveit_config').planning_pipelines(
        default_planning_pipeline='ompl', pipelines=PIPELINES).to_moveit_configs()
    return LaunchDescription([
        Node(package='moveit_ros_move_group', executable='move_group',
             parameters=[config.to_dict()]),
        DeclareLaunchArgument('robot_name', default_value='r1'),  # an entry point
        Node(package='demo_nodes_cpp', executable='talker', name=LaunchConfiguration('robot_name'),
             namespace=LaunchConfiguration('robot_id')),  # expect: LV201
    ])
