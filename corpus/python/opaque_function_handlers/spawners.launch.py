# ros2_control bring-ups (allegro_hand's) register the next spawners' handlers in an
# OpaqueFunction, waiting for a spawner made in generate_launch_description: the same
# object, which the launch starts (no LV502). One made in the function and never added
# is never executed: the handler waits for nothing.
from launch import LaunchDescription
from launch.actions import OpaqueFunction, RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch_ros.actions import Node


def generate_launch_description():
    broadcaster = Node(package='controller_manager', executable='spawner',
                       arguments=['joint_state_broadcaster'])

    def spawn_controllers(context):
        arm = Node(package='controller_manager', executable='spawner',
                   arguments=['arm_controller'])
        forgotten = Node(package='controller_manager', executable='spawner',
                         arguments=['gripper_controller'])
        return [
            RegisterEventHandler(OnProcessExit(  # expect-not: LV502
                target_action=broadcaster, on_exit=[arm])),
            RegisterEventHandler(OnProcessExit(  # expect: LV502
                target_action=forgotten, on_exit=[Node(
                    package='controller_manager', executable='spawner',
                    arguments=['gripper_action_controller'])])),
        ]

    return LaunchDescription([broadcaster, OpaqueFunction(function=spawn_controllers)])
