"""Processes that handlers run again: a loop is LV501, a plain second run stays LV002."""

from launch import LaunchDescription
from launch.actions import ExecuteProcess, RegisterEventHandler
from launch.event_handlers import OnProcessExit, OnProcessStart


def generate_launch_description():
    mapper = ExecuteProcess(cmd=['mapper'], name='mapper')  # expect-not: LV002
    saver = ExecuteProcess(cmd=['map_saver'], name='saver')
    # run again when the bridge starts, with no loop back to it: launch raises all the same
    logger = ExecuteProcess(cmd=['logger'], name='logger')  # expect: LV002
    bridge = ExecuteProcess(cmd=['bridge'], name='bridge')
    return LaunchDescription([
        # registered before mapper runs; handle_once does not help: the first time saver
        # exits, mapper (already running since launch) is executed a second time
        RegisterEventHandler(OnProcessExit(  # expect: LV501
            target_action=saver, on_exit=[mapper], handle_once=True)),
        mapper,
        RegisterEventHandler(OnProcessExit(
            target_action=mapper, on_exit=[saver], handle_once=True)),
        logger,
        bridge,
        RegisterEventHandler(OnProcessStart(target_action=bridge, on_start=[logger])),
    ])
