"""ros2_control in the computation graph: the controllers a spawner loads are nodes.

A spawner's controllers run in their manager's process, named after themselves in its
namespace, with the interface of their type's model; the spawner calls the manager's
services; ``/joint_states`` is never "published by nobody" when a broadcaster is spawned.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from launchverify.cli import main
from launchverify.engine import CheckOptions, run_check


@pytest.fixture(autouse=True)
def _no_ros(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)


def _systems(folder: Path, count: int) -> Path:
    """Write ``count`` root launch files, each starting a node of a shipped model."""
    launch = folder / "src" / "demo_bringup" / "launch"
    launch.mkdir(parents=True)
    (folder / "src" / "demo_bringup" / "package.xml").write_text(
        '<?xml version="1.0"?>\n<package format="3"><name>demo_bringup</name>'
        "<version>0.1.0</version><description>d</description>"
        '<maintainer email="d@example.com">d</maintainer><license>MIT</license>'
        "<export><build_type>ament_cmake</build_type></export></package>\n",
        encoding="utf-8")
    for number in range(count):
        (launch / f"robot{number}.launch.xml").write_text(
            f'<launch><node pkg="robot_state_publisher" exec="robot_state_publisher" '
            f'namespace="robot{number}"/>'
            '<node pkg="joint_state_publisher" exec="joint_state_publisher"/></launch>\n',
            encoding="utf-8")
    return folder


# ------------------------------------------------------------------ spawned controllers

SPAWNED = """\
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="controller_manager", executable="ros2_control_node",
             parameters=["{config}"]),
        Node(package="robot_state_publisher", executable="robot_state_publisher"),
        Node(package="controller_manager", executable="spawner",
             arguments=["joint_state_broadcaster", "diffbot_base_controller", "mystery",
                        "--param-file", "{spawner_config}",
                        "--controller-ros-args", "-r ~/cmd_vel:=/cmd_vel"]),
    ])
"""


def _spawned(folder: Path) -> Path:
    config = folder / "src" / "demo_bringup" / "config"
    config.mkdir(parents=True)
    (config / "manager.yaml").write_text(
        "controller_manager:\n  ros__parameters:\n    joint_state_broadcaster:\n"
        "      type: joint_state_broadcaster/JointStateBroadcaster\n", encoding="utf-8")
    (config / "controllers.yaml").write_text(
        "diffbot_base_controller:\n  ros__parameters:\n"
        "    type: diff_drive_controller/DiffDriveController\n", encoding="utf-8")
    _systems(folder, 0)
    root = folder / "src" / "demo_bringup" / "launch" / "bringup.launch.py"
    root.write_text(SPAWNED.format(config=config / "manager.yaml",
                                   spawner_config=config / "controllers.yaml"),
                    encoding="utf-8")
    return root


def _composed(root: Path, folder: Path) -> dict[str, object]:
    from launchverify.render.system_html import roots_to_show
    from launchverify.topology.compose import Composer, WorkspaceInterfaces
    from launchverify.workspace.packages import PackageIndex

    report = run_check(CheckOptions(paths=[root], workspace=folder))
    graph = roots_to_show(report)[0]
    source = WorkspaceInterfaces(PackageIndex.from_environment([folder], []))
    return {c.fqn or "?": c for c in Composer(graph, source, symbolic=False).compose()}


def test_spawned_controllers_are_nodes_of_the_managers_namespace(tmp_path: Path) -> None:
    from launchverify.topology.compose import NodeEndpoints

    folder = tmp_path / "ws"
    composed = _composed(_spawned(folder), folder)
    diff = composed["/diffbot_base_controller"]
    assert isinstance(diff, NodeEndpoints) and diff.interface is not None
    names = {e.endpoint.name: e.name for e in diff.endpoints}
    assert names["~/cmd_vel"] == "/cmd_vel"  # --controller-ros-args remaps it
    assert names["~/odom"] == "/diffbot_base_controller/odom"
    jsb = composed["/joint_state_broadcaster"]  # its type from the manager's parameters
    assert isinstance(jsb, NodeEndpoints) and jsb.executable == \
        "joint_state_broadcaster/JointStateBroadcaster"
    mystery = composed["/mystery"]  # no type anywhere: not known, never "creates nothing"
    assert isinstance(mystery, NodeEndpoints) and mystery.interface is None
    assert mystery.note is not None and "mystery.type" in mystery.note
    spawner = next(c for c in composed.values() if isinstance(c, NodeEndpoints)
                   and c.executable == "spawner")
    assert {e.name for e in spawner.endpoints} >= {"/controller_manager/load_controller"}


def test_joint_states_is_not_marked_unpublished(tmp_path: Path) -> None:
    folder = tmp_path / "ws"
    root = _spawned(folder)
    out = tmp_path / "report.html"
    # 'mystery' is defined nowhere: the manager refuses it (LV507)
    assert main(["report", str(root), "--workspace", str(folder), "-o", str(out)]) == 1
    page = out.read_text(encoding="utf-8")
    assert "LV507" in page and "mystery" in page
    joint = re.search(r'<g class="(ftopic[^"]*)"[^>]*><title>topic /joint_states\n([^<]*)',
                      page)
    assert joint is not None and "m-publisher" not in joint.group(1)
    assert "/joint_state_broadcaster" in joint.group(2)
    assert 'data-fqn="/diffbot_base_controller"' in page
    assert "<title>topic /diffbot_base_controller/odom\n" in page


def test_graph_json_and_wiring_view_see_controllers(tmp_path: Path,
                                                    capsys: pytest.CaptureFixture[str]) -> None:
    import json

    folder = tmp_path / "ws"
    root = _spawned(folder)
    assert main(["graph", str(root), "--workspace", str(folder), "--format", "json"]) == 0
    doc = json.loads(capsys.readouterr().out)
    odom = next(t for t in doc["topics"] if t["name"] == "/diffbot_base_controller/odom")
    assert [p["node"] for p in odom["publishers"]] == ["/diffbot_base_controller"]
    cmd = next(t for t in doc["topics"] if t["name"] == "/cmd_vel")
    assert [s["node"] for s in cmd["subscribers"]] == ["/diffbot_base_controller"]
    controllers = {c["name"]: c for c in doc["controllers"]}
    assert controllers["diffbot_base_controller"]["type"] == \
        "diff_drive_controller/DiffDriveController"
    assert controllers["diffbot_base_controller"]["manager"] == "/controller_manager"
    assert controllers["mystery"]["defined"] is False and controllers["mystery"]["type"] is None


def test_spawner_command_lines() -> None:
    from launchverify.ir.subst import Text
    from launchverify.topology.controllers import parse_spawner

    call = parse_spawner(["arm", "-c", "cm", "--inactive", "-u", "--param-file=/x.yaml"])
    assert call.controllers == ["arm"] and call.manager_fqn("/r1") == "/r1/cm"
    assert call.param_files == ["/x.yaml"] and call.unknown is None
    assert call.services() == ["list_controllers", "load_controller", "configure_controller",
                               "unload_controller"]
    assert parse_spawner(["arm", "-n", "robot2"]).manager_fqn("/") == \
        "/robot2/controller_manager"
    assert parse_spawner(["arm", "--ros-args", "-r", "a:=b"]).controllers == ["arm"]
    assert parse_spawner([Text("x")]).unknown is not None  # a name not known: unknown
    assert parse_spawner(["arm", "--bogus"]).unknown is not None
    assert parse_spawner(["arm", "-c", Text("x")]).manager_fqn("/") is None
