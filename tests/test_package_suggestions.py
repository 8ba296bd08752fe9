"""LV303 on packages that exist nowhere, and the names it suggests for them."""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from launchverify.engine import CheckOptions, run_check
from launchverify.rule import Finding, Severity
from launchverify.suggest import SUGGESTION_THRESHOLD, closest_package, name_similarity

FIXTURE = (Path(__file__).resolve().parent.parent / "corpus" / "files"
           / "unknown_package_not_released")

words = st.text("abcdegimnorst2", min_size=1, max_size=9)
names = st.lists(words, min_size=1, max_size=4).map("_".join)


@pytest.mark.parametrize(("name", "workspace", "expected"), [
    ("ros_gz_sim", ["ros_gz_simulator", "ros_gz_bridge"], "ros_gz_simulator"),
    ("nav2_bringup", ["navigation2_bringup", "nav2_common"], "navigation2_bringup"),
    ("my_robot_description", ["my_robot_descriptions", "my_robot_bringup"],
     "my_robot_descriptions"),
    ("robot_description", ["my_robot_description"], "my_robot_description"),
    ("my_robot_sim", ["my_robot_simulation", "my_robot_bringup"], "my_robot_simulation"),
    ("acme_ctrl", ["acme_control", "acme_driver"], "acme_control"),
])
def test_a_shortened_or_lengthened_name_finds_its_package(
        name: str, workspace: list[str], expected: str) -> None:
    assert closest_package(name, workspace) == expected


@pytest.mark.parametrize(("name", "workspace"), [
    ("acme_private_driver", ["local_tools", "my_robot_description"]),
    ("my_robot_driver", ["my_robot_description"]),  # a different package of one robot
    ("sensor_a_driver", ["sensor_b_driver"]),
    ("gazebo", ["gazebo_ros"]),  # one word in common is not enough
    ("ros", ["rosbridge_server"]),
    ("my_robot", ["my_robot_bringup", "my_robot_description"]),  # a tie: no guess
    ("anything", []),
])
def test_no_suggestion_when_nothing_is_clearly_close(name: str, workspace: list[str]) -> None:
    assert closest_package(name, workspace) is None


@given(names, names)
def test_similarity_is_symmetric_and_bounded(name: str, other: str) -> None:
    score = name_similarity(name, other)
    assert 0.0 <= score <= 1.0
    assert score == pytest.approx(name_similarity(other, name))


@given(names)
def test_a_name_is_wholly_like_itself(name: str) -> None:
    assert name_similarity(name, name) == 1.0


@given(names, st.lists(names, max_size=8))
def test_a_suggestion_is_another_candidate_close_enough(name: str, pool: list[str]) -> None:
    suggestion = closest_package(name, pool)
    if suggestion is not None:
        assert suggestion in pool and suggestion != name
        assert name_similarity(name, suggestion) >= SUGGESTION_THRESHOLD
    assert closest_package(name, list(reversed(pool))) == suggestion


def _lv303(tree: Path, workspace: Path | None = None) -> dict[tuple[str, int], Finding]:
    report = run_check(CheckOptions(paths=[tree], workspace=workspace or tree))
    return {(f.span.file.name, f.span.line): f for f in report.findings if f.code == "LV303"}


def test_typos_are_errors_close_names_warn_names_like_nothing_inform(
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    found = {key: (f.severity, f.message.partition(" (did you mean ")[2].rstrip("?)"))
             for key, f in _lv303(FIXTURE).items()}
    assert found == {
        ("robot.launch.xml", 6): (Severity.ERROR, "'acme_descriptions'"),
        ("robot.launch.xml", 8): (Severity.WARNING, "'acme_navigation2_bringup'"),
        ("robot.launch.xml", 10): (Severity.INFO, ""),
        ("robot.launch.xml", 12): (Severity.WARNING, "'acme_simulation'"),
        ("sim.launch.py", 16): (Severity.WARNING, "'acme_simulation'"),
        ("sim.launch.py", 17): (Severity.INFO, ""),
        ("sim.launch.py", 25): (Severity.INFO, ""),  # a numbered sibling, not a typo
        ("sim.launch.py", 28): (Severity.INFO, ""),  # another vendor's prefix, not a typo
        ("sim.launch.py", 30): (Severity.ERROR, "'leo_gz_worlds'"),
    }


def _write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


LAUNCH = """<launch>
  <node pkg="acme_private_driver" exec="driver" name="driver"/>
  <node pkg="demo_node_cpp" exec="talker" name="talker"/>
  <node pkg="rviz2" exec="rviz2" name="rviz"/>
</launch>
"""


def test_loose_launch_files_judge_only_typos(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    _write(tmp_path / "robot.launch.xml", LAUNCH)  # no package.xml: no workspace to miss
    assert list(_lv303(tmp_path)) == [("robot.launch.xml", 3)]


def test_with_ros_installed_every_package_found_nowhere_is_an_error(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    prefix = tmp_path / "opt"
    for installed in ("demo_nodes_cpp", "acme_private_drivers_pkg"):
        _write(prefix / "share" / "ament_index" / "resource_index" / "packages" / installed, "")
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(prefix))
    workspace = tmp_path / "ws"
    _write(workspace / "robot.launch.xml", LAUNCH)
    found = _lv303(workspace)
    assert {key: f.severity for key, f in found.items()} == {
        ("robot.launch.xml", line): Severity.ERROR for line in (2, 3, 4)}
    assert found[("robot.launch.xml", 3)].message.endswith("(did you mean 'demo_nodes_cpp'?)")
