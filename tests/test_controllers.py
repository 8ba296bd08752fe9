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


# ------------------------------------------------------------------ controller types (LV509)

TYPED = """\
controller_manager:
  ros__parameters:
    gps:
      type: gps_sensor_broadcaster/GPSSensorBroadcaster
    gripper:
      type: position_controllers/GripperActionController
    group:
      type: position_controllers/JointGroupPositionController
    legacy:
      type: joint_state_controller/JointStateController
"""

TYPED_LAUNCH = """\
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package="controller_manager", executable="ros2_control_node",
             parameters=["{config}"]),
        Node(package="controller_manager", executable="spawner",
             arguments=["gps", "gripper", "group", "legacy"]),
        Node(package="controller_manager", executable="spawner",
             arguments=["arm", "--controller-type",
                        "joint_trajectory_controller/JointTrajectoryControler"]),
    ])
"""


def _typed(folder: Path) -> Path:
    _systems(folder, 0)
    config = folder / "src" / "demo_bringup" / "config"
    config.mkdir(parents=True)
    (config / "controllers.yaml").write_text(TYPED, encoding="utf-8")
    root = folder / "src" / "demo_bringup" / "launch" / "typed.launch.py"
    root.write_text(TYPED_LAUNCH.format(config=config / "controllers.yaml"), encoding="utf-8")
    return root


def _unknown_types(root: Path, folder: Path, distro: str | None) -> dict[str, str]:
    report = run_check(CheckOptions(paths=[root], workspace=folder, distro=distro))
    found = {}
    for finding in report.findings:
        if finding.code == "LV509":
            name = re.search(r"controller '(\w+)'", finding.message)
            assert name is not None
            found[name.group(1)] = finding.message
    return found


@pytest.mark.parametrize(("distro", "reported"), [
    (None, {"legacy", "arm"}),  # what some release exports is taken
    ("humble", {"gps", "legacy", "arm"}),  # gps_sensor_broadcaster: since jazzy
    ("jazzy", {"legacy", "arm"}),
    ("kilted", {"gripper", "legacy", "arm"}),  # gripper_controllers left in kilted
    ("rolling", {"gripper", "group", "legacy", "arm"}),  # and the joint groups after it
])
def test_controller_types_per_distribution(tmp_path: Path, distro: str | None,
                                           reported: set[str]) -> None:
    folder = tmp_path / "ws"
    found = _unknown_types(_typed(folder), folder, distro)
    assert set(found) == reported
    assert "use joint_state_broadcaster/JointStateBroadcaster" in found["legacy"]
    assert "did you mean 'joint_trajectory_controller/JointTrajectoryController'" in \
        found["arm"]
    if "gps" in found:
        assert "humble has no gps_sensor_broadcaster" in found["gps"]
        assert "released since jazzy" in found["gps"]
    if "gripper" in found:
        assert "parallel_gripper_action_controller/GripperActionController" in found["gripper"]
    if "group" in found:
        assert "forward_command_controller/ForwardCommandController with interface_name: " \
            "position" in found["group"]


def test_controller_type_fixes(tmp_path: Path) -> None:
    from launchverify.rule import Applicability

    folder = tmp_path / "ws"
    root = _typed(folder)
    report = run_check(CheckOptions(paths=[root], workspace=folder, distro="rolling"))
    fixes = {f.message.split("'")[1]: f.fix for f in report.findings if f.code == "LV509"}
    legacy, arm = fixes["legacy"], fixes["arm"]
    assert legacy is not None and legacy.applicability is Applicability.SAFE
    assert legacy.edits[0].content == "joint_state_broadcaster/JointStateBroadcaster"
    assert legacy.edits[0].span.line == 10  # the YAML value
    assert arm is not None and arm.applicability is Applicability.SAFE
    assert arm.edits[0].span.file == root and arm.edits[0].span.line == 13
    gripper = fixes["gripper"]  # another action type: only with --unsafe-fixes
    assert gripper is not None and gripper.applicability is Applicability.UNSAFE
    assert fixes["group"] is None  # ForwardCommandController needs interface_name too


def test_a_workspace_package_may_export_a_released_type(tmp_path: Path) -> None:
    """Built from source on humble, parallel_gripper_controller exports its type."""
    folder = tmp_path / "ws"
    root = _typed(folder)
    config = folder / "src" / "demo_bringup" / "config" / "controllers.yaml"
    config.write_text("controller_manager:\n  ros__parameters:\n    gripper:\n      type: "
                      "parallel_gripper_action_controller/GripperActionController\n",
                      encoding="utf-8")
    found = _unknown_types(root, folder, "humble")
    assert set(found) == {"gripper", "arm"}  # not released for humble
    assert "(the type is released since jazzy)" in found["gripper"]
    package = folder / "src" / "parallel_gripper_controller"
    package.mkdir()
    (package / "package.xml").write_text(
        "<package format='3'><name>parallel_gripper_controller</name><version>1.0.0"
        "</version><description>d</description><maintainer email='d@example.com'>d"
        "</maintainer><license>Apache-2.0</license></package>\n", encoding="utf-8")
    (package / "CMakeLists.txt").write_text(
        "project(parallel_gripper_controller)\npluginlib_export_plugin_description_file("
        "controller_interface ros_control_plugins.xml)\n", encoding="utf-8")
    (package / "ros_control_plugins.xml").write_text(
        '<library path="parallel_gripper_action_controller"><class name='
        '"parallel_gripper_action_controller/GripperActionController" type='
        '"parallel_gripper_action_controller::GripperActionController" base_class_type='
        '"controller_interface::ControllerInterface"/></library>\n', encoding="utf-8")
    assert set(_unknown_types(root, folder, "humble")) == {"arm"}


def test_renamed_types_agree_with_the_models() -> None:
    """Each renamed type is gone from every modelled release from when the table says."""
    from launchverify.topology.controller_types import ORDER, RENAMED, release
    from launchverify.topology.releases import MODEL_DISTROS

    for old, renamed in RENAMED.items():
        for distro in MODEL_DISTROS:
            types = release(distro).types
            if ORDER.index(distro) >= ORDER.index(renamed.gone):
                assert old not in types and renamed.new in types, (old, distro)
            else:
                assert old in types, (old, distro)
