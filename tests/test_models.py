"""Interface models: the shipped files, their format, and the fallback of the graph to them.

A model is what the extractor found in a released package's public sources at a recorded
commit (``bench/interface_models.py`` writes them); a launched node of a package without
sources in the workspace gets its interface from it.
"""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from launchverify.cli import main
from launchverify.topology.compose import WorkspaceInterfaces
from launchverify.topology.model import EndpointKind
from launchverify.topology.nodes import package_interfaces
from launchverify.topology.releases import MODEL_DISTROS
from launchverify.topology.shipped import (
    ModelError,
    ModelSource,
    _shipped,
    dump_model,
    model_document,
    read_model,
    released_model,
    shipped_model,
    shipped_packages,
)
from launchverify.workspace.packages import Package, PackageIndex

ROOT = Path(__file__).resolve().parent.parent
DATA = Path(__file__).parent / "data" / "topology"
SOURCE = ModelSource("https://github.com/example/demo", "jazzy", "0123456789" * 4, "demo_cpp")
# Packages issue 17 asks models for (a few more are shipped)
WANTED = {"robot_state_publisher", "joint_state_publisher", "joy", "teleop_twist_joy",
          "teleop_twist_keyboard", "twist_mux", "slam_toolbox", "robot_localization",
          "pointcloud_to_laserscan", "image_proc", "depth_image_proc", "tf2_ros",
          "nav2_controller", "nav2_planner", "nav2_bt_navigator", "nav2_behaviors",
          "nav2_smoother", "nav2_velocity_smoother", "nav2_collision_monitor",
          "nav2_map_server", "nav2_amcl", "nav2_lifecycle_manager", "nav2_waypoint_follower",
          "nav2_route", "controller_manager", "joint_state_broadcaster", "opennav_docking",
          "diff_drive_controller", "joint_trajectory_controller",
          "forward_command_controller"}
# And issue 45 (every distribution's release, realsense, the image pipeline, every
# controller of ros2_controllers)
WANTED_IN_EVERY_DISTRO = WANTED - {"nav2_route", "opennav_docking"} | {
    "realsense2_camera", "stereo_image_proc", "image_rotate", "image_view",
    "ackermann_steering_controller", "admittance_controller", "pid_controller",
    "imu_sensor_broadcaster", "force_torque_sensor_broadcaster", "tricycle_controller",
    "range_sensor_broadcaster", "pose_broadcaster", "gpio_controllers",
    "mecanum_drive_controller", "bicycle_steering_controller"}
MODEL_FILES = sorted((ROOT / "models" / "interfaces").glob("*/*.json"))


def _model_id(path: Path) -> str:
    return f"{path.parent.name}/{path.stem}"


# --------------------------------------------------------------------------- shipped files


def test_the_wanted_packages_are_shipped() -> None:
    assert set(shipped_packages()) >= WANTED


@pytest.mark.parametrize("distro", MODEL_DISTROS)
def test_every_distribution_has_its_release_of_the_wanted_packages(distro: str) -> None:
    shipped = {path.stem for path in MODEL_FILES if path.parent.name == distro}
    assert shipped >= WANTED_IN_EVERY_DISTRO, sorted(WANTED_IN_EVERY_DISTRO - shipped)
    assert {path.parent.name for path in MODEL_FILES} == set(MODEL_DISTROS)


@pytest.mark.parametrize("path", MODEL_FILES, ids=_model_id)
def test_every_shipped_model_parses_and_names_its_source_commit(path: Path) -> None:
    package, distro = path.stem, path.parent.name
    document = json.loads(path.read_text())
    model = read_model(document)
    assert model.package == package
    assert re.fullmatch(r"[0-9a-f]{40}", model.source.commit)
    assert model.source.repository.startswith("https://github.com/")
    assert model.source.branch
    assert model.extracted_with.startswith("launchverify ")
    assert model.interfaces, "a model of no executable is no use"
    released = released_model(package, distro)
    assert released is not None and all(i.distro == distro for i in released.interfaces)
    for interface in model.interfaces:
        assert interface.package == package
        assert interface.model is not None and model.source.commit[:12] in interface.model
        for endpoint in interface.endpoints:
            assert (endpoint.name is None) == (endpoint.unresolved_reason is not None)
            assert str(endpoint.span.file).startswith(model.source.label())
    assert dump_model(document) == path.read_text(), "written by dump_model, unedited"


