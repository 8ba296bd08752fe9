"""ROS 1 (roslaunch) files: recognised by a few strong signals, one info when checked alone.

A file is ROS 1 with a decisive signal (``$(find)``, ``$(arg)``) or two signals of
different kinds, and no ROS 2 spelling; see ``launchverify.frontends.tags.ros1_launch_file``.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from launchverify.evaluate.runner import evaluate
from launchverify.frontends import load_launch_file
from launchverify.frontends.tags import ROS1_MESSAGE
from launchverify.problems import ProblemKind
from launchverify.workspace.packages import PackageIndex


def recognised(tmp_path: Path, body: str, name: str = "f.launch.xml") -> bool:
    path = tmp_path / name
    path.write_text(body)
    return load_launch_file(path).ros1 is not None


@pytest.mark.parametrize("body", [
    # decisive on their own
    '<launch><include file="$(find pkg)/launch/a.launch"/></launch>',
    '<launch><arg name="a" default="1"/><include file="b.launch">'
    '<arg name="b" value="$(arg a)"/></include></launch>',
    # two kinds
    '<launch><rosparam file="p.yaml"/><node pkg="p" type="t" name="n"/></launch>',
    '<launch><arg name="a" value="1"/><param name="p" value="1"/></launch>',
    '<launch><group ns="r"><remap from="a" to="b"/></group></launch>',
    '<launch><machine name="m" address="h"/><test test-name="t" pkg="p" type="t"/></launch>',
    '<launch><node pkg="p" type="t" name="n" ns="r"/></launch>',
])
def test_ros1_files_are_recognised(tmp_path: Path, body: str) -> None:
    assert recognised(tmp_path, body)


@pytest.mark.parametrize("body", [
    # a single weak signal: a ROS 2 file with one mistake
    '<launch><arg name="a" default="1"/><rosparam file="p.yaml"/></launch>',
    '<launch><node pkg="p" type="t" name="n"/></launch>',
    '<launch><param name="p" value="1"/></launch>',
    # ROS 2 spellings veto, however many ROS 1 ones there are
    '<launch><node pkg="p" exec="e" name="$(arg a)"/></launch>',
    '<launch><include file="$(find-pkg-share p)/a.launch.xml"/><rosparam file="$(find p)/x"/>'
    '</launch>',
    '<launch><let name="a" value="1"/><rosparam file="p.yaml"/><param name="p" value="1"/>'
    '</launch>',
    '<launch><node pkg="p" type="t" namespace="r"/><rosparam file="p.yaml"/></launch>',
    '<launch><param name="p" value="$(var a)"/><rosparam file="p.yaml"/></launch>',
    # <arg value> inside <include> is ROS 2 as well; $(find-exec) is not $(find)
    '<launch><include file="a.launch.xml"><arg name="a" value="1"/></include>'
    '<rosparam file="p.yaml"/></launch>',
    '<launch><executable cmd="$(find-exec ls)"/></launch>',
    # not a launch root; commented-out ROS 1 does not count
    '<robot><node pkg="p" type="t" name="$(find p)"/></robot>',
    '<launch><!-- <rosparam file="$(find p)/x"/> --></launch>',
])
def test_ros2_files_are_not_recognised(tmp_path: Path, body: str) -> None:
    assert not recognised(tmp_path, body)


def test_launch_suffix_counts_as_one_signal(tmp_path: Path) -> None:
    body = '<launch><node pkg="p" type="t" name="n"/></launch>'
    assert recognised(tmp_path, body, "old.launch")
    assert not recognised(tmp_path, body, "new.launch.xml")


def test_the_info_points_at_the_root_and_names_the_evidence(tmp_path: Path) -> None:
    path = tmp_path / "f.launch.xml"
    path.write_text('<?xml version="1.0"?>\n<launch>\n  <rosparam file="$(find p)/x"/>\n'
                    '</launch>\n')
    loaded = load_launch_file(path)
    assert loaded.ros1 is not None
    assert loaded.ros1.kind is ProblemKind.UNMODELED
    assert loaded.ros1.message.startswith(ROS1_MESSAGE)
    assert "$(find) (line 3)" in loaded.ros1.message
    assert (loaded.ros1.span.line, loaded.ros1.span.column) == (2, 1)
    # what an includer reports stays: ros2 launch cannot load the file
    assert [p.kind for p in loaded.problems] == [ProblemKind.PARSE]


def test_checked_alone_one_info_included_its_errors(tmp_path: Path) -> None:
    old = tmp_path / "old.launch.xml"
    old.write_text('<launch>\n  <rosparam file="$(find p)/x"/>\n'
                   '  <node pkg="p" type="t" name="n"/>\n</launch>\n')
    new = tmp_path / "new.launch.xml"
    new.write_text('<launch>\n  <include file="$(dirname)/old.launch.xml"/>\n</launch>\n')
    index = PackageIndex()
    alone = evaluate(old.resolve(), index=index, workspace=tmp_path.resolve())
    assert [(r.problem.kind, r.problem.span.line) for r in alone.problems] == [
        (ProblemKind.UNMODELED, 1)]
    assert not alone.complete
    included = evaluate(new.resolve(), index=index, workspace=tmp_path.resolve())
    kinds = [(r.problem.kind, r.problem.span.line) for r in included.problems
             if r.problem.span.file == old.resolve()]
    assert kinds == [(ProblemKind.PARSE, 2), (ProblemKind.PARSE, 3)]
