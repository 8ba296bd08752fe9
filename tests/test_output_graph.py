"""``graph --format text``: values as a launch file spells them, never Python's."""

from __future__ import annotations

from pathlib import Path

import pytest

from launchverify.cli import main
from launchverify.ir import subst as s

LAUNCH = """<launch>
  <arg name="model" default="robot.urdf.xacro"/>
  <node pkg="robot_state_publisher" exec="robot_state_publisher">
    <param name="robot_description" value="$(command 'xacro $(var model)')"/>
    <param name="publish_frequency" value="20.0"/>
    <param name="ignore_timestamp" value="false"/>
    <param name="frames" value="[base, odom]"/>
  </node>
</launch>
"""


def test_parameter_values_read_as_launch_writes_them(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    launch = tmp_path / "describe.launch.xml"
    launch.write_text(LAUNCH)
    assert main(["graph", str(launch), "--format", "text"]) == 0
    params = {line.split(" = ")[0].split()[-1]: line.split(" = ", 1)[1].split("  (")[0]
              for line in capsys.readouterr().out.splitlines()
              if line.startswith("    param ")}
    assert params["robot_description"] == "<output of $(command 'xacro $(var model)')>"
    assert params["ignore_timestamp"] == "false"
    assert params["publish_frequency"] == "20.0"
    assert params["frames"] == "['base', 'odom']"
    assert "None" not in params.values() and "False" not in params.values()


def test_an_unknown_is_bracketed_once() -> None:
    assert s.Opaque("share folder of demo").describe() == "<share folder of demo>"
    assert s.Opaque("<share folder of demo>").describe() == "<share folder of demo>"
