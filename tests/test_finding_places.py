"""One finding per place: a file reached by a link, an installed copy or several roots."""

from __future__ import annotations

from pathlib import Path

from launchverify.engine import CheckOptions, run_check
from launchverify.workspace.packages import PackageIndex

MANIFEST = """<?xml version="1.0"?>
<package format="3"><name>{name}</name><version>0.0.0</version><description>d</description>
<maintainer email="a@b.c">a</maintainer><license>MIT</license></package>
"""
DUPLICATE = """<launch>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>
  <node pkg="demo_nodes_cpp" exec="listener" name="talker"/>
</launch>
"""


def _package(root: Path, name: str, files: dict[str, str]) -> Path:
    folder = root / name
    (folder / "launch").mkdir(parents=True)
    (folder / "package.xml").write_text(MANIFEST.format(name=name))
    for relative, text in files.items():
        (folder / relative).write_text(text)
    return folder


def _install(root: Path, name: str, files: dict[str, str]) -> Path:
    """Install a package as colcon does (a prefix with its ament index), files copied."""
    marker = root / "install" / "share" / "ament_index" / "resource_index" / "packages" / name
    marker.parent.mkdir(parents=True, exist_ok=True)
    marker.write_text("")
    return _package(root / "install" / "share", name, files)


def _including(package: str, file: str) -> str:
    return f'<launch><include file="$(find-pkg-share {package})/launch/{file}"/></launch>\n'


def _places(workspace: Path) -> list[tuple[str, int]]:
    report = run_check(CheckOptions(paths=[workspace], workspace=workspace))
    return [(f.span.file.relative_to(workspace).as_posix(), f.span.line)
            for f in report.findings if f.code == "LV101"]


def test_a_linked_launch_file_is_reported_once_under_its_own_path(tmp_path: Path) -> None:
    # A package links another's launch file into its own launch folder, and two roots
    # include it, one through the link: the duplicate is one finding, in the real file.
    _package(tmp_path, "robot", {"launch/robot.launch.xml": DUPLICATE})
    alias = _package(tmp_path, "alias", {})
    (alias / "launch" / "robot.launch.xml").symlink_to(
        tmp_path / "robot" / "launch" / "robot.launch.xml")
    _package(tmp_path, "bringup", {"launch/a.launch.xml": _including("alias", "robot.launch.xml"),
                                   "launch/b.launch.xml": _including("robot", "robot.launch.xml")})
    assert _places(tmp_path) == [("robot/launch/robot.launch.xml", 3)]


def test_an_installed_copy_is_reported_at_its_source(tmp_path: Path) -> None:
    # An installed copy under .../share/<package> holding the source's bytes: the source is
    # the file to edit, whichever copy $(find-pkg-share) reaches.
    _package(tmp_path / "src", "robot", {"launch/robot.launch.xml": DUPLICATE})
    _install(tmp_path, "robot", {"launch/robot.launch.xml": DUPLICATE})
    _package(tmp_path / "src", "bringup",
             {"launch/a.launch.xml": _including("robot", "robot.launch.xml")})
    assert _places(tmp_path) == [("src/robot/launch/robot.launch.xml", 3)]


def test_an_installed_copy_that_differs_is_its_own_file(tmp_path: Path) -> None:
    # The twin: a stale copy is what runs, so findings stay on it.
    source = _package(tmp_path / "src", "robot", {"launch/robot.launch.xml": DUPLICATE})
    installed = _install(tmp_path, "robot", {
        "launch/robot.launch.xml": DUPLICATE, "launch/stale.launch.xml": DUPLICATE})
    (source / "launch" / "stale.launch.xml").write_text(DUPLICATE.replace("talker", "tlk"))
    index = PackageIndex([tmp_path])
    assert index.canonical(installed / "launch" / "robot.launch.xml") == (
        source / "launch" / "robot.launch.xml")
    assert index.canonical(installed / "launch" / "stale.launch.xml") == (
        installed / "launch" / "stale.launch.xml")


def test_a_node_started_twice_by_one_file_included_twice_names_the_first_include() -> None:
    """Both copies are one line: what tells them apart is the include of each."""
    tree = Path(__file__).resolve().parent.parent / "corpus" / "naming" / \
        "duplicate_across_includes"
    report = run_check(CheckOptions(paths=[tree], workspace=tree))
    [finding] = [f for f in report.findings if f.code == "LV101"]
    assert (finding.span.file.name, finding.span.line) == ("camera.launch.xml", 2)
    assert finding.message.endswith(
        "at camera.launch.xml:2 (this same node, started first through the include at "
        "bringup.launch.xml:8)")
    [related] = finding.related
    assert (related.span.file.name, related.span.line) == ("bringup.launch.xml", 8)
