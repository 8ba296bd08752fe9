"""``launchverify diff``: what a change does to the launched system, on git repositories.

Each test builds a repository with a base commit, changes it (a commit, or the working
tree) and asserts the JSON: one kind of change each, as a reviewer would want it told.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
from pathlib import Path
from typing import Any

import pytest

from launchverify.cli import main

PACKAGE = ("<package format='3'><name>demo</name><version>0.0.0</version><description>d"
           "</description><maintainer email='a@b.c'>a</maintainer><license>MIT</license>"
           "</package>\n")
PARAMS = """\
/**:
  ros__parameters:
    rate: 10
    frame: base_link
"""
BRINGUP = """\
<launch>
  <arg name="use_sim" default="false"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker" if="$(var use_sim)">
    <param from="$(find-pkg-share demo)/config/params.yaml"/>
  </node>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker" unless="$(var use_sim)">
    <param from="$(find-pkg-share demo)/config/params.yaml"/>
    <remap from="chatter" to="/chat"/>
  </node>
  <node pkg="demo_nodes_cpp" exec="listener" name="listener">
    <remap from="chatter" to="/chat"/>
  </node>
</launch>
"""
SIM = """\
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('use_sim', default_value='false'),
        Node(package='demo_nodes_cpp', executable='talker', name='sim_talker'),
        # SIMULATED
    ])
"""
SIMULATED = ("Node(package='demo_nodes_cpp', executable='listener', name='sim_listener', "
             "condition=IfCondition(LaunchConfiguration('use_sim'))),")


class Repository:
    """A git repository in a folder, with a package and helpers to change it."""

    def __init__(self, root: Path) -> None:
        self.root = root
        self.git("init", "-q", "-b", "main")
        self.write("demo/package.xml", PACKAGE)
        self.write("demo/config/params.yaml", PARAMS)
        self.write("demo/launch/bringup.launch.xml", BRINGUP)
        self.write("demo/launch/sim.launch.py", SIM)
        self.commit("base")

    def git(self, *arguments: str) -> str:
        return subprocess.run(["git", "-C", str(self.root), *arguments], check=True,
                              capture_output=True, text=True,
                              env={**os.environ, "GIT_AUTHOR_NAME": "a",
                                   "GIT_AUTHOR_EMAIL": "a@b", "GIT_COMMITTER_NAME": "a",
                                   "GIT_COMMITTER_EMAIL": "a@b"}).stdout

    def write(self, name: str, text: str) -> None:
        path = self.root / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)

    def edit(self, name: str, old: str, new: str) -> None:
        text = (self.root / name).read_text()
        assert old in text, old
        self.write(name, text.replace(old, new))

    def commit(self, message: str) -> str:
        self.git("add", "-A")
        self.git("commit", "-q", "-m", message)
        return self.git("rev-parse", "HEAD").strip()


@pytest.fixture
def repo(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Repository:
    monkeypatch.chdir(tmp_path)
    return Repository(tmp_path)


def diff(capsys: pytest.CaptureFixture[str], *arguments: str,
         status: int = 0) -> dict[str, object]:
    assert main(["diff", *arguments, "--format", "json", "-j", "1"]) == status
    return json.loads(capsys.readouterr().out)


def launch(found: dict[str, object], file: str) -> dict[str, object]:
    launches = found["launches"]
    assert isinstance(launches, list)
    return next(item for item in launches if item["file"] == file)


def test_a_parameter_changed_in_an_untouched_parameter_file(
        repo: Repository, capsys: pytest.CaptureFixture[str]) -> None:
    repo.edit("demo/config/params.yaml", "rate: 10", "rate: 20")
    found = diff(capsys)
    assert found["base"] == {"label": "merge base", "commit": repo.git(
        "rev-parse", "HEAD").strip()}
    assert found["head"] == {"label": "working tree", "commit": None}
    bringup = launch(found, "demo/launch/bringup.launch.xml")
    assert bringup["parameters"] == [{
        "node": "/talker", "name": "rate",
        "base": {"value": 10, "from": "demo/config/params.yaml:3"},
        "head": {"value": 20, "from": "demo/config/params.yaml:3"}}]
    assert not any(bringup["nodes"].values())
    assert [item["file"] for item in found["launches"]] == ["demo/launch/bringup.launch.xml"]
    assert found["unchanged"] == 1


def test_a_node_renamed(repo: Repository, capsys: pytest.CaptureFixture[str]) -> None:
    repo.edit("demo/launch/bringup.launch.xml", 'name="listener"', 'name="listener_2"')
    nodes = launch(diff(capsys), "demo/launch/bringup.launch.xml")["nodes"]
    assert nodes["added"] == nodes["removed"] == []
    assert [(n["base"], n["head"]) for n in nodes["renamed"]] == [("/listener", "/listener_2")]


def test_a_remap_removed(repo: Repository, capsys: pytest.CaptureFixture[str]) -> None:
    repo.edit("demo/launch/bringup.launch.xml",
              '    <remap from="chatter" to="/chat"/>\n  </node>\n  <node pkg="demo_nodes_cpp"'
              ' exec="listener"', '  </node>\n  <node pkg="demo_nodes_cpp" exec="listener"')
    bringup = launch(diff(capsys), "demo/launch/bringup.launch.xml")
    assert [(r["node"], r["added"], r["removed"]) for r in bringup["remappings"]] == [
        ("/talker", [], ["chatter:=/chat"])]


def test_an_argument_default_changed(repo: Repository,
                                     capsys: pytest.CaptureFixture[str]) -> None:
    repo.edit("demo/launch/bringup.launch.xml", 'default="false"', 'default="true"')
    bringup = launch(diff(capsys), "demo/launch/bringup.launch.xml")
    assert [(a["name"], a["base"], a["head"]) for a in bringup["arguments"]["changed"]] == [
        ("use_sim", "false", "true")]
    # under the new default the other talker starts: the same name, another remapping
    assert [(r["node"], r["removed"]) for r in bringup["remappings"]] == [
        ("/talker", ["chatter:=/chat"])]


def test_a_node_added_only_under_an_argument(repo: Repository,
                                             capsys: pytest.CaptureFixture[str]) -> None:
    repo.edit("demo/launch/sim.launch.py", "# SIMULATED", SIMULATED)
    sim = launch(diff(capsys), "demo/launch/sim.launch.py")
    assert sim["nodes"]["added"] == []
    assert sim["conditional"] == [{"node": "/sim_listener (demo_nodes_cpp/listener)",
                                   "base": None, "head": "$(var use_sim)",
                                   "witness": {"use_sim": "true"}}]
    sim = launch(diff(capsys, "use_sim:=true"), "demo/launch/sim.launch.py")
    assert [n["fqn"] for n in sim["nodes"]["added"]] == ["/sim_listener"]
    assert sim["conditional"] == []


def test_two_commits_and_a_renamed_launch_file(repo: Repository,
                                               capsys: pytest.CaptureFixture[str]) -> None:
    base = repo.git("rev-parse", "HEAD").strip()
    repo.git("mv", "demo/launch/sim.launch.py", "demo/launch/simulation.launch.py")
    repo.edit("demo/launch/simulation.launch.py", "name='sim_talker'", "name='talker_sim'")
    head = repo.commit("rename")
    repo.edit("demo/config/params.yaml", "rate: 10", "rate: 99")  # not committed: unseen
    found = diff(capsys, base, head)
    assert found["head"] == {"label": head, "commit": head}
    moved = launch(found, "demo/launch/simulation.launch.py")
    assert moved["base_file"] == "demo/launch/sim.launch.py" and moved["status"] == "changed"
    assert [(n["base"], n["head"]) for n in moved["nodes"]["renamed"]] == [
        ("/sim_talker", "/talker_sim")]
    assert [item["file"] for item in found["launches"]] == ["demo/launch/simulation.launch.py"]
    assert repo.git("status", "--porcelain").strip() == "M demo/config/params.yaml"


def test_a_new_error_fails_and_a_change_fails_when_asked(
        repo: Repository, capsys: pytest.CaptureFixture[str]) -> None:
    repo.edit("demo/launch/bringup.launch.xml", 'name="listener"', 'name="talker"')
    found = diff(capsys, status=1)
    assert [(f["code"], f["file"]) for f in found["findings"]["introduced"]] == [
        ("LV101", "demo/launch/bringup.launch.xml")]
    assert found["summary"]["errors_introduced"] == 1
    repo.edit("demo/launch/bringup.launch.xml", 'name="talker">\n    <remap',
              'name="listener_x">\n    <remap')
    assert diff(capsys)["summary"]["errors_introduced"] == 0
    diff(capsys, "--fail-on-change", status=1)


def test_nothing_changed(repo: Repository, capsys: pytest.CaptureFixture[str]) -> None:
    found = diff(capsys, "--fail-on-change")
    assert found["launches"] == [] and found["unchanged"] == 2
    assert main(["diff", "--format", "markdown", "-j", "1"]) == 0
    assert "No change in what the 2 launch file(s) start" in capsys.readouterr().out


def test_two_folders(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                     monkeypatch: pytest.MonkeyPatch) -> None:
    for side, rate in (("old", 10), ("new", 12)):
        (tmp_path / side / "config").mkdir(parents=True)
        (tmp_path / side / "package.xml").write_text(PACKAGE)
        (tmp_path / side / "config" / "params.yaml").write_text(
            PARAMS.replace("rate: 10", f"rate: {rate}"))
        (tmp_path / side / "launch").mkdir()
        (tmp_path / side / "launch" / "bringup.launch.xml").write_text(BRINGUP)
    monkeypatch.chdir(tmp_path)
    found = diff(capsys, "new", "--against", "old")
    assert [(p["name"], p["base"]["value"], p["head"]["value"])
            for p in launch(found, "launch/bringup.launch.xml")["parameters"]] == [
        ("rate", 10, 12)]


def test_what_a_pull_request_wrote_cannot_format_the_comment_or_the_terminal(
        repo: Repository, capsys: pytest.CaptureFixture[str]) -> None:
    hostile = "x`<img src=x onerror=alert(1)>`@team\x1b]52;c;ZWNobw==\x07"
    repo.edit("demo/config/params.yaml", "frame: base_link", f"frame: {json.dumps(hostile)}")
    assert main(["diff", "--format", "markdown", "-j", "1"]) == 0
    markdown = capsys.readouterr().out
    assert "\x1b" not in markdown and "\x07" not in markdown
    line = next(text for text in markdown.splitlines() if "frame" in text)
    assert "``" in line and "<img" in line  # inside a longer fence: shown, never rendered
    assert main(["diff", "--color", "always", "-j", "1"]) == 0
    text = capsys.readouterr().out
    assert "\x1b]52" not in text and "\x07" not in text and "]52;c;" in text


def test_a_link_out_of_the_tree_in_a_revision_is_not_written(
        repo: Repository, capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    (repo.root / "demo" / "config" / "secret.yaml").symlink_to("/etc/hostname")
    repo.commit("link")
    from launchverify.diff.sides import commit_of, exported

    with exported(repo.root, commit_of(repo.root, "HEAD"), "HEAD", 10_000_000) as side:
        assert not (side.root / "demo" / "config" / "secret.yaml").exists()
        assert (side.root / "demo" / "config" / "params.yaml").is_file()
        folder = side.root
    assert not folder.exists()  # removed when the diff ends


ACTION = Path(__file__).resolve().parent.parent / "action.yml"
GH_STUB = """#!/bin/sh
# records each call; POST and PATCH fail when READ_ONLY is set (a fork's token)
printf '%s\\n' "$*" >> "$GH_CALLS"
case "$*" in
  *"-X POST"*|*"-X PATCH"*) [ -n "$READ_ONLY" ] && exit 1 ;;
esac
exit 0
"""


def _action_step(step_id: str) -> tuple[str, dict[str, str]]:
    """Return a step of the action: its script and its environment as written."""
    import yaml

    steps = yaml.safe_load(ACTION.read_text())["runs"]["steps"]
    step = next(s for s in steps if s.get("id") == step_id)
    return step["run"], step.get("env", {})


@pytest.mark.parametrize("read_only", [False, True])
def test_the_action_comments_or_falls_back_to_the_job_summary(
        repo: Repository, tmp_path_factory: pytest.TempPathFactory, read_only: bool) -> None:
    """The action's diff step, run as a runner would run it, with ``gh`` stood in for."""
    import sys

    base = repo.git("rev-parse", "HEAD").strip()
    repo.edit("demo/config/params.yaml", "rate: 10", "rate: 11")
    repo.commit("change")
    tools = tmp_path_factory.mktemp("tools")
    (tools / "gh").write_text(GH_STUB)
    (tools / "gh").chmod(0o755)
    outputs = tmp_path_factory.mktemp("runner")
    script, written = _action_step("diff")
    assert "${{" not in script  # inputs reach the script through the environment only
    env = {**os.environ, "PATH": f"{tools}:{Path(sys.executable).parent}:{os.environ['PATH']}",
           "LV_PATHS": ".", "LV_ARGUMENTS": "", "BASE_SHA": base, "PR_NUMBER": "7",
           "REPOSITORY": "owner/repo", "GH_TOKEN": "token",
           "GITHUB_OUTPUT": str(outputs / "output"),
           "GITHUB_STEP_SUMMARY": str(outputs / "summary"),
           "GH_CALLS": str(outputs / "calls"), "READ_ONLY": "1" if read_only else ""}
    assert set(written) <= set(env)
    done = subprocess.run(["bash", "--noprofile", "--norc", "-eo", "pipefail", "-c", script],
                          cwd=repo.root, env=env, capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr
    summary = (outputs / "summary").read_text()
    assert "launchverify diff" in summary and "rate 10 -> 11" in summary
    calls = (outputs / "calls").read_text()
    assert "-X POST repos/owner/repo/issues/7/comments" in calls
    assert ("job summary" in done.stdout) is read_only
    output = (outputs / "output").read_text()
    assert "errors-introduced=0" in output and "status=0" in output


def test_the_markdown_is_a_table_then_folded_details_capped(
        repo: Repository, capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    for n in range(4):
        repo.write(f"demo/launch/extra{n}.launch.xml", BRINGUP.replace(
            'name="listener"', f'name="listener{n}"'))
    repo.edit("demo/config/params.yaml", "rate: 10", "rate: 30")
    assert main(["diff", "--format", "markdown", "--max-items", "2", "-j", "1",
                 "--json", str(tmp_path / "diff.json")]) == 0
    markdown = capsys.readouterr().out
    table = markdown.index("| launch file |")
    assert table < markdown.index("<details>")
    assert markdown.count("<details>") == 2 and "…and 3 more launch files." in markdown
    assert "5 launch file(s) changed, 1 unchanged." in markdown
    written = json.loads((tmp_path / "diff.json").read_text())
    assert written["summary"]["launches_changed"] == 5


def test_a_change_read_but_for_no_node_started_is_said_apart(
        repo: Repository, capsys: pytest.CaptureFixture[str]) -> None:
    repo.edit("demo/config/params.yaml", "/**:", "other_node:\n  ros__parameters:\n"
              "    gain: 2\n/**:")
    found = diff(capsys)
    assert found["launches"] == [] and found["unchanged"] == 1
    assert found["inputs_only"] == [{"file": "demo/launch/bringup.launch.xml",
                                     "inputs_changed": ["demo/config/params.yaml"]}]
    # and the block no node loads is a finding of its own
    assert [f["code"] for f in found["findings"]["introduced"]] == ["LV402"]


def test_an_include_added(repo: Repository, capsys: pytest.CaptureFixture[str]) -> None:
    repo.edit("demo/launch/bringup.launch.xml", "</launch>",
              '  <include file="$(dirname)/sim.launch.py"/>\n</launch>')
    bringup = launch(diff(capsys), "demo/launch/bringup.launch.xml")
    assert bringup["includes"] == [{"include": "demo/launch/sim.launch.py", "base": None,
                                    "head": "loaded"}]
    assert [n["fqn"] for n in bringup["nodes"]["added"]] == ["/sim_talker"]


CHAT_NODE = """\
import rclpy
from rclpy.node import Node
from std_msgs.msg import String


class Chat(Node):
    def __init__(self):
        super().__init__('{name}')
        self.end = self.{call}


def main():
    rclpy.init()
    rclpy.spin(Chat())
"""
CHAT_LAUNCH = """\
<launch>
  <node pkg="chat" exec="talker" name="talker">
    <remap from="chatter" to="/chat"/>
  </node>
  <node pkg="chat" exec="listener" name="listener">
    <remap from="chatter" to="/chat"/>
  </node>
</launch>
"""


def test_a_topic_that_loses_its_last_publisher(
        repo: Repository, capsys: pytest.CaptureFixture[str]) -> None:
    repo.write("chat/package.xml", PACKAGE.replace("<name>demo</name>", "<name>chat</name>"))
    repo.write("chat/resource/chat", "")
    repo.write("chat/chat/__init__.py", "")
    repo.write("chat/chat/talker.py", CHAT_NODE.format(
        name="talker", call="create_publisher(String, 'chatter', 10)"))
    repo.write("chat/chat/listener.py", CHAT_NODE.format(
        name="listener", call="create_subscription(String, 'chatter', print, 10)"))
    repo.write("chat/setup.py", "from setuptools import setup\nsetup(name='chat', "
               "packages=['chat'], entry_points={'console_scripts': ["
               "'talker = chat.talker:main', 'listener = chat.listener:main']})\n")
    repo.write("chat/launch/chat.launch.xml", CHAT_LAUNCH)
    repo.commit("chat")
    repo.edit("chat/launch/chat.launch.xml", '<remap from="chatter" to="/chat"/>\n  </node>\n'
              '  <node pkg="chat" exec="listener"', '</node>\n  <node pkg="chat" '
              'exec="listener"')
    graph = launch(diff(capsys), "chat/launch/chat.launch.xml")["graph"]
    assert [(g["name"], g["change"]) for g in graph] == [
        ("topic /chat", "end lost"), ("topic /chatter", "added")]
    lost = graph[0]
    assert lost["base"] == {"type": "std_msgs/msg/String", "publishers": ["/talker"],
                            "subscribers": ["/listener"]}
    assert lost["head"]["publishers"] == []
    assert main(["diff", "-j", "1"]) == 0
    assert "topic /chat lost its last publisher ([/talker])" in capsys.readouterr().out


def test_a_head_revision_checked_out_cleanly_is_read_in_place(
        repo: Repository, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    from launchverify.diff import sides

    base = repo.git("rev-parse", "HEAD").strip()
    repo.edit("demo/config/params.yaml", "rate: 10", "rate: 12")
    head = repo.commit("change")
    exports: list[str] = []
    export = sides.exported

    def counted(repository: Path, commit: str, label: str, limit: int):  # type: ignore[no-untyped-def]
        exports.append(label)
        return export(repository, commit, label, limit)

    monkeypatch.setattr(sides, "exported", counted)
    found = diff(capsys, base, head)
    assert exports == [base] and found["head"] == {"label": head, "commit": head}
    assert found["summary"]["parameters_changed"] == 1
    repo.write("demo/launch/new.launch.xml", "<launch/>\n")  # not the commit any longer
    exports.clear()
    diff(capsys, base, head)
    assert exports == [base, head]


def test_a_node_for_other_argument_values_wired_otherwise(
        repo: Repository, capsys: pytest.CaptureFixture[str]) -> None:
    """The talker under use_sim:=true gets another parameter: said with its condition."""
    repo.edit("demo/launch/bringup.launch.xml", 'if="$(var use_sim)">\n    <param '
              'from="$(find-pkg-share demo)/config/params.yaml"/>',
              'if="$(var use_sim)">\n    <param name="rate" value="5"/>')
    conditional = launch(diff(capsys), "demo/launch/bringup.launch.xml")["conditional"]
    assert conditional == [{
        "node": "/talker (demo_nodes_cpp/talker)", "when": "$(var use_sim)",
        "witness": {"use_sim": "true"}, "parameters": {"added": ["rate := 5"],
                       "removed": ["file demo/config/params.yaml"]}}]


REWRITTEN = """\
import os
import re
from launch import LaunchDescription
from launch_ros.actions import Node
from launch_ros.descriptions import ParameterFile
from nav2_common.launch import RewrittenYaml


def generate_launch_description():
    params = os.path.join(os.path.dirname(__file__), '..', 'config', 'params.yaml')
    rewritten = ParameterFile(RewrittenYaml(source_file=params, root_key='robot1',
                                            param_rewrites={}, convert_types=True),
                              allow_substs=True)
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='talker',
             namespace='robot1', parameters=[rewritten])])
"""


def test_a_parameter_file_rewritten_before_it_is_read_counts_as_read(
        repo: Repository, capsys: pytest.CaptureFixture[str]) -> None:
    repo.write("demo/launch/robots.launch.py", REWRITTEN)
    repo.commit("robots")
    repo.edit("demo/config/params.yaml", "rate: 10", "rate: 15")
    found = diff(capsys)
    rewritten = [item for item in found["launches"] + found["inputs_only"]
                 if item["file"] == "demo/launch/robots.launch.py"]
    assert rewritten and rewritten[0]["inputs_changed"] == ["demo/config/params.yaml"]


def test_witness_assignments_compared_on_request(
        repo: Repository, capsys: pytest.CaptureFixture[str]) -> None:
    repo.edit("demo/launch/sim.launch.py", "# SIMULATED", SIMULATED)
    repo.edit("demo/config/params.yaml", "rate: 10", "rate: 12")
    found = diff(capsys, "--witnesses", "2")
    assignments = found["assignments"]
    assert [a["arguments"] for a in assignments] == [{"use_sim": "true"}]
    changed = {(launch["file"], change["change"]) for launch in assignments[0]["launches"]
               for change in launch["changes"]}
    assert ("demo/launch/sim.launch.py",
            "node /sim_listener (demo_nodes_cpp/listener)") in changed
    # the talker that runs under use_sim:=true reads the same file: its change shows there
    assert ("demo/launch/bringup.launch.xml", "/talker: rate 10 -> 12") not in changed
    assert diff(capsys)["assignments"] == []


def test_github_annotations_on_the_head_sides_lines(
        repo: Repository, capsys: pytest.CaptureFixture[str]) -> None:
    repo.edit("demo/config/params.yaml", "rate: 10", "rate: 20")
    repo.edit("demo/launch/bringup.launch.xml", 'name="listener"', 'name="talker"')
    assert main(["diff", "--format", "github", "-j", "1"]) == 1  # a new error
    lines = capsys.readouterr().out.splitlines()
    assert ("::notice file=demo/config/params.yaml,line=3,title=launchverify diff::"
            "/talker: rate 10 -> 20") in lines
    assert any(line.startswith("::error file=demo/launch/bringup.launch.xml,line=")
               and "title=LV101::new: " in line for line in lines)


def test_the_markdown_fits_in_a_comment(monkeypatch: pytest.MonkeyPatch) -> None:
    import io as text_io

    from launchverify.diff import render

    change = {"node": "/n", "name": "p", "base": {"value": 1, "from": "a.yaml:1"},
              "head": {"value": 2, "from": "a.yaml:1"}}
    empty = {"added": [], "removed": [], "renamed": []}
    launches = [{"file": f"l{n}.launch.xml", "base_file": f"l{n}.launch.xml",
                 "status": "changed", "inputs_changed": [], "nodes": empty,
                 "includes": [], "graph": [], "conditional": [],
                 "parameters": [dict(change, name=f"p{i}") for i in range(200)],
                 "parameter_files": [], "remappings": [], "executables": [],
                 "arguments": {"added": [], "removed": [], "changed": []}, "lifecycle": [],
                 "stops": {"base": False, "head": False}} for n in range(200)]
    diff = {"base": {"label": "a", "commit": None}, "head": {"label": "b", "commit": None},
            "launches": launches, "unchanged": 0, "inputs_only": [], "assignments": [],
            "findings": {"introduced": [], "fixed": []},
            "summary": {"launches_changed": 200}}
    out = text_io.StringIO()
    render.render_markdown(diff, out)
    assert len(out.getvalue()) <= render.MAX_COMMENT
    assert "more" in out.getvalue()
    monkeypatch.setattr(render, "MAX_COMMENT", 300)  # even one item each is too much
    out = text_io.StringIO()
    render.render_markdown(diff, out)
    assert len(out.getvalue()) <= 300 and out.getvalue().endswith(
        "the whole diff is in `--format json`.\n")


def test_a_revision_is_written_from_git_objects_none_linked_from_the_working_tree(
        repo: Repository) -> None:
    """A hard link would change the reviewer's file's ctime (git then rewrites the
    index); the export's files are its own, with the commit's content."""
    from launchverify.diff.sides import commit_of, exported

    base = commit_of(repo.root, "HEAD")
    repo.edit("demo/config/params.yaml", "rate: 10", "rate: 13")  # not committed
    mine = repo.root / "demo" / "launch" / "bringup.launch.xml"
    before = mine.stat()
    with exported(repo.root, base, "base", 10_000_000) as side:
        copy = side.root / "demo" / "launch" / "bringup.launch.xml"
        assert copy.read_text() == BRINGUP and copy.stat().st_ino != before.st_ino
        assert "rate: 10" in (side.root / "demo" / "config" / "params.yaml").read_text()
        assert mine.stat().st_nlink == 1
    after = mine.stat()
    assert (after.st_ino, after.st_nlink, after.st_ctime_ns) == (
        before.st_ino, before.st_nlink, before.st_ctime_ns)


def test_a_working_tree_diff_follows_committed_renames(
        repo: Repository, capsys: pytest.CaptureFixture[str]) -> None:
    base = repo.git("rev-parse", "HEAD").strip()
    repo.git("mv", "demo/launch/sim.launch.py", "demo/launch/simulation.launch.py")
    repo.commit("rename")
    repo.edit("demo/launch/simulation.launch.py", "name='sim_talker'", "name='talker_sim'")
    found = diff(capsys, base)  # the head: the working tree, one edit on the renamed file
    moved = launch(found, "demo/launch/simulation.launch.py")
    assert moved["base_file"] == "demo/launch/sim.launch.py" and moved["status"] == "changed"


def _inside(files: list[str], links: dict[str, str]) -> dict[str, str]:
    from launchverify.diff.links import inside_links

    def parts(path: str) -> tuple[str, ...]:
        return tuple(path.split("/"))

    kept = inside_links([parts(f) for f in files], {parts(k): v for k, v in links.items()})
    return {"/".join(path): target for path, target in kept.items()}


def test_links_are_judged_on_the_whole_tree() -> None:
    files = ["a/config/p.yaml", "a/launch/x.xml", "b/f"]
    links = {
        "chain/l0": "l1/..", "chain/l1": "l2/..", "chain/l2": ".",  # l0: above the top
        "in/l0": "l1/..", "in/l1": "../a/launch",  # in/l0 -> a (the linked folder's parent)
        "abs": "/etc/passwd", "up": "..", "deep": "a/../../x",
        "loop1": "loop2", "loop2": "loop1", "self": "self/x",
        "dangling": "a/none.yaml", "through_file": "b/f/..", "trailing": "b/f/",
        "empty": "", "via_out": "chain/l0/a/launch/x.xml",
        "to_file": "a/config/p.yaml", "to_top": ".", "via": "to_top/a/launch/x.xml",
        "a/launch/param": "../../in/l0/config/p.yaml",
        "a/launch/x.xml/inner": "../x.xml",  # below a file: a malformed tree
        "b": "a",  # a link that is also a folder: a malformed tree
    }
    assert _inside(files, links) == {
        "chain/l1": "l2/..", "chain/l2": ".", "in/l0": "l1/..", "in/l1": "../a/launch",
        "to_file": "a/config/p.yaml", "to_top": ".", "via": "to_top/a/launch/x.xml",
        "a/launch/param": "../../in/l0/config/p.yaml"}


def test_a_long_chain_fails_as_the_kernel_does_and_costs_its_length() -> None:
    """Past 40 links followed (the link itself counts), a walk fails as Linux's does
    (ELOOP); 20,000 links are judged at once."""
    from launchverify.diff.links import MAX_FOLLOWS

    links = {f"c{i}": f"c{i + 1}" for i in range(20_000)} | {"c20000": "f"}
    kept = _inside(["f"], links)
    assert sorted(kept, key=lambda name: int(name[1:])) == [
        f"c{i}" for i in range(20_001 - MAX_FOLLOWS, 20_001)]


REMAPS = """\
<launch>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker">
    <remap from="chatter" to="/chat"/>
    <remap from="chatter" to="/chat_b"/>
    <remap from="other" to="/chat"/>
  </node>
</launch>
"""


def _sides(root: Path, base: str, head: str) -> None:
    """Write two folders, ``old`` and ``new``, each a package with one launch file."""
    for side, text in (("old", base), ("new", head)):
        (root / side / "launch").mkdir(parents=True)
        (root / side / "package.xml").write_text(PACKAGE)
        (root / side / "launch" / "bringup.launch.xml").write_text(text)


def test_a_finding_whose_message_changed_is_changed_not_introduced_and_fixed(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    # the first rule for chatter now names /chat2: line 4's remap still never applies
    # (its message names the new winner), line 5's no longer merges two names
    _sides(tmp_path, REMAPS, REMAPS.replace('to="/chat"/>\n    <remap from="chatter"',
                                            'to="/chat2"/>\n    <remap from="chatter"'))
    monkeypatch.chdir(tmp_path)
    found: Any = diff(capsys, "new", "--against", "old")
    findings = found["findings"]
    assert findings["introduced"] == []  # was: 1 introduced, 2 fixed
    assert [(f["code"], f["line"]) for f in findings["fixed"]] == [("LV103", 5)]
    [changed] = findings["changed"]
    assert (changed["code"], changed["line"], changed["base"]["line"]) == ("LV103", 4, 4)
    assert changed["message"].endswith("already remapped to /chat2 (the first rule wins)")
    assert changed["base"]["message"].endswith("already remapped to /chat (the first rule "
                                               "wins)")
    assert (found["summary"]["findings_introduced"], found["summary"]["findings_fixed"],
            found["summary"]["findings_changed"]) == (0, 1, 1)
    assert main(["diff", "new", "--against", "old", "-j", "1"]) == 0
    text = capsys.readouterr().out
    assert "findings: 0 introduced, 1 fixed, 1 changed" in text
    assert re.search(r"~ warning LV103 launch/bringup\.launch\.xml:4 remap chatter -> "
                     r"/chat_b never applies: .*/chat2 .*\(was: remap chatter -> /chat_b "
                     r"never applies: .*/chat \(the first rule wins\)\)", text), text


