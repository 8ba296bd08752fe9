"""Start-up order, a handler on process start, a timer, then a shutdown."""
import os

from launch import LaunchDescription
from launch.actions import (EmitEvent, ExecuteProcess, LogInfo, RegisterEventHandler,
                            TimerAction)
from launch.event_handlers import OnExecutionComplete, OnProcessExit, OnProcessStart
from launch.events import Shutdown

WORKER = os.path.join(os.path.dirname(__file__), '..', 'nodes', 'worker.py')


def generate_launch_description():
    first = ExecuteProcess(cmd=['python3', WORKER, 'first'], output='screen')
    second = ExecuteProcess(cmd=['python3', WORKER, 'second'], output='screen')
    short = ExecuteProcess(cmd=['python3', WORKER, 'short', '--finish-after', '0.3'],
                           output='screen')
    return LaunchDescription([
        RegisterEventHandler(OnProcessStart(target_action=first, on_start=[second])),
        RegisterEventHandler(OnProcessExit(target_action=short, on_exit=[
            LogInfo(msg='short finished')])),
        RegisterEventHandler(OnExecutionComplete(target_action=short, on_completion=[
            LogInfo(msg='short complete')])),
        first,
        short,
        TimerAction(period=2.0, actions=[
            LogInfo(msg='timer fired'),
            EmitEvent(event=Shutdown(reason='timer'))]),
    ])
