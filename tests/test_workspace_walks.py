"""The workspace walks (launch files, packages, include names) read as plain walks would.

Each walk was rewritten for speed (strings instead of paths, ``scandir`` instead of
``os.walk``, a suffix search instead of a regex over every word); the straightforward
versions are kept here as their specification.
"""

from __future__ import annotations

import os
import re
from collections.abc import Iterator
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from launchverify.workspace import discover as discovering
from launchverify.workspace.discover import discover, is_launch_file
from launchverify.workspace.includers import Includers, file_names
from launchverify.workspace.packages import IGNORE_MARKERS, SKIP_DIRS, package_name, scan_sources

# a name is a run of name characters, starting where the run does, up to a file suffix
REFERENCE_NAME = re.compile(rb"(?<![\w.\-])[\w.\-]+\.(?:py|xml|yaml|yml|launch|urdf|xacro|sdf)\b")

FRAGMENTS = [b"a", b"Z", b"_", b"0", b".", b"-", b" ", b"/", b"'", b"\n", b"py", b"xml",
             b"yaml", b"yml", b"launch", b"urdf", b"xacro", b"sdf", b"pyc", b"\xc3\xa9"]


@given(st.lists(st.sampled_from(FRAGMENTS), max_size=24))
@settings(max_examples=400, deadline=None)
def test_file_names_are_the_reference_regex_names(fragments: list[bytes]) -> None:
    text = b"".join(fragments)
    assert file_names(text) == set(REFERENCE_NAME.findall(text))


@pytest.mark.parametrize(("text", "names"), [
    (b"$(find-pkg-share nav)/launch/x.launch.xml", {b"x.launch.xml"}),
    (b"os.path.join(d, 'launch', 'bringup_launch.py')", {b"bringup_launch.py"}),
    (b"a.xml.bak b.py-c.yaml", {b"a.xml", b"b.py-c.yaml"}),  # a run's last suffix wins
    (b".py.xml", {b".py.xml"}),  # the first dot starts the name: something is before the last
    (b" .py x.pyc", set()),  # nothing before the dot; no suffix at the end of the word
    (b"", set()),
])
def test_file_names(text: bytes, names: set[bytes]) -> None:
    assert file_names(text) == names


def _reference_discover(top: Path) -> list[Path]:
    found = []
    for current, dirs, files in os.walk(top):
        dirs[:] = sorted(d for d in dirs if d not in SKIP_DIRS and not d.startswith("."))
        found += [Path(current) / name for name in sorted(files)
                  if is_launch_file(Path(current) / name)]
    return found


def _tree(root: Path) -> None:
    """A workspace with the cases the walks must get right."""
    files = {
        "src/b/launch/one.launch.xml": "<launch/>",
        "src/b/launch/two_launch.py": "def generate_launch_description():\n    pass\n",
        "src/b/launch/include/part.py": "def generate_launch_description():\n    pass\n",
        "src/b/launch/helper.py": "X = 1\n",
        "src/b/launch/plain.xml": "<launch>\n</launch>\n",
        "src/b/config/not_launch.xml": "<launch/>",
        "src/b/package.xml": "<package><name>b</name></package>",
        "src/a/package.xml": "<package><name>a</name></package>",
        "src/a/launch/a.launch.yaml": "launch: []\n",
        "src/a/nested/package.xml": "<package><name>nested</name></package>",
        "src/ignored/COLCON_IGNORE": "",
        "src/ignored/package.xml": "<package><name>ignored</name></package>",
        "src/ignored/launch/i.launch.xml": "<launch/>",
        "build/x/launch/built.launch.xml": "<launch/>",
        "src/.hidden/launch/h.launch.xml": "<launch/>",
        "elsewhere/c/package.xml": "<package><name>c</name></package>",
        "elsewhere/c/launch/c.launch.xml": "<launch/>",
    }
    for relative, text in files.items():
        path = root / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    (root / "src" / "linked").symlink_to(root / "elsewhere")  # a repository linked in
    (root / "src" / "b" / "launch" / "loop").symlink_to(root / "src")  # link loops
    (root / "src" / "loop").symlink_to(root)
    (root / "src" / "b" / "launch" / "alias.launch.xml").symlink_to(
        root / "src" / "b" / "launch" / "one.launch.xml")