def test_shipped_models_are_data_not_code() -> None:
    """Only the documented keys: no source text, qos expressions or owners leak in; a
    parameter's default is plain data."""
    allowed = {"kind", "name", "type", "name_parameter", "parameter_default", "via",
               "note", "unresolved", "at"}
    parameter_keys = {"name", "type", "default", "dynamic", "required", "strict", "read_only",
                      "limits", "via", "at"}
    for path in MODEL_FILES:
        package = path.stem
        document = json.loads(path.read_text())
        assert set(document) == {"format", "package", "source", "extracted_with",
                                 "interfaces"}
        for interface in document["interfaces"]:
            assert set(interface) - {"node_name_at", "loaders", "plugins"} == {
                "executable", "component", "node_name", "problems", "parameters_open",
                "endpoints", "parameters"}
            for endpoint in interface["endpoints"]:
                assert set(endpoint) <= allowed, (package, endpoint)
            plugins = interface.get("plugins", [])
            for plugin in plugins:
                assert set(plugin) == {"type", "base", "open", "parameters"}, (package, plugin)
            for parameter in [*interface["parameters"],
                              *(p for plugin in plugins for p in plugin["parameters"])]:
                assert set(parameter) <= parameter_keys, (package, parameter)
                assert isinstance(parameter.get("default"), (type(None), bool, int, float, str,
                                                             list)), (package, parameter)


def test_nav2_servers_as_checked_against_their_sources() -> None:
    """A few facts read by eye in navigation2's jazzy sources, kept by the model."""
    def names(package: str, executable: str) -> dict[str, set[str | None]]:
        model = shipped_model(package)
        assert model is not None
        interface = min((i for i in model.interfaces if i.executable == executable),
                        key=lambda i: i.component is not None)
        out: dict[str, set[str | None]] = {}
        for e in interface.endpoints:
            out.setdefault(e.kind.value, set()).add(e.name)
        return out

    controller = names("nav2_controller", "controller_server")
    assert {"follow_path"} <= controller["action_server"]
    assert {"cmd_vel", "local_costmap/costmap", "local_costmap/costmap_raw"} <= (
        controller["publisher"])
    assert {"odom", "local_costmap/footprint", "speed_limit"} <= controller["subscription"]
    assert "local_costmap/clear_entirely_local_costmap" in controller["service"]
    planner = names("nav2_planner", "planner_server")
    assert {"compute_path_to_pose", "compute_path_through_poses"} <= planner["action_server"]
    smoother = names("nav2_velocity_smoother", "velocity_smoother")
    assert smoother["publisher"] == {"cmd_vel_smoothed"}
    assert {"cmd_vel", "odom"} <= smoother["subscription"]
    manager = names("nav2_lifecycle_manager", "lifecycle_manager")
    assert manager["service"] == {"~/manage_nodes", "~/is_active"}
    assert manager["publisher"] == {"/diagnostics"}
    rsp = names("robot_state_publisher", "robot_state_publisher")
    assert rsp == {"publisher": {"/tf", "/tf_static", "robot_description"},
                   "subscription": {"joint_states"}}


def test_loading_is_lazy_one_package_at_a_time() -> None:
    _shipped.cache_clear()
    released_model.cache_clear()
    reader = WorkspaceInterfaces(PackageIndex())
    interface, _ = reader.interface("joy", "joy_node", False)
    assert interface is not None
    assert _shipped.cache_info().currsize == 1
    assert released_model.cache_info().currsize == len(MODEL_DISTROS)
    assert shipped_model("not_a_package") is None
    assert shipped_model("../pyproject") is None  # not a package name: no file is opened


