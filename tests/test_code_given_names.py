"""LV101 on nodes the launch does not name: the names their code gives them (issue 45).

The corpus tree ``naming/code_given_names`` holds the bugs and the traps; these tests pin
what the corpus markers cannot see: where the finding points, what it says, and that no
interface is read when no two unnamed nodes can collide.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from launchverify.engine import CheckOptions, run_check
from launchverify.rule import Finding

CORPUS = Path(__file__).resolve().parent.parent / "corpus" / "naming" / "code_given_names"


def _lv101(tree: Path, monkeypatch: pytest.MonkeyPatch) -> list[Finding]:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    report = run_check(CheckOptions(paths=[tree], workspace=tree))
    return sorted((f for f in report.findings if f.code == "LV101"),
                  key=lambda f: f.span.line)


def test_the_finding_points_at_where_the_code_names_the_node(
        monkeypatch: pytest.MonkeyPatch) -> None:
    found = {f.span.line: f for f in _lv101(CORPUS, monkeypatch)}
    talker = found[12]
    assert "the launch names neither node" in talker.message
    assert "talker.cpp:10 in the sources of chatter_cpp" in talker.message
    places = [(r.span.file.name, r.span.line) for r in talker.related]
    assert places == [("duplicates.launch.py", 11), ("talker.cpp", 10)]
    # two executables, one name: both places where their code gives it
    mixed = found[15]
    assert {(r.span.file.name, r.span.line) for r in mixed.related} >= {
        ("talker.py", 9), ("talker.cpp", 10)}
    # a component: its constructor's initialiser
    relay = found[28]
    assert ("relay.cpp", 13) in [(r.span.file.name, r.span.line) for r in relay.related]


def test_a_model_without_the_place_names_what_it_was_extracted_from(
        monkeypatch: pytest.MonkeyPatch) -> None:
    found = {f.span.line: f for f in _lv101(CORPUS, monkeypatch)}
    model = found[20]
    assert "/robot_state_publisher" in model.message
    assert "the model of robot_state_publisher shipped with launchverify" in model.message
    assert "github.com/ros/robot_state_publisher" in model.message


LONE = """from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='chatter_cpp', executable='talker'),
        Node(package='chatter_cpp', executable='talker', namespace='left'),
        Node(package='chatter_py', executable='talker', namespace='right'),
        Node(package='chatter_cpp', executable='talker', name='talker', namespace='left'),
    ])
"""


def test_no_interface_is_read_when_no_two_unnamed_nodes_can_collide(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    tree = tmp_path / "ws"
    shutil.copytree(CORPUS, tree)
    for launch in (tree / "chatter_bringup" / "launch").iterdir():
        launch.unlink()
    (tree / "chatter_bringup" / "launch" / "lone.launch.py").write_text(LONE)
    from launchverify.topology import compose

    asked: list[object] = []
    monkeypatch.setattr(compose, "code_name", lambda *args: asked.append(args))
    # three unnamed nodes in three namespaces; the launch-named /left/talker is compared
    # with launch-given names only
    assert _lv101(tree, monkeypatch) == []
    assert asked == []  # no interface composed for LV101


def test_two_unnamed_nodes_that_may_share_a_namespace_are_composed(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The counterpart of the test above: the gate opens, and only those two are asked."""
    tree = tmp_path / "ws"
    shutil.copytree(CORPUS, tree)
    for launch in (tree / "chatter_bringup" / "launch").iterdir():
        launch.unlink()
    (tree / "chatter_bringup" / "launch" / "lone.launch.py").write_text(
        LONE.replace("namespace='right'", "namespace='left'"))
    found = _lv101(tree, monkeypatch)
    assert [(f.span.line, "/left/talker" in f.message) for f in found] == [(9, True)]
