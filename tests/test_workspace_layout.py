"""The workspace as users lay it out: one workspace for every path, and visible coverage.

A colcon workspace made by ``vcs import`` holds one git clone per repository under
``src/``. Checking two of them, in either order, or the whole workspace from its root,
must find the same packages and so the same findings. What was not followed (packages
found in no workspace or underlay) is said in the summary and counted in the JSON.
Everything runs through the command line, as a user types it.
"""

from __future__ import annotations

import json
import re
import subprocess
import time
from pathlib import Path
from typing import Any

import pytest

from launchverify.cli import main
from launchverify.findings import cache
from launchverify.workspace.packages import discover_workspace, sensible_workspace

MANIFEST = """<?xml version="1.0"?>
<package format="3"><name>{name}</name>{depends}
  <buildtool_depend>ament_cmake</buildtool_depend></package>
"""
# repository a: a bringup that starts a driver, and includes b's robot launch file
BRINGUP = """<launch>
  <node pkg="beta_robot" exec="driver" name="driver"/>
  <include file="$(find-pkg-share beta_robot)/launch/robot.launch.xml">
    <arg name="robot_nmae" value="alpha"/>
  </include>
</launch>
"""
# repository b: its launch file starts a node of the same name (the planted mistake, seen
# only through a's include), and declares robot_name (a's include misspells it)
ROBOT = """<launch>
  <arg name="robot_name" default="beta"/>
  <node pkg="beta_robot" exec="driver" name="driver">
    <param name="robot" value="$(var robot_name)"/>
  </node>
</launch>
"""