def test_reading_a_model_imports_no_tree_sitter() -> None:
    code = ("import sys\nfrom launchverify.topology.shipped import shipped_model\n"
            "assert shipped_model('nav2_amcl') is not None\n"
            "print(sorted(m for m in sys.modules if m.startswith('tree_sitter')))\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert out.strip() == "[]"


def test_pyproject_ships_the_models_in_the_wheel() -> None:
    if sys.version_info >= (3, 11):
        import tomllib
    else:  # pragma: no cover
        import tomli as tomllib
    config = tomllib.loads((ROOT / "pyproject.toml").read_text())
    assert "interfaces/*/*.json" in config["tool"]["setuptools"]["package-data"][
        "launchverify.models"]


# --------------------------------------------------------------------------- the format


def _key(interface: Any) -> tuple[Any, ...]:
    return (interface.executable, interface.component, interface.node_name,
            tuple((e.kind, e.name, e.type, e.name_parameter, e.parameter_default, e.via,
                   e.note, e.unresolved_reason, e.span.line) for e in interface.endpoints))


def _key_of(e: Any) -> tuple[Any, ...]:
    return (e.kind, e.name, e.type, e.name_parameter, e.parameter_default, e.via, e.note,
            e.unresolved_reason)


def test_round_trip_of_a_workspace_package() -> None:
    root = DATA / "demo_cpp"
    interfaces = package_interfaces(Package("demo_cpp", source=root))
    document = model_document("demo_cpp", interfaces, SOURCE, root, "launchverify test")
    model = read_model(json.loads(dump_model(document)))
    assert model.source == SOURCE
    assert len(model.interfaces) == len(interfaces)
    for read, extracted in zip(model.interfaces, interfaces, strict=True):
        kept: list[Any] = []
        for e in extracted.endpoints:  # one line per endpoint differing in more than place
            if all(_key_of(k) != _key_of(e) for k in kept):
                kept.append(e)
        assert _key(read) == _key(extracted.__class__(
            extracted.package, extracted.executable, extracted.component,
            extracted.node_name, tuple(kept), ()))
        assert all(root.as_posix() not in p for p in read.problems)
        for endpoint, original in zip(read.endpoints, kept, strict=True):
            relative = original.span.file.relative_to(root).as_posix()
            assert endpoint.span.file == Path(f"demo@0123456/demo_cpp/{relative}")
        if extracted.node_name_at is None:
            assert read.node_name_at is None
        else:  # where the code names the node, as the endpoints' places
            assert read.node_name_at is not None
            relative = extracted.node_name_at.file.relative_to(root).as_posix()
            assert read.node_name_at.file == Path(f"demo@0123456/demo_cpp/{relative}")
            assert read.node_name_at.line == extracted.node_name_at.line
    assert any(i.node_name_at is not None for i in model.interfaces)


def _document(**changes: Any) -> dict[str, Any]:
    document: dict[str, Any] = {
        "format": 1, "package": "demo",
        "source": {"repository": "https://github.com/example/demo", "branch": "jazzy",
                   "commit": "ab" * 20, "path": ""},
        "extracted_with": "launchverify 0.1.0",
        "interfaces": [{"executable": "demo", "component": None, "node_name": "demo",
                        "problems": [], "endpoints": [
                            {"kind": "publisher", "name": "out", "type": "std_msgs/msg/Empty",
                             "at": "src/demo.cpp:7"},
                            {"kind": "subscription", "name_parameter": "input",
                             "unresolved": "parameter 'input' has no default"}]}]}
    document.update(changes)
    return document


def test_a_minimal_model_reads_as_documented() -> None:
    model = read_model(_document())
    (interface,) = model.interfaces
    out, into = interface.endpoints
    assert (out.kind, out.name, out.type, out.span.line) == (
        EndpointKind.PUBLISHER, "out", "std_msgs/msg/Empty", 7)
    assert str(out.span.file) == "demo@abababa/src/demo.cpp"
    assert (into.name, into.name_parameter, into.unresolved_reason) == (
        None, "input", "parameter 'input' has no default")


@pytest.mark.parametrize(("changes", "message"), [
    ({"format": 2}, "format 1"),
    ({"source": {"repository": "x", "branch": "b", "commit": "main", "path": ""}},
     "40 hex digits"),
    ({"source": None}, "'source'"),
    ({"package": ""}, "'package'"),
    ({"interfaces": {}}, "'interfaces'"),
    ({"interfaces": [{"executable": "x", "endpoints": [{"kind": "topic"}]}]}, "kind"),
    ({"interfaces": [{"executable": "x", "endpoints": [{"kind": "publisher", "name": 3}]}]},
     "'name'"),
])
def test_a_malformed_model_is_a_model_error(changes: dict[str, Any], message: str) -> None:
    with pytest.raises(ModelError, match=message):
        read_model(_document(**changes))


# --------------------------------------------------------------------------- the fallback


def _package(root: Path, name: str, code: str | None) -> Path:
    folder = root / "src" / name
    (folder / "launch").mkdir(parents=True)
    (folder / "package.xml").write_text(
        f"<package format='3'><name>{name}</name>"
        "<export><build_type>ament_cmake</build_type></export></package>")
    (folder / "CMakeLists.txt").write_text(
        f"project({name})\nadd_executable({name} src/main.cpp)\n"
        f"install(TARGETS {name} DESTINATION lib/${{PROJECT_NAME}})\n")
    if code is not None:
        (folder / "src").mkdir()
        (folder / "src" / "main.cpp").write_text(code)
    return folder


def test_workspace_sources_win_over_a_shipped_model(tmp_path: Path) -> None:
    _package(tmp_path, "robot_state_publisher",
             'int main() { auto n = rclcpp::Node::make_shared("rsp");\n'
             '  n->create_publisher<std_msgs::msg::String>("my_description", 1); }\n')
    reader = WorkspaceInterfaces(PackageIndex([tmp_path]))
    interface, note = reader.interface("robot_state_publisher", "robot_state_publisher", False)
    assert interface is not None and note is None and interface.model is None
    assert [e.name for e in interface.endpoints] == ["my_description"]


def test_a_package_without_sources_falls_back_to_its_model(tmp_path: Path) -> None:
    _package(tmp_path, "robot_state_publisher", None)  # launch files only, as installed
    reader = WorkspaceInterfaces(PackageIndex([tmp_path]))
    interface, note = reader.interface("robot_state_publisher", "robot_state_publisher", False)
    assert interface is not None and interface.model is not None
    assert note is not None and "model shipped with launchverify" in note
    assert "ros/robot_state_publisher" in note and "commit" in note
    component, _ = reader.interface("robot_state_publisher",
                                    "robot_state_publisher::RobotStatePublisher", True)
    assert component is not None and component.component is not None


def test_a_package_not_found_falls_back_too_and_unknowns_say_why(tmp_path: Path) -> None:
    reader = WorkspaceInterfaces(PackageIndex([tmp_path]))
    interface, note = reader.interface("nav2_amcl", "amcl", False)
    assert interface is not None and interface.node_name == "amcl"
    assert note is not None and "navigation2 branch jazzy" in note
    none, why = reader.interface("nav2_amcl", "no_such_exe", False)
    assert none is None and why is not None and "has no executable no_such_exe" in why
    none, why = reader.interface("acme_driver", "driver", False)
    assert none is None and why is not None and "no model is shipped" in why
    off = WorkspaceInterfaces(PackageIndex([tmp_path]), models=False)
    assert off.interface("nav2_amcl", "amcl", False)[0] is None


LAUNCH = """<launch>
  <node pkg="robot_state_publisher" exec="robot_state_publisher"/>
  <node pkg="joint_state_publisher" exec="joint_state_publisher">
    <remap from="joint_states" to="/arm/joint_states"/>
  </node>
  <node pkg="joy" exec="joy_node"/>
</launch>
"""


def test_graph_composes_released_nodes_from_their_models(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    folder = _package(tmp_path, "bringup", None)
    launch = folder / "launch" / "robot.launch.xml"
    launch.write_text(LAUNCH)
    assert main(["graph", str(launch), "--workspace", str(tmp_path), "--format", "json"]) == 0
    document = json.loads(capsys.readouterr().out)
    topics = {t["name"]: t for t in document["topics"]}
    assert [e["node"] for e in topics["/arm/joint_states"]["publishers"]] == [
        "/joint_state_publisher"]
    assert [e["node"] for e in topics["/joint_states"]["subscribers"]] == [
        "/robot_state_publisher"]
    assert [e["node"] for e in topics["/robot_description"]["publishers"]] == [
        "/robot_state_publisher"]
    assert [e["node"] for e in topics["/robot_description"]["subscribers"]] == [
        "/joint_state_publisher"]
    source = topics["/joy"]["publishers"][0]["source"]
    assert source.startswith("joystick_drivers@") and source.endswith(".cpp:99")
    for node in document["nodes"]:
        assert node["interface"]["found"]
        assert "model shipped with launchverify" in node["interface"]["note"]


def test_a_model_that_creates_nothing_is_not_taken_for_a_silent_node() -> None:
    """joint_state_publisher_gui publishes through joint_state_publisher's class: its
    extracted sources show no endpoint, which must read as unknown, not as none."""
    from launchverify.topology.shipped import EMPTY_MODEL

    model = shipped_model("joint_state_publisher_gui")
    assert model is not None
    empty = [i for i in model.interfaces if not i.endpoints]
    assert empty and all(i.problems == (EMPTY_MODEL,) for i in empty)


# --------------------------------------------------------------------------- distributions


def _diffbot(tmp_path: Path, block: str) -> Path:
    """Return a workspace starting diff_drive_controller (no sources) with ``block``."""
    package = tmp_path / "ws" / "bot"
    shutil.copytree(ROOT / "corpus" / "parameters" / "released_contracts" / "diffbot", package)
    config = package / "config" / "controllers.yaml"
    config.write_text(config.read_text().replace("    publish_rate: 50.0  # expect-not: LV405",
                                                 block))
    return tmp_path / "ws"


def _codes_at(capsys: pytest.CaptureFixture[str], *args: str) -> set[tuple[str, str]]:
    """Return the findings on rear_controller's last line (the block ``_diffbot`` wrote)."""
    main(["check", "--no-cache", "--format", "json", *args])
    report = json.loads(capsys.readouterr().out)
    config = Path(args[0]) / "bot" / "config" / "controllers.yaml"
    last = len(config.read_text().splitlines())
    return {(f["code"], f["severity"]) for f in report["findings"]
            if f["file"].endswith("controllers.yaml") and f["line"] == last}


def test_a_name_one_release_declares_is_judged_by_the_distribution(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    """diff_drive_controller's use_stamped_vel is humble's alone (jazzy dropped it)."""
    monkeypatch.delenv("ROS_DISTRO", raising=False)
    ws = _diffbot(tmp_path, "    use_stamped_vel: false")
    assert _codes_at(capsys, str(ws), "--distro", "humble") == set()
    assert _codes_at(capsys, str(ws), "--distro", "jazzy") == {("LV405", "warning")}
    assert _codes_at(capsys, str(ws)) == set()  # any distribution: one release takes it
    assert _codes_at(capsys, str(ws), "--distro", "kilted") == set()  # no model: merged


def test_a_typo_is_an_error_for_every_distribution(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("ROS_DISTRO", raising=False)
    ws = _diffbot(tmp_path, "    cmd_vel_timout: 0.5")
    for distro in ([], ["--distro", "humble"], ["--distro", "rolling"]):
        assert _codes_at(capsys, str(ws), *distro) == {("LV405", "error")}


def test_the_merge_keeps_only_what_every_release_agrees_on() -> None:
    merged = shipped_model("diff_drive_controller")
    humble = released_model("diff_drive_controller", "humble")
    assert merged is not None and humble is not None
    (interface,) = merged.interfaces
    names = {p.name: p for p in interface.parameters}
    assert "use_stamped_vel" in names  # humble's alone: taken
    humble_only = {p.name for p in humble.interfaces[0].parameters} - {
        p.name for p in released_model("diff_drive_controller", "jazzy").interfaces[0].parameters}
    assert all(not names[n].required and not names[n].limits for n in humble_only)
    assert interface.distro is None and humble.interfaces[0].distro == "humble"
    assert shipped_model("diff_drive_controller", "iron") == merged


def test_a_name_renamed_between_releases_is_no_misspelling(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    """humble's progress_checker_plugin (a string) is jazzy's progress_checker_plugins (a
    string array): on jazzy it is ignored, but renaming the key would make the node throw."""
    monkeypatch.delenv("ROS_DISTRO", raising=False)
    package = tmp_path / "ws" / "nav"
    shutil.copytree(ROOT / "corpus" / "parameters" / "released_contracts" / "diffbot", package)
    config = package / "config" / "nav2_params.yaml"
    config.write_text(config.read_text().replace(
        '    controller_plugins: ["FollowPath", "FollowVendor"]',
        '    controller_plugins: ["FollowPath", "FollowVendor"]\n'
        '    progress_checker_plugin: "progress_checker"'))
    line = config.read_text().splitlines().index(
        '    progress_checker_plugin: "progress_checker"') + 1

    def at_line(*distro: str) -> list[dict[str, Any]]:
        main(["check", "--no-cache", "--format", "json", str(tmp_path / "ws"), *distro])
        return [f for f in json.loads(capsys.readouterr().out)["findings"]
                if f["file"].endswith("nav2_params.yaml") and f["line"] == line]

    (jazzy,) = at_line("--distro", "jazzy")
    assert (jazzy["code"], jazzy["severity"], jazzy["fix"]) == ("LV405", "warning", None)
    assert "the humble release declares it" in jazzy["message"]
    assert at_line("--distro", "humble") == [] and at_line() == []
