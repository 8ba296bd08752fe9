"""Two nodes of one name that never run at the same time are not duplicates.

launch starts what an OnProcessExit handler runs once the target's process has exited;
the target runs again only when it respawns (ProcessExited is emitted before launch
respawns it). OnExecutionComplete of a process fires after its last run, respawns
included. Processes in OnShutdown handlers are not started at all.
"""

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, RegisterEventHandler, TimerAction
from launch.event_handlers import (OnExecutionComplete, OnProcessExit, OnProcessStart,
                                   OnShutdown)
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node

PKG = 'acme_tools'


def generate_launch_description():
    # a script, then a second one under the same name once the first has exited
    generate_launch = Node(package=PKG, executable='generate_launch', name='generate')
    # expect-not: LV101
    generate_param = Node(package=PKG, executable='generate_param', name='generate')

    # a chain: the first exits, a middle step runs and exits, then the second
    first_step = Node(package=PKG, executable='fetch', name='step')
    middle_step = Node(package=PKG, executable='unpack', name='unpack')
    last_step = Node(package=PKG, executable='install', name='step')  # expect-not: LV101

    # on_exit of the process itself is an OnProcessExit on it (the handler's node is
    # recorded first, so a finding would land on either line)
    second_pass = Node(package=PKG, executable='pass_two', name='pass')  # expect-not: LV101
    # expect-not: LV101
    first_pass = Node(package=PKG, executable='pass_one', name='pass', on_exit=[second_pass])

    # completion comes after the last run, respawns included
    server = Node(package=PKG, executable='server', name='server', respawn=True)
    # expect-not: LV101
    replacement = Node(package=PKG, executable='server_fallback', name='server')

    # a respawn that never happens
    once = Node(package=PKG, executable='once', name='once', respawn=True, respawn_max_retries=0)
    after_once = Node(package=PKG, executable='after_once', name='once')  # expect-not: LV101

    # nothing starts at shutdown
    recorder = Node(package=PKG, executable='recorder', name='recorder')
    # expect-not: LV101
    final_recorder = Node(package=PKG, executable='recorder_flush', name='recorder')

    # trap: started when the first one starts, both run
    monitor = Node(package=PKG, executable='monitor', name='monitor')
    # expect: LV101
    second_monitor = Node(package=PKG, executable='monitor_backup', name='monitor')

    # trap: a timer after the first one, which still runs
    bridge = Node(package=PKG, executable='bridge', name='bridge')
    late_bridge = Node(package=PKG, executable='bridge_late', name='bridge')  # expect: LV101

    # trap: started on the exit of another process, unrelated to the first
    logger = Node(package=PKG, executable='logger', name='logger')
    unrelated = Node(package=PKG, executable='unrelated', name='unrelated')
    other_logger = Node(package=PKG, executable='logger_two', name='logger')  # expect: LV101

    # trap: the first one respawns after its exit, while the second runs
    driver = Node(package=PKG, executable='driver', name='driver', respawn=True)
    driver_helper = Node(package=PKG, executable='driver_helper', name='driver')  # expect: LV101

    # trap: it respawns when use_respawn:=true
    planner = Node(package=PKG, executable='planner', name='planner',
                   respawn=LaunchConfiguration('use_respawn'))
    planner_check = Node(package=PKG, executable='planner_check', name='planner')  # expect: LV101

    # trap: a handler without target fires on the exit of any process
    watcher = Node(package=PKG, executable='watcher', name='watcher')
    watcher_two = Node(package=PKG, executable='watcher_two', name='watcher')  # expect: LV101

    return LaunchDescription([
        DeclareLaunchArgument('use_respawn', default_value='false'),
        generate_launch,
        RegisterEventHandler(OnProcessExit(target_action=generate_launch,
                                           on_exit=[generate_param])),
        first_step,
        RegisterEventHandler(OnProcessExit(target_action=first_step, on_exit=[middle_step])),
        RegisterEventHandler(OnProcessExit(target_action=middle_step, on_exit=[last_step])),
        first_pass,
        server,
        RegisterEventHandler(OnExecutionComplete(target_action=server,
                                                 on_completion=[replacement])),
        once,
        RegisterEventHandler(OnProcessExit(target_action=once, on_exit=[after_once])),
        recorder,
        RegisterEventHandler(OnShutdown(on_shutdown=[final_recorder])),
        monitor,
        RegisterEventHandler(OnProcessStart(target_action=monitor,
                                            on_start=[second_monitor])),
        bridge,
        TimerAction(period=5.0, actions=[late_bridge]),
        logger,
        unrelated,
        RegisterEventHandler(OnProcessExit(target_action=unrelated, on_exit=[other_logger])),
        driver,
        RegisterEventHandler(OnProcessExit(target_action=driver, on_exit=[driver_helper])),
        planner,
        RegisterEventHandler(OnProcessExit(target_action=planner, on_exit=[planner_check])),
        watcher,
        RegisterEventHandler(OnProcessExit(on_exit=[watcher_two], handle_once=True)),
    ])