@pytest.fixture(autouse=True)
def _no_underlay(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    monkeypatch.delenv("ROS_DISTRO", raising=False)
    monkeypatch.delenv("LAUNCHVERIFY_PACKAGE_PATH", raising=False)


def git_init(folder: Path) -> None:
    subprocess.run(["git", "init", "-q", str(folder)], check=True)


def package(root: Path, name: str, depends: tuple[str, ...] = ()) -> Path:
    root.mkdir(parents=True, exist_ok=True)
    tags = "".join(f"\n  <exec_depend>{d}</exec_depend>" for d in depends)
    (root / "package.xml").write_text(MANIFEST.format(name=name, depends=tags))
    (root / "launch").mkdir()
    return root / "launch"


def repositories(parent: Path) -> tuple[Path, Path]:
    """Lay out two git repositories in ``parent``: a includes a launch file of b's package."""
    a, b = parent / "a", parent / "b"
    for repository in (a, b):
        repository.mkdir(parents=True)
        git_init(repository)
    launch = package(a / "alpha_bringup", "alpha_bringup", depends=("beta_robot",))
    (launch / "bringup.launch.xml").write_text(BRINGUP)
    launch = package(b / "beta_robot", "beta_robot")
    (launch / "robot.launch.xml").write_text(ROBOT)
    return a, b


@pytest.fixture
def workspace(tmp_path: Path) -> Path:
    """A colcon workspace as ``vcs import`` and a first build leave it: src/a, src/b, log/."""
    ws = tmp_path / "ws"
    repositories(ws / "src")
    (ws / "log").mkdir()
    return ws


def check(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(["check", "--no-cache", *argv])
    out, err = capsys.readouterr()
    return code, out, err


def check_json(capsys: pytest.CaptureFixture[str], *argv: str) -> dict[str, Any]:
    code, out, err = check(capsys, *argv, "--format", "json")
    assert code in (0, 1), err
    document: dict[str, Any] = json.loads(out)
    return document


def findings(document: dict[str, Any], root: Path) -> set[tuple[str, str, int, str]]:
    """Return each finding as (code, file relative to ``root``, line, message)."""
    return {(f["code"], str(Path(f["file"]).resolve().relative_to(root.resolve())),
             f["line"], f["message"]) for f in document["findings"]}


# ---------------------------------------------------------------- the first hour (C)


def test_both_path_orders_and_the_root_give_the_same_findings(
        workspace: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(workspace)
    forward = check_json(capsys, "src/a", "src/b")
    backward = check_json(capsys, "src/b", "src/a")
    whole = check_json(capsys)
    assert findings(forward, workspace) == findings(backward, workspace) \
        == findings(whole, workspace)
    codes = {code for code, *_ in findings(whole, workspace)}
    assert {"LV101", "LV204"} <= codes  # both planted mistakes, seen through the include
    for document in (forward, backward, whole):
        assert document["workspace"] == {"path": ".", "how": "colcon workspace: src/ and log/"}
        assert document["summary"]["not_followed"]["includes"] == 0


def test_from_inside_a_repository_the_workspace_is_still_the_colcon_root(
        workspace: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(workspace / "src" / "a")
    code, out, err = check(capsys, ".", "-v")
    assert code == 1
    assert out.splitlines()[0] == f"workspace: {workspace.resolve()} (colcon workspace: " \
        "src/ and log/)"
    assert "LV101" in out and "LV204" in out
    assert f"launchverify: workspace {workspace.resolve()} (colcon workspace" in err


def test_the_workspace_line_is_left_out_at_the_root_and_in_other_formats(
        workspace: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(workspace)
    _, out, err = check(capsys, "src/a")
    assert "workspace:" not in out and "workspace" not in err
    monkeypatch.chdir(workspace / "src")
    _, out, _ = check(capsys, "a", "--format", "concise")
    assert "workspace" not in out
    _, out, _ = check(capsys, "a", "-q")
    assert "workspace" not in out


def test_affected_finds_the_includer_in_the_other_repository(
        workspace: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    """pre-commit in repository b: the file a change breaks is in repository a."""
    monkeypatch.chdir(workspace / "src" / "b")
    code, out, _ = check(capsys, "--affected", "beta_robot/launch/robot.launch.xml",
                         "--format", "concise")
    assert code == 1
    assert "bringup.launch.xml" in out and "LV204" in out


# ---------------------------------------------------------------- the rules of A


@pytest.mark.parametrize("marker", ["build", "install", "log", ".colcon", "colcon.meta"])
def test_each_colcon_marker_makes_the_workspace(
        tmp_path: Path, marker: str, capsys: pytest.CaptureFixture[str]) -> None:
    ws = tmp_path / "ws"
    a, _ = repositories(ws / "src")
    if marker == "colcon.meta":
        (ws / marker).write_text("{}")
    else:
        (ws / marker).mkdir()
    document = check_json(capsys, str(a))
    assert Path(document["workspace"]["path"]).resolve() == ws.resolve()
    assert "LV204" in {code for code, *_ in findings(document, ws)}


def test_without_a_marker_the_repositories_git_roots_are_the_workspace(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """src/ without colcon's traces is no colcon workspace: each path alone is its repository."""
    ws = tmp_path / "ws"
    a, _ = repositories(ws / "src")
    document = check_json(capsys, str(a))
    assert document["workspace"]["how"] == "git root"
    assert Path(document["workspace"]["path"]).resolve() == a.resolve()


def test_paths_in_two_repositories_share_the_folder_holding_them(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """No colcon workspace: the common folder of the paths' repositories."""
    parent = tmp_path / "checkouts"
    a, b = repositories(parent)
    forward = check_json(capsys, str(a), str(b))
    backward = check_json(capsys, str(b), str(a))
    assert findings(forward, parent) == findings(backward, parent)
    assert "LV204" in {code for code, *_ in findings(forward, parent)}
    assert Path(forward["workspace"]["path"]).resolve() == parent.resolve()
    assert forward["workspace"]["how"] == "the folder holding the paths' 2 workspaces"


def test_paths_sharing_only_the_home_folder_fall_back_to_the_first_git_root(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    """A folder that holds everything (/, /home, the home folder) is no workspace: said."""
    home = tmp_path / "home"
    a, _ = repositories(home / "one")
    _, b = repositories(home / "two")
    monkeypatch.setenv("HOME", str(home))
    code, out, err = check(capsys, str(a), str(b), "--format", "json")
    document = json.loads(out)
    assert Path(document["workspace"]["path"]).resolve() == a.resolve()
    assert document["workspace"]["how"] == "the first path's git root"
    assert "note: the paths share no workspace" in err and "--workspace DIR" in err
    assert code == 0  # a's include of b's package is not followed: said, not hidden
    assert document["summary"]["not_followed"]["includes"] == 1


def test_sensible_workspaces() -> None:
    assert not sensible_workspace(Path("/"))
    assert not sensible_workspace(Path("/tmp"))
    assert not sensible_workspace(Path.home().resolve())
    assert sensible_workspace(Path.home().resolve() / "ws" / "src")


def test_a_nested_repository_that_looks_like_a_workspace_is_a_source(tmp_path: Path) -> None:
    """src/<repo>/.git with a src/ and build/ of its own: the colcon root above wins."""
    ws = tmp_path / "ws"
    repo = ws / "src" / "repo"
    (repo / "src").mkdir(parents=True)
    (repo / "build").mkdir()
    git_init(repo)
    (ws / "install").mkdir()
    assert discover_workspace([repo / "src"]).folder == ws.resolve()
    assert discover_workspace([repo]).folder == ws.resolve()


def test_a_package_with_src_and_build_is_no_workspace(tmp_path: Path) -> None:
    """A C++ package built in place (src/, build/) is not a colcon workspace."""
    ws = tmp_path / "ws"
    pkg = ws / "src" / "driver"
    (pkg / "src").mkdir(parents=True)
    (pkg / "build").mkdir()
    (pkg / "package.xml").write_text(MANIFEST.format(name="driver", depends=""))
    (ws / "build").mkdir()
    assert discover_workspace([pkg]).folder == ws.resolve()


def test_workspace_option_still_decides(
        workspace: Path, capsys: pytest.CaptureFixture[str]) -> None:
    a = workspace / "src" / "a"
    document = check_json(capsys, str(a), "--workspace", str(a))
    assert document["workspace"]["how"] == "as given"
    assert document["summary"]["not_followed"] == {
        "includes": 1, "packages": 1, "package_names": ["beta_robot"]}


def test_report_and_graph_find_the_other_repository(
        workspace: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(workspace / "src" / "a")
    bringup = "alpha_bringup/launch/bringup.launch.xml"
    assert main(["graph", bringup, "--format", "json"]) == 0
    graph = json.loads(capsys.readouterr().out)
    assert [i["status"] for i in graph["includes"]] == ["loaded"]
    code = main(["report", ".", "../b", "-o", str(workspace / "report.html")])
    _, err = capsys.readouterr()
    assert code == 1 and "wrote" in err
    assert "robot.launch.xml" in (workspace / "report.html").read_text()


# ---------------------------------------------------------------- coverage (B)


def test_the_summary_says_what_was_not_followed(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    launch = package(tmp_path / "ws" / "src" / "bringup", "bringup",
                     depends=("nav2_bringup", "ros_gz_sim", "rviz2", "slam_toolbox"))
    (tmp_path / "ws" / "log").mkdir()
    (launch / "all.launch.xml").write_text("""<launch>
  <include file="$(find-pkg-share nav2_bringup)/launch/bringup_launch.py"/>
  <include file="$(find-pkg-share nav2_bringup)/launch/rviz_launch.py"/>
  <include file="$(find-pkg-share ros_gz_sim)/launch/gz_sim.launch.py"/>
  <node pkg="rviz2" exec="rviz2"/>
  <node pkg="slam_toolbox" exec="async_slam_toolbox_node"/>
  <node pkg="slam_toolbox" exec="sync_slam_toolbox_node" name="sync_slam"/>
</launch>
""")
    monkeypatch.chdir(tmp_path / "ws")
    code, out, _ = check(capsys)
    summary, coverage = out.splitlines()[-2:]
    assert re.fullmatch(r"No findings in 1 file \(\d+\.\d\ds\)\.", summary), summary
    assert coverage == (
        "Not followed: 3 includes and 4 packages (nav2_bringup, slam_toolbox, "
        "ros_gz_sim, 1 more), found in neither the workspace nor an underlay: "
        "`source /opt/ros/<distro>/setup.bash` (then AMENT_PREFIX_PATH lists the "
        "underlay) or --package-path DIR adds them.")
    assert code == 0
    _, out, _ = check(capsys, "--distro", "jazzy")
    assert "`source /opt/ros/jazzy/setup.bash`" in out
    document = check_json(capsys)
    assert document["summary"]["not_followed"] == {
        "includes": 3, "packages": 4,
        "package_names": ["nav2_bringup", "slam_toolbox", "ros_gz_sim", "rviz2"]}
    # a sourced underlay that lacks them: only --package-path is left to say
    underlay = tmp_path / "opt" / "share" / "ament_index" / "resource_index" / "packages"
    underlay.mkdir(parents=True)
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(tmp_path / "opt"))
    _, out, _ = check(capsys)
    assert ("found in neither the workspace nor AMENT_PREFIX_PATH: --package-path DIR "
            "adds them.") in out.splitlines()[-1]


def test_a_package_path_follows_what_was_not(
        workspace: Path, capsys: pytest.CaptureFixture[str]) -> None:
    a, b = workspace / "src" / "a", workspace / "src" / "b"
    _, out, _ = check(capsys, str(a), "--workspace", str(a))
    assert "Not followed: 1 include and 1 package (beta_robot)" in out
    _, out, _ = check(capsys, str(a), "--workspace", str(a), "--package-path", str(b))
    assert "not followed" not in out and "LV204" in out


def test_a_cached_report_keeps_what_was_not_followed(
        workspace: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("LAUNCHVERIFY_NO_CACHE")
    # files written a moment before a check are kept (as in tests/test_cache.py)
    monkeypatch.setattr(cache, "CLOCK_SLACK", 0.0)
    a = workspace / "src" / "a"
    argv = ["check", str(a), "--workspace", str(a), "--cache-dir", str(workspace / "cache")]
    outputs = []
    for _ in range(2):
        main(argv)
        outputs.append("\n".join(capsys.readouterr().out.splitlines()[-2:]))
        time.sleep(0.02)  # (what the check stamped is older than the next check)
    assert "unchanged since the cached run" in outputs[1]
    assert all("Not followed: 1 include and 1 package (beta_robot)" in o for o in outputs)


def test_the_language_server_sees_the_repositories_beside_the_opened_one(
        workspace: Path) -> None:
    """An editor opened on src/a: the colcon workspace above it holds b's package."""
    from launchverify.lsp.checking import check_documents

    a = workspace / "src" / "a"
    bringup = a / "alpha_bringup" / "launch" / "bringup.launch.xml"
    checked = check_documents([bringup], {}, [a])
    assert not checked.problems
    assert {"LV101", "LV204"} <= {f.code for f in checked.findings}
