"""Include paths computed from an argument: every candidate is followed under its guard.

The sensor's launch file is found from ``sensor``: with ``choices`` each one is tried (a
missing one is a finding), without them the packages or files that fit the pattern are.
A mistake in one candidate's file is reported with the value that reaches it.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from launchverify.cli import main

TREE = Path(__file__).resolve().parent.parent / "corpus" / "files" / "computed_includes"
ROOT = TREE / "robot_bringup" / "launch"


@pytest.fixture(autouse=True)
def _no_ros(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)


@pytest.mark.parametrize("root", ["sensors_by_choice.launch.py",
                                  "sensors_by_package.launch.xml"])
def test_a_mistake_in_one_candidate_names_its_value(
        root: str, capsys: pytest.CaptureFixture[str]) -> None:
    main(["check", str(ROOT / root), "--workspace", str(TREE), "--format", "json",
          "--no-cache"])
    findings = json.loads(capsys.readouterr().out)["findings"]
    assert [(f["code"], f["witness"]) for f in findings] == [("LV101", {"sensor": "ouster"})]
    assert findings[0]["file"].endswith("ouster_sensor_launch/launch/driver.launch.xml")


def test_graph_lists_the_candidates(capsys: pytest.CaptureFixture[str]) -> None:
    main(["graph", str(ROOT / "sensors_by_choice.launch.py"), "--workspace", str(TREE),
          "--symbolic"])
    includes = json.loads(capsys.readouterr().out)["includes"]
    computed = next(i for i in includes if i["status"] == "computed")
    assert computed["computed_from"] == "sensor"
    assert computed["candidates"] == ["velodyne", "ouster"]
    branches = {i["candidates"][0]: i for i in includes if i["status"] == "loaded"}
    assert branches["ouster"]["condition"] == "$(var sensor) == 'ouster'"
    assert branches["ouster"]["target"].endswith("ouster_sensor_launch/launch/driver.launch.xml")


def test_a_choice_without_its_package_is_reported(tmp_path: Path,
                                                  capsys: pytest.CaptureFixture[str]) -> None:
    root = tmp_path / "robot.launch.py"
    root.write_text((ROOT / "sensors_by_choice.launch.py").read_text().replace(
        "choices=['velodyne', 'ouster']", "choices=['velodyne', 'ouster', 'hesai']"))
    main(["check", str(root), "--workspace", str(TREE), "--format", "json", "--no-cache"])
    codes = {f["code"] for f in json.loads(capsys.readouterr().out)["findings"]}
    assert "LV303" in codes  # hesai_sensor_launch: the choice reaches a package not there


def test_a_file_name_pattern_tries_the_files_that_fit(tmp_path: Path,
                                                      capsys: pytest.CaptureFixture[str]) -> None:
    """Without a default the arguments as given name no file: the folder's files that fit
    the name are tried. With a default, that file alone is followed, as before."""
    (tmp_path / "robots").mkdir()
    for robot, extra in (("alpha", ""), ("beta", '<node pkg="a" exec="b" name="n"/>')):
        (tmp_path / "robots" / f"{robot}.launch.xml").write_text(
            f'<launch><node pkg="a" exec="b" name="n"/>{extra}</launch>')
    include = '<include file="$(dirname)/robots/$(var robot).launch.xml"/></launch>'
    for declared, expected in (('<arg name="robot"/>', [("LV101", {"robot": "beta"})]),
                               ('<arg name="robot" default="alpha"/>', [])):
        root = tmp_path / "main.launch.xml"
        root.write_text(f"<launch>{declared}{include}")
        main(["check", str(root), "--workspace", str(tmp_path), "--format", "json",
              "--no-cache"])
        findings = json.loads(capsys.readouterr().out)["findings"]
        assert [(f["code"], f["witness"]) for f in findings if f["code"] == "LV101"] == \
            expected


def test_a_computed_path_outside_the_workspace_is_not_listed(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """The folder a computed file name points into is listed only inside the workspace:
    a launch file cannot make the check reveal another folder's file names."""
    outside = tmp_path / "outside"
    outside.mkdir()
    (outside / "private_key.launch.xml").write_text("<launch/>")
    workspace = tmp_path / "ws"
    workspace.mkdir()
    root = workspace / "main.launch.xml"
    root.write_text(f'<launch><arg name="name"/><include file="{outside}/$(var name).launch.xml"/>'
                    "</launch>")
    main(["graph", str(root), "--workspace", str(workspace), "--symbolic"])
    includes = json.loads(capsys.readouterr().out)["includes"]
    assert [i["status"] for i in includes] == ["unresolved"]
    assert "private_key" not in json.dumps(includes)