def test_an_edited_line_that_keeps_its_mistake_is_neither(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    # line 5's text changes (an attribute added), its finding and message stay
    _sides(tmp_path, REMAPS, REMAPS.replace('<remap from="other" to="/chat"/>',
                                            '<remap from="other" to="/chat" />'))
    monkeypatch.chdir(tmp_path)
    findings = diff(capsys, "new", "--against", "old")["findings"]
    assert findings == {"introduced": [], "fixed": [], "changed": []}


def test_markdown_cuts_a_long_message_at_a_word_with_an_ellipsis(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    long = "/the_planner_output_topic_with_rather_long_name"  # 120 characters: in "(the"
    _sides(tmp_path, "<launch/>\n", REMAPS.replace("/chat_b", long))
    monkeypatch.chdir(tmp_path)
    found: Any = diff(capsys, "new", "--against", "old")
    messages = [f["message"] for f in found["findings"]["introduced"]]
    message = next(m for m in messages if long in m)
    assert len(message) > 120
    assert main(["diff", "new", "--against", "old", "--format", "markdown", "-j", "1"]) == 0
    line = next(text for text in capsys.readouterr().out.splitlines()
                if text.startswith("- ") and "never applies" in text)
    shown = line.rsplit(" `", 1)[1].rstrip("`")
    assert shown.endswith("…") and len(shown) <= 120, shown
    kept = shown[:-1]
    assert message.startswith(kept) and message[len(kept)] in " ,;:", (kept, message)
