# webots_ros2_driver's helpers are modelled: the supervisor node, the driver the handlers
# name, the nodes started once the driver connects, the reset handler.
import launch
from launch import LaunchDescription
from launch_ros.actions import Node
from webots_ros2_driver.wait_for_controller_connection import WaitForControllerConnection
from webots_ros2_driver.webots_controller import WebotsController
from webots_ros2_driver.webots_launcher import WebotsLauncher


def generate_launch_description():
    webots = WebotsLauncher(world='/opt/worlds/arena.wbt', ros2_supervisor=True)  # expect-not: LV404
    driver = WebotsController(robot_name='rover', parameters=[{'use_sim_time': True}])
    spawner = Node(package='controller_manager', executable='spawner',
                   arguments=['diffdrive_controller'])
    odometry = Node(package='demo_nodes_cpp', executable='listener', name='odometry',
                    parameters=[{'use_sim_time': True}])
    echo = Node(package='demo_nodes_cpp', executable='listener', name='odometry',  # expect: LV101
                parameters=[{'use_sim_time': True}])
    waiting = WaitForControllerConnection(target_driver=driver,
                                          nodes_to_start=[spawner, odometry, echo])
    return LaunchDescription([
        webots,
        webots._supervisor,
        driver,
        waiting,
        launch.actions.RegisterEventHandler(  # expect-not: LV502
            event_handler=launch.event_handlers.OnProcessExit(
                target_action=driver,
                on_exit=[launch.actions.EmitEvent(event=launch.events.Shutdown())])),
    ])
