# A helper (webots_ros2_driver's WaitForControllerConnection) starts the nodes it is given
# once the controller is up: the handler's target runs, through code launchverify cannot see.
from launch import LaunchDescription
from launch.actions import RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch_ros.actions import Node
from vendor_helpers import WaitForController


def generate_launch_description():
    spawner = Node(package='demo_nodes_cpp', executable='talker')
    return LaunchDescription([
        WaitForController(nodes_to_start=[spawner]),
        RegisterEventHandler(OnProcessExit(  # expect-not: LV502
            target_action=spawner, on_exit=[Node(package='demo_nodes_cpp', executable='listener')])),
    ])
