"""Node interfaces read from sources: the fixture files are the test.

Each C++ or Python file under ``tests/data/topology`` marks the line of every endpoint its
code creates with ``expect: KIND NAME TYPE [param=P] [via=W] [unresolved]`` (``?`` for an
unknown name or type, several endpoints on one line separated by `` ; ``) and the line of a
default node name with ``expect-node-name: NAME``. Extraction must find exactly those.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from collections import Counter
from pathlib import Path

import pytest

from launchverify.cli import main
from launchverify.topology import files
from launchverify.topology.files import cache_stats, clear_cache, file_interfaces, language_of
from launchverify.topology.model import EndpointKind
from launchverify.topology.nodes import package_interfaces, workspace_interfaces
from launchverify.topology.sources import package_targets
from launchverify.workspace.package_executables import build_targets
from launchverify.workspace.packages import Package

DATA = Path(__file__).parent / "data" / "topology"
SOURCES = sorted(p for p in DATA.rglob("*") if p.is_file() and language_of(p))
_EXPECT = re.compile(r"(?://|#) expect: (.*)$")
_NODE_NAME = re.compile(r"expect-node-name: (\S+)")

Record = tuple[int, str, "str | None", "str | None", "str | None", "str | None", bool]


def _expected(path: Path) -> tuple[Counter[Record], set[tuple[int, str]]]:
    endpoints: Counter[Record] = Counter()
    names: set[tuple[int, str]] = set()
    for number, line in enumerate(path.read_text().splitlines(), 1):
        named = _NODE_NAME.search(line)
        if named:
            names.add((number, named.group(1)))
        marked = _EXPECT.search(line)
        if not marked:
            continue
        for part in marked.group(1).split(" ; "):
            kind, name, type_, *options = part.split()
            keys = dict(o.split("=", 1) for o in options if "=" in o)
            endpoints[(number, kind, None if name == "?" else name,
                       None if type_ == "?" else type_, keys.get("param"), keys.get("via"),
                       "unresolved" in options)] += 1
    return endpoints, names


@pytest.mark.parametrize("path", SOURCES, ids=lambda p: str(p.relative_to(DATA)))
def test_fixture_endpoints(path: Path) -> None:
    expected, expected_names = _expected(path)
    result = file_interfaces(path)
    assert result.problem is None
    found: Counter[Record] = Counter(
        (e.span.line, e.kind.value, e.name, e.type, e.name_parameter, e.via,
         e.unresolved_reason is not None) for e in result.endpoints)
    assert found == expected
    assert {(n.span.line, n.name) for n in result.node_names if n.name} == expected_names
    for endpoint in result.endpoints:
        assert (endpoint.name is None) == (endpoint.unresolved_reason is not None)
        if endpoint.name_parameter is not None:
            assert endpoint.parameter_default == endpoint.name


def test_fixtures_cover_every_kind_and_wrapper() -> None:
    endpoints = [e for p in SOURCES for e in file_interfaces(p).endpoints]
    assert {e.kind for e in endpoints} == set(EndpointKind)
    from launchverify.topology.wrappers import WRAPPERS

    libraries = {w.library for w in WRAPPERS.values()}
    assert {e.via for e in endpoints} == {None, "image_transport", "message_filters",
                                          "tf2_ros", *libraries}
    helpers = {(e.via, e.kind) for e in endpoints}
    assert all((w.library, m.kind) in helpers for w in WRAPPERS.values() for m in w.made)
    assert any(e.span.file.suffix == ".py" and e.name_parameter for e in endpoints)
    assert any(e.span.file.suffix == ".cpp" and e.unresolved_reason for e in endpoints)


def test_unresolved_names_say_why() -> None:
    result = file_interfaces(DATA / "demo_cpp" / "src" / "scan_filter.cpp")
    reasons = {e.span.line: e.unresolved_reason for e in result.endpoints if e.name is None}
    assert "prefix + \"/scan_raw\"" in reasons[38]
    assert "several values" in reasons[39]
    assert "topic_for" in reasons[40]
    assert "extra_topic" in reasons[44]


# --------------------------------------------------------------------------- sources


def _relative(paths: tuple[Path, ...], root: Path) -> list[str]:
    return sorted(str(p.relative_to(root)) for p in paths)


def test_cmake_targets_and_components_map_to_their_sources() -> None:
    root = DATA / "demo_cpp"
    targets = {t.executable: t for t in package_targets(Package("demo_cpp", source=root))}
    assert set(targets) == {"talker", "scan_filter", "fibonacci_server", "camera",
                            "stereo_sync", "broken", "relay", "demo_cpp::Ping",
                            "demo_cpp::Pong", "left_driver", "right_driver"}
    assert _relative(targets["left_driver"].sources, root) == [
        "src/drivers.cpp", "src/left_main.cpp"]
    assert _relative(targets["talker"].sources, root) == ["src/talker.cpp"]
    assert targets["relay"].component == "demo_cpp::Relay"
    assert _relative(targets["relay"].sources, root) == [
        "include/demo_cpp/relay.hpp", "src/relay.cpp"]
    assert targets["demo_cpp::Ping"].other_components == ("demo_cpp::Pong",)
    assert all(not t.problems for t in targets.values())


def test_python_entry_points_map_to_modules_and_their_imports() -> None:
    root = DATA / "demo_py"
    targets = {t.executable: t for t in package_targets(Package("demo_py", source=root))}
    assert _relative(targets["turtle_follower"].sources, root) == [
        "demo_py/follower.py", "demo_py/spawner.py"]
    assert _relative(targets["listener"].sources, root) == ["demo_py/listener.py"]
    assert targets["missing"].sources == ()
    assert targets["missing"].problems == ("module demo_py.not_there not found",)


def test_cmake_variables_directories_and_linked_libraries(tmp_path: Path) -> None:
    (tmp_path / "src" / "core").mkdir(parents=True)
    (tmp_path / "src" / "main.cpp").write_text("int main() {}\n")
    (tmp_path / "src" / "core" / "a.cpp").write_text("// a\n")
    (tmp_path / "src" / "core" / "b.cc").write_text("// b\n")
    (tmp_path / "src" / "gen.cpp").write_text("// generated\n")
    (tmp_path / "CMakeLists.txt").write_text(
        "project(tiny)\n"
        "ament_auto_add_library(core SHARED DIRECTORY src/core)\n"
        "add_executable(tool ${CMAKE_CURRENT_SOURCE_DIR}/src/main.cpp)\n"
        "target_sources(tool PRIVATE src/gen.cpp)\n"
        "target_link_libraries(tool core)\n"
        "install(TARGETS tool DESTINATION lib/${PROJECT_NAME})\n")
    built = build_targets(tmp_path, "tiny")
    assert built is not None
    assert built.sources["core"] == ("src/core/",)
    assert built.executables == frozenset({"tool"})
    [target] = package_targets(Package("tiny", source=tmp_path))
    assert _relative(target.sources, tmp_path) == [
        "src/core/a.cpp", "src/core/b.cc", "src/gen.cpp", "src/main.cpp"]



def test_a_cmake_function_with_keyword_arguments_registers_a_component(tmp_path: Path) -> None:
    # ros2/demos' demo_nodes_cpp: create_demo_library(plugin executable FILES ...) reads its
    # sources from cmake_parse_arguments' ${ARG_FILES} and registers ${plugin}
    (tmp_path / "src").mkdir()
    (tmp_path / "src" / "talker.cpp").write_text("// talker\n")
    (tmp_path / "CMakeLists.txt").write_text(
        "project(demo)\n"
        "function(create_demo_library plugin executable)\n"
        '  cmake_parse_arguments(ARG "" "" "FILES;DEPENDENCIES" ${ARGN})\n'
        "  set(library ${executable}_library)\n"
        "  add_library(${library} SHARED ${ARG_FILES})\n"
        "  rclcpp_components_register_node(${library} PLUGIN ${plugin} "
        "EXECUTABLE ${executable})\n"
        "endfunction()\n"
        'create_demo_library("demo::Talker" talker FILES src/talker.cpp '
        "DEPENDENCIES rclcpp::rclcpp)\n")
    built = build_targets(tmp_path, "demo")
    assert built is not None
    assert built.sources["talker_library"] == ("src/talker.cpp",)
    assert built.components == (("talker_library", "demo::Talker", "talker"),)


# --------------------------------------------------------------------------- interfaces


def test_components_in_one_library_keep_their_own_endpoints() -> None:
    interfaces = {i.executable: i for i in package_interfaces(
        Package("demo_cpp", source=DATA / "demo_cpp"))}
    ping, pong = interfaces["demo_cpp::Ping"], interfaces["demo_cpp::Pong"]
    assert [(e.kind.value, e.name) for e in ping.endpoints] == [("publisher", "ping")]
    assert [(e.kind.value, e.name) for e in pong.endpoints] == [("subscription", "ping")]
    assert (ping.node_name, pong.node_name) == ("ping", "pong")
    # where each constructor names its node: what LV101 points at
    assert ping.node_name_at is not None and pong.node_name_at is not None
    assert ping.node_name_at.file.name == "pair.cpp"
    assert ping.node_name_at.line != pong.node_name_at.line


def test_executables_sharing_a_library_keep_the_classes_their_main_builds() -> None:
    interfaces = {i.executable: i for i in package_interfaces(
        Package("demo_cpp", source=DATA / "demo_cpp"))}
    left = {e.name for e in interfaces["left_driver"].endpoints}
    right = {e.name for e in interfaces["right_driver"].endpoints}
    # the base class's publisher for both, a member's helper class for the left one
    assert left == {"status", "left/scan", "watchdog"}
    assert right == {"status", "right/scan"}


def test_a_header_types_the_endpoints_of_the_sources_including_it() -> None:
    interfaces = {i.executable: i for i in package_interfaces(
        Package("demo_cpp", source=DATA / "demo_cpp"))}
    relay = interfaces["relay"]
    assert relay.node_name == "relay"
    assert {(e.kind.value, e.name, e.type, e.via) for e in relay.endpoints} == {
        ("publisher", "/cmd_vel", "geometry_msgs/msg/Twist", None),
        ("subscription", "cmd_vel_in", "geometry_msgs/msg/Twist", None),
        # members declared in the header, built in relay.cpp's initialiser list
        ("subscription", "feedback", "geometry_msgs/msg/Twist", "message_filters"),
        ("publisher", "/tf_static", "tf2_msgs/msg/TFMessage", "tf2_ros"),
        # a typedef of the header names the wrapper built with new in relay.cpp
        ("subscription", "limits", "geometry_msgs/msg/Twist", "message_filters")}
    assert interfaces["broken"].problems  # parsed as far as recovered, and says so


def test_workspace_scan_finds_both_packages() -> None:
    found = {(i.package, i.executable) for i in workspace_interfaces([DATA])}
    assert ("demo_cpp", "talker") in found
    assert ("demo_py", "countdown") in found


# --------------------------------------------------------------------------- cache, bad input


def test_same_content_is_parsed_once(tmp_path: Path) -> None:
    clear_cache()
    first = tmp_path / "a.cpp"
    shutil.copy(DATA / "demo_cpp" / "src" / "talker.cpp", first)
    copy = tmp_path / "sub" / "b.cpp"
    copy.parent.mkdir()
    shutil.copy(first, copy)
    file_interfaces(first)
    again = file_interfaces(first)
    moved = file_interfaces(copy)
    assert cache_stats() == {"parsed": 1, "reused": 2}
    assert again.endpoints[0].span.file == first
    assert moved.endpoints[0].span.file == copy
    assert moved.endpoints[0].name == "chatter"
    first.write_text(first.read_text().replace('"chatter"', '"other"'))
    assert file_interfaces(first).endpoints[0].name == "other"
    assert cache_stats()["parsed"] == 2


def test_bad_input_gives_a_reason_not_a_traceback(tmp_path: Path,
                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    binary = tmp_path / "blob.cpp"
    binary.write_bytes(b"\x7fELF\0\0\x01")
    assert "binary" in (file_interfaces(binary).problem or "")
    folder = tmp_path / "folder.py"
    folder.mkdir()
    assert file_interfaces(folder).problem
    assert file_interfaces(tmp_path / "absent.cpp").problem
    monkeypatch.setattr(files, "MAX_SOURCE_BYTES", 100)
    large = tmp_path / "large.py"
    large.write_text("x = 1\n" * 100)
    assert "larger" in (file_interfaces(large).problem or "")
    monkeypatch.undo()
    nested = tmp_path / "nested.cpp"
    nested.write_text("void f() { auto p = create_publisher<a::msg::B>("
                      + "(" * 3000 + '"x"' + ")" * 3000 + ", 1); }\n")
    assert file_interfaces(nested).problem is None
    garbage = tmp_path / "garbage.py"
    garbage.write_bytes(bytes(range(1, 256)) * 20)
    assert file_interfaces(garbage).endpoints == ()


def test_a_fifo_is_not_read(tmp_path: Path) -> None:
    if not hasattr(os, "mkfifo"):
        pytest.skip("no FIFOs here")
    fifo = tmp_path / "node.cpp"
    os.mkfifo(fifo)
    assert "not a regular file" in (file_interfaces(fifo).problem or "")


# --------------------------------------------------------------------------- command line


def test_interfaces_command_json(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["interfaces", str(DATA / "demo_cpp"), "--format", "json"]) == 0
    report = json.loads(capsys.readouterr().out)
    talker = next(i for i in report["interfaces"] if i["executable"] == "talker")
    assert talker["node_name"] == "talker"
    [endpoint] = talker["endpoints"]
    assert (endpoint["kind"], endpoint["name"], endpoint["type"]) == (
        "publisher", "chatter", "std_msgs/msg/String")
    assert endpoint["line"] == 16


def test_interfaces_command_text_and_single_files(capsys: pytest.CaptureFixture[str]) -> None:
    scan = DATA / "demo_cpp" / "src" / "scan_filter.cpp"
    assert main(["interfaces", str(scan), str(DATA / "demo_py")]) == 0
    out = capsys.readouterr().out
    assert "scan  (parameter input_topic)" in out
    assert "unknown: 'twice' is assigned several values" in out
    assert "demo_py listener  node name: listener" in out
    assert main(["interfaces", str(DATA / "nowhere")]) == 2


def test_skipped_parts_are_said_once_per_file_and_only_when_asked(
        capsys: pytest.CaptureFixture[str]) -> None:
    # what the reader does not understand is no syntax error (valid C++ has macros)
    assert main(["interfaces", str(DATA / "demo_cpp")]) == 0
    out = capsys.readouterr().out
    assert "skipped" not in out and "syntax error" not in out
    assert main(["interfaces", str(DATA / "demo_cpp"), "-v"]) == 0
    notes = [line for line in capsys.readouterr().out.splitlines() if "skipped" in line]
    assert len(notes) == len(set(notes)) >= 1
    assert any("broken.cpp" in note for note in notes)


def test_check_does_not_import_tree_sitter() -> None:
    code = ("import sys\nfrom launchverify.cli import build_parser\nimport launchverify.engine\n"
            "build_parser()\n"
            "print(sorted(m for m in sys.modules if m.startswith('tree_sitter')))\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout
    assert out.strip() == "[]"


def test_controllers_are_targets_under_their_pluginlib_names() -> None:
    root = DATA / "demo_controllers"
    targets = {t.executable: t for t in package_targets(Package("demo_controllers", source=root))}
    assert set(targets) == {"demo_controllers/SpeedController",
                            "demo_controllers/LevelBroadcaster"}  # the costmap layer is not one
    speed = targets["demo_controllers/SpeedController"]
    assert speed.component == "demo_controllers::SpeedController"
    assert _relative(speed.sources, root) == ["src/level_broadcaster.cpp",
                                              "src/speed_controller.cpp"]  # no extension
    interfaces = {i.executable: i for i in package_interfaces(
        Package("demo_controllers", source=root))}
    assert [e.name for e in interfaces["demo_controllers/SpeedController"].endpoints] == [
        "~/speed"]
    assert [e.name for e in interfaces["demo_controllers/LevelBroadcaster"].endpoints] == [
        "~/level"]


def test_plugin_loaders_are_named_as_a_problem(tmp_path: Path) -> None:
    package = tmp_path / "loader_pkg"
    (package / "src").mkdir(parents=True)
    (package / "package.xml").write_text("<package format='3'><name>loader_pkg</name></package>")
    (package / "CMakeLists.txt").write_text(
        "project(loader_pkg)\nadd_executable(server src/server.cpp)\n"
        "install(TARGETS server DESTINATION lib/${PROJECT_NAME})\n")
    (package / "src" / "server.cpp").write_text(
        "class Server : public rclcpp::Node {\n"
        "  pluginlib::ClassLoader<nav2_core::Controller> loader_;\n"
        "  Server() : Node(\"server\"), loader_(\"nav2_core\", \"nav2_core::Controller\") {\n"
        "    pub_ = create_publisher<std_msgs::msg::Empty>(\"ready\", 1);\n  }\n};\n")
    (interface,) = package_interfaces(Package("loader_pkg", source=package))
    assert [e.name for e in interface.endpoints] == ["ready"]
    assert any("plugins chosen by parameters (nav2_core::Controller)" in p
               for p in interface.problems)
