# webots_ros2's pattern: the simulator's supervisor is a process of a helper launchverify
# cannot see; when it exits (a simulation reset) a handler starts the robot's nodes again.
from launch import LaunchDescription
from launch.actions import RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch_ros.actions import Node
from vendor_helpers import SimulatorLauncher


def robot_nodes(*args):
    return [
        Node(package='demo_nodes_cpp', executable='talker', name='ekf_filter_node'),  # expect-not: LV101
        Node(package='demo_nodes_cpp', executable='listener', name='state_publisher'),
    ]


def generate_launch_description():
    simulator = SimulatorLauncher(world='warehouse.wbt')
    return LaunchDescription([
        simulator,
        RegisterEventHandler(OnProcessExit(  # expect-not: LV501 LV502
            target_action=simulator._supervisor, on_exit=robot_nodes)),
        *robot_nodes(),
    ])