def test_discover_finds_what_a_plain_walk_finds(tmp_path: Path,
                                                monkeypatch: pytest.MonkeyPatch) -> None:
    _tree(tmp_path)
    expected = _reference_discover(tmp_path)
    assert discover([tmp_path]) == expected
    assert len(expected) == 9  # the cases are all there
    monkeypatch.chdir(tmp_path)  # a relative folder, given with a trailing slash
    assert discover([Path("src/")]) == _reference_discover(Path("src/"))


def test_discover_passes_over_an_unreadable_folder(tmp_path: Path,
                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    _tree(tmp_path)
    real = os.scandir

    def refusing(path: str) -> Iterator[os.DirEntry[str]]:
        if path.endswith(f"src{os.sep}a"):
            raise PermissionError(13, "denied")
        return real(path)

    monkeypatch.setattr(discovering.os, "scandir", refusing)
    assert all("/src/a/" not in str(found) for found in discover([tmp_path]))
    assert discover([tmp_path])


def _reference_sources(root: Path) -> list[tuple[str, Path]]:
    out = []
    seen = set()
    for current, dirs, files in os.walk(root, followlinks=True):
        identity = Path(current).stat()
        if (identity.st_dev, identity.st_ino) in seen:
            dirs[:] = []
            continue
        seen.add((identity.st_dev, identity.st_ino))
        if any(marker in files for marker in IGNORE_MARKERS):
            dirs[:] = []
            continue
        if "package.xml" in files:
            name = package_name(Path(current) / "package.xml")
            if name:
                out.append((name, Path(current)))
            dirs[:] = []
            continue
        dirs[:] = sorted(d for d in dirs if d not in SKIP_DIRS and not d.startswith("."))
    return out


def test_package_scan_finds_what_a_plain_walk_finds(tmp_path: Path) -> None:
    _tree(tmp_path)
    expected = _reference_sources(tmp_path)
    assert list(scan_sources(tmp_path)) == expected
    assert [name for name, _ in expected] == ["c", "a", "b"]  # each folder once


def test_includers_through_a_linked_workspace(tmp_path: Path) -> None:
    """Files are known by their resolved paths, however the workspace was named."""
    _tree(tmp_path)
    (tmp_path / "src" / "a" / "launch" / "a.launch.yaml").write_text(
        "launch:\n- include:\n    file: $(find-pkg-share b)/launch/one.launch.xml\n")
    (tmp_path.parent / f"{tmp_path.name}-link").symlink_to(tmp_path)
    includers = Includers.of_workspace([tmp_path.parent / f"{tmp_path.name}-link"])
    one = tmp_path / "src" / "b" / "launch" / "one.launch.xml"
    assert includers.included(one)
    assert includers.naming(one) == {tmp_path.resolve() / "src/a/launch/a.launch.yaml"}
    assert all(path == path.resolve() for path in includers.files)
    assert not includers.included(tmp_path / "src" / "a" / "launch" / "a.launch.yaml")


def test_real_path_is_realpath(tmp_path: Path) -> None:
    """The remembered real path reads by: the kernel's answer, links, ``..`` and all."""
    from launchverify.workspace.paths import real_path

    (tmp_path / "a" / "b").mkdir(parents=True)
    (tmp_path / "a" / "b" / "f").write_text("")
    links = {"lb": "a/b", "a/l1": "../lb/f", "l2": str(tmp_path / "a" / "l1"),
             "proc": "/proc/self", "loop1": "loop2", "loop2": "loop1",
             "up": "a/b/../../a", "certs": "/etc/ssl/certs"}
    for name, target in links.items():
        (tmp_path / name).symlink_to(target)
    for relative in ["a/b/f", "lb/f", "a/l1", "l2", "proc/environ", "loop1", "missing",
                     "lb/../a/b/f", "certs/../passwd", "./a//b/f", "lb/./f", "up/b/f",
                     "a/b/", "lb/../../x"]:
        path = f"{tmp_path}/{relative}"
        assert real_path(path) == os.path.realpath(path), relative


LINK_TARGETS = ["..", "../..", "d1", "../d2/..", "x", "../../d0/d3", "l0/..", "l1/../..",
                "../../../d1/d2", "d1/../..", "."]


@pytest.mark.skipif(not Path("/proc/self/fd").is_dir(), reason="needs /proc (Linux)")
@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 7), st.integers(0, 7), st.sampled_from(LINK_TARGETS),
                          st.booleans()), min_size=1, max_size=10))
