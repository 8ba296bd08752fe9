"""What event handlers start runs in the scope launch has when the event comes.

launch visits the whole file before it handles any event and captures no scope at a
handler's registration (humble, jazzy and rolling): the group a handler is registered in
has popped its namespace, SetParameter, SetRemap and configurations by then. The expected
names are those the real launch library gives (checked with the differential oracle).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from launchverify.cli import main

HEADER = """from launch import LaunchDescription
from launch.actions import (GroupAction, RegisterEventHandler, SetLaunchConfiguration,
                            TimerAction)
from launch.event_handlers import OnProcessExit, OnProcessStart
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node, PushRosNamespace, SetParameter, SetRemap


def talker(name):
    return Node(package='demo_nodes_cpp', executable='talker',
                name=[name, '_', LaunchConfiguration('who', default='unset')])
"""

GROUPED = HEADER + """

def generate_launch_description():
    spawner = Node(package='controller_manager', executable='spawner', name='spawner')
    return LaunchDescription([
        SetLaunchConfiguration('who', 'outer'),
        GroupAction([
            PushRosNamespace('robot1'),
            SetLaunchConfiguration('who', 'inner'),
            SetParameter('group_param', 1),
            SetRemap('chatter', 'group_chatter'),
            RegisterEventHandler(OnProcessExit(target_action=spawner,
                                               on_exit=[talker('on_exit')])),
            RegisterEventHandler(OnProcessStart(target_action=spawner, on_start=[
                GroupAction([PushRosNamespace('own'), talker('pushed_in_handler')])])),
            TimerAction(period=1.0, actions=[talker('timer')]),
            spawner,
            talker('at_launch'),
        ]),
        SetLaunchConfiguration('who', 'late'),
    ])
"""

NESTED = HEADER + """

def generate_launch_description():
    first = Node(package='controller_manager', executable='spawner', name='first')
    second = Node(package='controller_manager', executable='spawner', name='second')
    return LaunchDescription([
        GroupAction([
            PushRosNamespace('robot1'),
            RegisterEventHandler(OnProcessExit(target_action=first, on_exit=[
                PushRosNamespace('leaked'),
                SetLaunchConfiguration('who', 'leaked'),
                RegisterEventHandler(OnProcessExit(target_action=second,
                                                   on_exit=[talker('nested')])),
                second,
            ])),
            first,
        ]),
    ])
"""


def graph_nodes(tmp_path: Path, text: str, capsys: pytest.CaptureFixture[str]
                ) -> dict[str, list[str]]:
    """Return each node line of ``graph --format text`` with the lines describing it."""
    path = tmp_path / "handlers.launch.py"
    path.write_text(text)
    assert main(["graph", str(path), "--format", "text"]) == 0
    nodes: dict[str, list[str]] = {}
    current: list[str] | None = None
    for line in capsys.readouterr().out.splitlines():
        if line.startswith("/"):
            current = nodes.setdefault(line.split()[0], [])
        elif line.startswith("    ") and current is not None:
            current.append(line.strip())
        else:
            current = None
    return nodes


def test_a_handlers_node_runs_outside_the_group_that_registered_it(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    nodes = graph_nodes(tmp_path, GROUPED, capsys)
    # at launch: the group's namespace, parameter, remap and configuration
    assert "/robot1/at_launch_inner" in nodes
    assert any(line.startswith("param group_param") for line in nodes["/robot1/at_launch_inner"])
    # the handler's node: none of them, and the configuration the top level ends with
    assert "/on_exit_late" in nodes
    assert nodes["/on_exit_late"] == []
    assert not any(name.startswith("/robot1/on_exit") for name in nodes)
    # a namespace pushed in the handler's own entities applies
    assert "/own/pushed_in_handler_late" in nodes
    # a timer captures the scope it is executed in (jazzy 3.4.5, rolling; humble's gives
    # /timer_late, which is not modelled)
    assert "/robot1/timer_inner" in nodes


def test_a_nested_handler_sees_what_the_handler_that_registered_it_left(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    nodes = graph_nodes(tmp_path, NESTED, capsys)
    # the first handler's entities ran unscoped at the top level: their namespace and
    # configuration stay there, for the process they start and the handler they register
    assert "/leaked/second" in nodes
    assert "/leaked/nested_leaked" in nodes
    assert "/robot1/first" in nodes
