"""Event handlers: loops without end, targets that never run, and the quiet cases.

launch refuses to execute one ExecuteProcess/Node object twice ('executed more than
once'), so a handler that restarts the very object it waits for fails the second time
(LV002 where the object is built); a loop that builds a new process each time, as an
OpaqueFunction does, never ends (LV501).
"""

from launch import LaunchDescription
from launch.actions import (DeclareLaunchArgument, ExecuteProcess, LogInfo, OpaqueFunction,
                            RegisterEventHandler, Shutdown)
from launch.conditions import IfCondition, UnlessCondition
from launch.event_handlers import OnProcessExit, OnProcessStart
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def start_worker(context):
    return [Node(package='acme_driver', executable='worker', name='worker')]


def start_helper(context):
    return [Node(package='acme_driver', executable='helper', name='helper')]


def generate_launch_description():
    use_sim = LaunchConfiguration('use_sim')
    driver = Node(package='acme_driver', executable='driver', name='driver')  # expect-not: LV002
    ping = ExecuteProcess(cmd=['ping_a'])  # expect-not: LV002
    pong = ExecuteProcess(cmd=['ping_b'])
    camera = ExecuteProcess(cmd=['camera_daemon'])
    recorder = ExecuteProcess(cmd=['recorder'])
    supervised = Node(package='acme_driver', executable='watchdog', name='watchdog',
                      respawn=True, respawn_max_retries=3)
    forgotten = Node(package='controller_manager', executable='spawner', name='spawner',
                     arguments=['arm_controller'])
    simulator = Node(package='acme_sim', executable='simulator', name='simulator',
                     condition=IfCondition(use_sim))
    return LaunchDescription([
        DeclareLaunchArgument('use_sim', default_value='false'),
        driver,
        # restarts its own target: the same object, so launch raises the second time (the
        # loop explains it: LV501, not LV002)
        RegisterEventHandler(OnProcessExit(  # expect: LV501
            target_action=driver, on_exit=[driver])),
        ping,
        # ping's exit starts pong, whose exit starts ping again: raises there
        RegisterEventHandler(OnProcessExit(target_action=ping, on_exit=[pong])),  # expect: LV501
        RegisterEventHandler(OnProcessExit(target_action=pong, on_exit=[ping])),
        # every process exit starts a new worker, whose exit starts another one
        RegisterEventHandler(OnProcessExit(  # expect: LV501
            on_exit=[OpaqueFunction(function=start_worker)])),
        camera,
        # trap: handle_once ends it after one run
        RegisterEventHandler(OnProcessExit(  # expect-not: LV501
            on_exit=[OpaqueFunction(function=start_helper)], handle_once=True)),
        recorder,
        # trap: a chain that ends
        RegisterEventHandler(OnProcessExit(  # expect-not: LV501
            target_action=recorder, on_exit=[LogInfo(msg='recording done'), Shutdown()])),
        supervised,
        # trap: respawn with a limit is how ROS 2 restarts a process
        RegisterEventHandler(OnProcessExit(  # expect-not: LV501
            target_action=supervised, on_exit=[LogInfo(msg='watchdog exited')])),
        # the spawner is never added to the launch: this never fires
        RegisterEventHandler(OnProcessStart(  # expect: LV502
            target_action=forgotten, on_start=[LogInfo(msg='spawning')])),
        simulator,
        # the simulator runs only with use_sim:=true, this handler only without
        RegisterEventHandler(OnProcessExit(  # expect: LV502
            target_action=simulator, on_exit=[Shutdown()]), condition=UnlessCondition(use_sim)),
        # trap: same condition as its target
        RegisterEventHandler(OnProcessExit(  # expect-not: LV502
            target_action=simulator, on_exit=[Shutdown()]), condition=IfCondition(use_sim)),
    ])
