"""Spawners from controller_manager's launch helpers (each declares its own arguments)."""

from controller_manager.launch_utils import (
    generate_controllers_spawner_launch_description,
    generate_load_controller_launch_description,
)
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument


def generate_launch_description():
    return LaunchDescription([
        # the helpers read their unload_on_kill and controller_manager_name themselves
        generate_controllers_spawner_launch_description(  # expect-not: LV202
            ['joint_state_broadcaster', 'arm_controller'],
            controller_params_files=['/opt/robot/controllers.yaml'],
        ),
        generate_load_controller_launch_description('gripper_controller'),  # expect-not: LV202
        # declared here and read nowhere: the helpers do not make every argument used
        DeclareLaunchArgument('use_fake_hardware', default_value='true'),  # expect: LV202
    ])
