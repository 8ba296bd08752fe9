"""Fifty processes; one crashes and is respawned; a timer shuts the launch down."""
import os

from launch import LaunchDescription
from launch.actions import EmitEvent, ExecuteProcess, TimerAction
from launch.events import Shutdown

WORKER = os.path.join(os.path.dirname(__file__), '..', 'nodes', 'worker.py')


def generate_launch_description():
    actions = []
    for index in range(50):
        extra = ['--crash-after', '0.5', '--crash-once'] if index == 7 else []
        actions.append(ExecuteProcess(
            cmd=['python3', WORKER, f'worker{index}', *extra], name=f'worker{index}',
            output='log', respawn=index == 7, respawn_max_retries=1, sigterm_timeout='2'))
    # Long enough for worker7's respawn to be running (signal handlers set) before the
    # shutdown, even when fifty interpreters start at once on a loaded two-core machine.
    actions.append(TimerAction(period=6.0, actions=[EmitEvent(event=Shutdown(reason='done'))]))
    return LaunchDescription(actions)