def test_real_path_is_the_kernel_s_on_trees_of_climbing_links(
        links: list[tuple[int, int, str, bool]]) -> None:
    """Links that climb (an install folder's ``../../../src/...``), chains, loops: where
    the kernel reaches a file, ``real_path`` names the file it reaches."""
    import tempfile

    from launchverify.workspace.paths import forget_real_folders, real_path

    root = Path(tempfile.mkdtemp())
    folders = [root]
    for i in range(8):
        folders.append(folders[i // 2] / f"d{i}")
        folders[-1].mkdir()
    names = list(folders)
    for n, (where, towards, target, absolute) in enumerate(links):
        link = folders[where] / f"l{n}"
        text = str(names[towards % len(names)]) if absolute else target
        link.symlink_to(text)
        names.append(link)
    forget_real_folders()
    for name in names:
        for suffix in ("", "/..", "/../d1", "/x"):
            path = f"{name}{suffix}"
            try:
                fd = os.open(path, getattr(os, "O_PATH", os.O_RDONLY))
            except OSError:
                continue  # a loop, or nothing there: the kernel names no file
            kernel = str(Path(f"/proc/self/fd/{fd}").readlink())
            os.close(fd)
            assert real_path(path) == kernel, path


LAUNCH_MODULE = ("from launch import LaunchDescription\n\n"
                 "def generate_launch_description():\n    return LaunchDescription([])\n")


@pytest.mark.parametrize("given", [".", "./", "..", "../../launch", "launch_only"])
def test_a_folder_is_judged_by_its_real_name_whatever_the_path_given(
        given: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """``check .`` inside a ``launch`` folder finds what ``check launch`` finds above it."""
    folder = tmp_path / "pkg" / "launch"
    (folder / "launch_only").mkdir(parents=True)
    (folder / "bringup.py").write_text(LAUNCH_MODULE)  # counts only in a launch folder
    (folder / "launch_only" / "x.py").write_text(LAUNCH_MODULE)
    (tmp_path / "pkg" / "helper.py").write_text(LAUNCH_MODULE)  # not in one: never counts
    monkeypatch.chdir(folder / "launch_only" if given.startswith("..") else folder)
    if given == "launch_only":
        monkeypatch.chdir(folder)
    names = sorted(path.resolve().relative_to(tmp_path).as_posix()
                   for path in discover([Path(given)]))
    expected = ["pkg/launch/launch_only/x.py"]
    if given != "launch_only":
        expected = ["pkg/launch/bringup.py", *expected]
    assert names == expected
    above = sorted(path.relative_to(tmp_path).as_posix()
                   for path in discover([tmp_path / "pkg"]))
    assert set(names) <= set(above)


def test_a_ros2_file_named_the_roslaunch_way_is_found_a_ros1_file_is_not(
        tmp_path: Path) -> None:
    """ros_deep_learning's ``*.ros2.launch``: ROS 2 XML under roslaunch's file name."""
    launch = tmp_path / "launch"
    launch.mkdir()
    (launch / "video_viewer.ros2.launch").write_text(
        '<launch>\n  <arg name="input" default="csi://0"/>\n'
        '  <node pkg="ros_deep_learning" exec="video_source" output="screen">\n'
        '    <param name="resource" value="$(var input)"/>\n  </node>\n</launch>\n')
    (launch / "video_viewer.ros1.launch").write_text(
        '<launch>\n  <arg name="input" default="csi://0"/>\n'
        '  <node pkg="ros_deep_learning" type="video_source" name="video_source">\n'
        '    <param name="resource" value="$(arg input)"/>\n  </node>\n</launch>\n')
    (launch / "notes.launch").write_text("not XML at all, $(var x)\n")
    assert [p.name for p in discover([tmp_path])] == ["video_viewer.ros2.launch"]


@pytest.mark.parametrize(("folder", "found"), [
    ("launch", True), ("launches", True), ("bringup_launch", True), ("launch-files", True),
    ("launch/include", True), ("Launch", True),
    # a word that only begins so: a clone named launchverify, whose tests define launch files
    ("launchverify/tests", False), ("launcher", False), ("relaunchable", False)])
def test_a_launch_folder_is_one_named_for_launch_files(folder: str, found: bool,
                                                       tmp_path: Path) -> None:
    root = tmp_path / "ws"  # (pytest names tmp_path after the test: "..._launch_...")
    (root / folder).mkdir(parents=True)
    (root / folder / "start.py").write_text(LAUNCH_MODULE)
    assert bool(discover([root / folder.partition("/")[0]])) is found
