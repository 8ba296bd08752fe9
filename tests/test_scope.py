"""The same file gets the same findings whatever paths the check is given (issue 44).

A workspace of three packages: ``robot``'s ``part.launch.xml`` declares two arguments and
reads neither; ``other``'s bringup includes it and then reads one of them (the include
does not scope configurations); ``third`` includes it and reads none. The argument only
``other`` reads is used there: no check may call it unused, whichever paths it is given.
The argument nobody reads is unused everywhere: every check reaching it says so.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from launchverify.engine import CheckOptions, run_check
from launchverify.rule import Finding

MANIFEST = ('<?xml version="1.0"?>\n<package format="3"><name>{name}</name>'
            "<version>0.0.0</version><description>d</description>"
            '<maintainer email="a@b.c">a</maintainer><license>MIT</license>'
            "{depends}</package>\n")


def package(src: Path, name: str, launch: dict[str, str], depends: tuple[str, ...]) -> None:
    folder = src / name
    (folder / "launch").mkdir(parents=True)
    (folder / "package.xml").write_text(MANIFEST.format(
        name=name, depends="".join(f"<exec_depend>{d}</exec_depend>" for d in depends)))
    for file, text in launch.items():
        (folder / "launch" / file).write_text(text)


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    src = tmp_path / "src"
    package(src, "robot", {"part.launch.xml": (
        "<launch>\n"
        '  <arg name="talker_name" default="talker"/>\n'
        '  <arg name="never_read" default="x"/>\n'
        '  <node pkg="demo_nodes_cpp" exec="listener" name="listener"/>\n'
        "</launch>\n")}, ("demo_nodes_cpp",))
    package(src, "other", {"bringup.launch.xml": (
        "<launch>\n"
        '  <include file="$(find-pkg-share robot)/launch/part.launch.xml"/>\n'
        '  <node pkg="demo_nodes_cpp" exec="talker" name="$(var talker_name)"/>\n'
        '  <node pkg="demo_nodes_cpp" exec="talker" name="$(var not_declared)"/>\n'
        "</launch>\n")}, ("robot", "demo_nodes_cpp"))
    package(src, "third", {"solo.launch.xml": (
        "<launch>\n"
        '  <include file="$(find-pkg-share robot)/launch/part.launch.xml"/>\n'
        "</launch>\n")}, ("robot",))
    return tmp_path


def unused(workspace: Path, *paths: str) -> dict[str, tuple[str, ...]]:
    """Return the LV202 findings of a check of ``paths``: argument -> their notes."""
    report = run_check(CheckOptions(paths=[workspace / p for p in paths], workspace=workspace))
    return {f.message.split("'")[1]: tuple(r.message for r in f.related)
            for f in report.findings if f.code == "LV202"}


def test_an_argument_an_includer_reads_is_used_whatever_the_scope(workspace: Path) -> None:
    for scope in (("src/robot",), ("src/robot", "src/third"), ("src/third", "src/robot"),
                  ("src",)):
        found = unused(workspace, *scope)
        assert "talker_name" not in found, scope
        assert found.get("never_read") == (), scope  # inside the paths: judged by all


def test_the_including_launches_findings_stay_theirs(workspace: Path) -> None:
    """``other``'s bringup is evaluated for its context; its own LV201 is not reported."""
    report = run_check(CheckOptions(paths=[workspace / "src/robot"], workspace=workspace))
    assert not [f for f in report.findings if "bringup" in f.span.file.name]
    whole = run_check(CheckOptions(paths=[workspace / "src"], workspace=workspace))
    assert [f.code for f in whole.findings if "bringup" in f.span.file.name] == ["LV201"]
    assert [p.name for p in report.checked] == ["part.launch.xml"]


def test_a_file_outside_the_paths_is_judged_only_with_every_includer_heard(
        workspace: Path) -> None:
    """Checked through ``third`` alone, robot's file is not judged: ``other`` was not heard.

    What needs every context to agree is claimed where the check hears them all.
    """
    assert unused(workspace, "src/third") == {}
    assert "never_read" in unused(workspace, "src/third", "src/other")


CORPUS = Path(__file__).resolve().parent.parent / "corpus"
WORKSPACES = sorted(tree for tree in CORPUS.glob("*/*")
                    if tree.is_dir() and len(list(tree.rglob("package.xml"))) >= 2)


def said(findings: list[Finding]) -> set[tuple[object, ...]]:
    """Each finding's code, place and message (LV305's copy read is the paths' nearest)."""
    return {(f.code, f.span.file, f.span.line, f.message.split("; launchverify reads")[0])
            for f in findings}


@pytest.mark.parametrize("tree", WORKSPACES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_a_package_checked_alone_says_what_the_whole_workspace_says(
        tree: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The issue's test on the corpus's trees of several packages: nothing only alone."""
    from launchverify.workspace.discover import discover

    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    whole = said(run_check(CheckOptions(paths=[tree], workspace=tree)).findings)
    for manifest in sorted(tree.rglob("package.xml")):
        package = manifest.parent
        if not discover([package]):
            continue
        alone = said(run_check(CheckOptions(paths=[package], workspace=tree)).findings)
        assert alone <= whole, (package.relative_to(tree), sorted(alone - whole))


def test_the_trees_of_several_packages_are_there() -> None:
    assert len(WORKSPACES) >= 10


def test_an_includer_of_another_file_of_the_same_name_has_no_say(tmp_path: Path) -> None:
    """The includers scan goes by file name; only a launch that loads the file votes."""
    src = tmp_path / "src"
    package(src, "robot", {"robot.launch.xml": (
        "<launch>\n"
        '  <arg name="never_read" default="x"/>\n'
        '  <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>\n'
        "</launch>\n")}, ("demo_nodes_cpp",))
    package(src, "unrelated", {"top.launch.xml": (
        "<launch>\n"
        '  <include file="$(dirname)/robot.launch.xml"/>\n'
        '  <node pkg="demo_nodes_cpp" exec="talker" name="$(var not_declared)"/>\n'
        "</launch>\n"), "robot.launch.xml": (
        "<launch>\n"
        '  <node pkg="demo_nodes_cpp" exec="listener" name="$(var never_read)"/>\n'
        "</launch>\n")}, ("demo_nodes_cpp",))
    report = run_check(CheckOptions(paths=[src / "robot"], workspace=tmp_path))
    assert [(f.code, f.span.file.parent.parent.name) for f in report.findings] == [
        ("LV202", "robot")]  # unrelated's file reads a never_read of its own
    assert [p.name for p in report.checked] == ["robot.launch.xml"]
