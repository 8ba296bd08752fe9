"""The command line: exit codes, output contracts, and no traceback on bad input."""

from __future__ import annotations

import gc
import json
import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from launchverify import __version__
from launchverify.cli import main

CORPUS = Path(__file__).resolve().parent.parent / "corpus"
DUPLICATE = CORPUS / "naming" / "duplicate_same_scope" / "dup.launch.xml"
CLEAN = CORPUS / "naming" / "scoped_namespaces_clean" / "robots.launch.xml"


@pytest.fixture(autouse=True)
def _no_ros(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_exit_status_reflects_errors(capsys: pytest.CaptureFixture[str]) -> None:
    assert run(capsys, "check", str(CLEAN))[0] == 0
    assert run(capsys, "check", str(DUPLICATE))[0] == 1


def test_json_contract(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "check", str(DUPLICATE), "--format", "json")
    document = json.loads(out)
    assert document["tool"] == {"name": "launchverify", "version": __version__}
    assert set(document) == {"tool", "workspace", "findings", "not_judged", "summary"}
    assert set(document["workspace"]) == {"path", "how"}
    assert DUPLICATE.is_relative_to(Path(document["workspace"]["path"]).resolve())
    assert set(document["summary"]) == {"files", "errors", "warnings", "infos", "seconds",
                                           "cached", "baselined", "not_followed"}
    # the example's nodes come from demo packages, which no underlay provides here
    assert document["summary"]["not_followed"] == {
        "includes": 0, "packages": 2, "package_names": ["demo_nodes_cpp", "demo_nodes_py"]}
    assert document["not_judged"] == []
    finding = document["findings"][0]
    assert set(finding) == {"code", "slug", "severity", "message", "file", "line", "column",
                            "end_line", "end_column", "related", "include_chain", "witness",
                            "trace", "fix", "url"}
    assert finding["code"] == "LV101" and finding["slug"] == "duplicate-node-name"
    assert finding["file"] == str(DUPLICATE)
    assert finding["line"] == 4 and finding["column"] == 3
    assert finding["related"][0]["line"] == 3
    assert finding["fix"] is None
    assert code == 1


def test_include_chain_in_json(capsys: pytest.CaptureFixture[str]) -> None:
    tree = CORPUS / "naming" / "duplicate_across_includes"
    _, out, _ = run(capsys, "check", str(tree / "bringup.launch.xml"), "--format", "json")
    finding = json.loads(out)["findings"][0]
    assert finding["file"].endswith("camera.launch.xml")
    assert [step["line"] for step in finding["include_chain"]] == [9]


def test_text_output_has_location_frame_and_summary(capsys: pytest.CaptureFixture[str]) -> None:
    _, out, _ = run(capsys, "check", str(DUPLICATE), "--color", "never")
    assert f"{DUPLICATE}:4:3: error LV101 [duplicate-node-name]" in out
    assert ' 4 |   <node pkg="demo_nodes_py"' in out
    assert "\x1b[" not in out
    assert any(line.startswith("Found 2 findings (2 errors)")
               for line in out.strip().splitlines()[-2:])


def test_select_and_ignore(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "check", str(DUPLICATE), "--ignore", "LV101", "--format", "json")
    assert code == 0 and json.loads(out)["findings"] == []
    code, out, _ = run(capsys, "check", str(DUPLICATE), "--select", "naming", "--format",
                       "json")
    assert code == 2


def test_arguments_are_pinned(capsys: pytest.CaptureFixture[str]) -> None:
    tree = CORPUS / "naming" / "node_name_from_argument" / "args.launch.xml"
    assert run(capsys, "check", str(tree))[0] == 1
    assert run(capsys, "check", str(tree), "right:=camera_right")[0] == 0


@pytest.mark.parametrize("argv", [
    ["check", "/nonexistent/file.launch.xml"],
    ["check", str(CLEAN), "broken:="],
    ["check", str(CLEAN), ":=value"],
    ["graph", str(CLEAN), str(DUPLICATE)],
    ["check", str(CLEAN), "--workspace", "/nonexistent"],
    [],
])
def test_usage_errors_exit_2_without_traceback(capsys: pytest.CaptureFixture[str],
                                                argv: list[str]) -> None:
    code, out, err = run(capsys, *argv)
    assert code == 2
    assert "Traceback" not in out + err


def test_graph_json_contract(capsys: pytest.CaptureFixture[str]) -> None:
    tree = CORPUS / "realistic" / "talker_listener_yaml_clean" / "demo.launch.yaml"
    code, out, _ = run(capsys, "graph", str(tree))
    document = json.loads(out)
    assert code == 0
    assert set(document) >= {"nodes", "processes", "includes", "arguments"}
    listener = next(n for n in document["nodes"] if n["name"] == "listener")
    assert listener["fqn"] == "/demo/listener"
    assert listener["remappings"] == [["chatter", "chatter"]]
    assert listener["parameters"] == [{"name": "verbose", "value": True},
                                      {"name": "qos.depth", "value": 10}]
    assert listener["condition"] is None and listener["lifecycle"] is False
    assert listener["line"] == 13
    code, out, _ = run(capsys, "graph", str(tree), "ns:=robot", "topic_name:=talk")
    nodes = json.loads(out)["nodes"]
    assert {n["fqn"] for n in nodes} == {"/robot/talker", "/robot/listener"}


def test_graph_symbolic_shows_conditions(capsys: pytest.CaptureFixture[str]) -> None:
    tree = CORPUS / "conditions" / "exclusive_conditions_clean" / "sim.launch.xml"
    _, out, _ = run(capsys, "graph", str(tree))
    assert len(json.loads(out)["nodes"]) == 2
    _, out, _ = run(capsys, "graph", str(tree), "--symbolic")
    nodes = json.loads(out)["nodes"]
    assert len(nodes) == 4
    assert {n["condition"] for n in nodes} >= {"$(var use_sim)", "not $(var use_sim)"}


def test_version_and_module_entry_point() -> None:
    result = subprocess.run([sys.executable, "-m", "launchverify", "--version"],
                            capture_output=True, text=True, check=False)
    assert result.returncode == 0
    assert result.stdout.strip() == f"launchverify {__version__}"


def test_the_command_flushes_everything_before_its_quick_exit(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """The command leaves without freeing its objects: what it printed must all be out."""
    nodes = "".join(f'<node pkg="demo_nodes_cpp" exec="talker" name="twin" '
                    f'namespace="/n{i // 2}"/>' for i in range(400))
    launch = tmp_path / "many.launch.xml"
    launch.write_text(f"<launch>{nodes}</launch>")
    buffered = {k: v for k, v in os.environ.items() if k != "PYTHONUNBUFFERED"}
    code, out, _ = run(capsys, "check", str(launch), "--format", "json", "--no-cache")
    done = subprocess.run([sys.executable, "-m", "launchverify", "check", str(launch),
                           "--format", "json", "--no-cache"],
                          capture_output=True, text=True, check=False, env=buffered)
    assert done.returncode == code == 1
    assert len(done.stdout) > 65536  # more than a pipe holds: written while we read
    assert _without_times(json.loads(done.stdout)) == _without_times(json.loads(out))
    code, out, _ = run(capsys, "rules")  # printed, never flushed by the command itself
    done = subprocess.run([sys.executable, "-m", "launchverify", "rules"],
                          capture_output=True, text=True, check=False, env=buffered)
    assert (done.returncode, done.stdout) == (code, out)


def test_the_collector_is_paused_for_one_shot_commands_only(
        capsys: pytest.CaptureFixture[str]) -> None:
    """The command pauses Python's cycle collector from its start; a launch run by
    ``launchverify run`` (or the language server) must collect its garbage as it goes."""
    gc.disable()
    try:
        assert main(["rules"]) == 0 and not gc.isenabled()  # as found: paused till the end
        assert main(["run", "/nonexistent/x.launch.py"]) == 2 and gc.isenabled()
    finally:
        gc.enable()
    capsys.readouterr()
    assert main(["rules"]) == 0 and gc.isenabled()  # a library caller gets it back on


@pytest.mark.parametrize(("argv", "collecting"), [(["check", "x"], False),
                                                   (["lsp"], True), (["run", "x"], True)])
def test_the_command_pauses_the_collector_from_its_start(
        argv: list[str], collecting: bool, monkeypatch: pytest.MonkeyPatch) -> None:
    import launchverify.cli
    from launchverify.process import command

    seen: list[bool] = []

    def main() -> int:  # what the collector is doing while the command runs
        seen.append(gc.isenabled())
        return 3

    monkeypatch.setattr(launchverify.cli, "main", main)
    monkeypatch.setattr(sys, "argv", ["launchverify", *argv])
    monkeypatch.setattr(command.threading, "active_count", lambda: 1)
    monkeypatch.setattr("launchverify.process.code_cache.install", lambda: None)

    def leave(status: int) -> None:
        raise SystemExit(f"left with {status}")

    monkeypatch.setattr(command.os, "_exit", leave)
    monkeypatch.setattr(sys, "gettrace", lambda: None)  # coverage would keep the usual exit
    try:
        with pytest.raises(SystemExit, match="left with 3"):
            command.run()
    finally:
        gc.enable()
    assert seen == [collecting]


def _without_times(report: dict[str, Any]) -> dict[str, Any]:
    return {**report, "summary": {k: v for k, v in report["summary"].items()
                                  if k != "seconds"}}


def test_checking_never_writes_into_the_tree(tmp_path: Path,
                                             capsys: pytest.CaptureFixture[str]) -> None:
    launch = tmp_path / "a.launch.xml"
    launch.write_text('<launch><node pkg="demo_nodes_cpp" exec="talker"/></launch>')
    before = sorted(p.name for p in tmp_path.rglob("*"))
    run(capsys, "check", str(tmp_path))
    run(capsys, "graph", str(launch))
    assert sorted(p.name for p in tmp_path.rglob("*")) == before


def test_arguments_may_follow_options(capsys: pytest.CaptureFixture[str]) -> None:
    tree = CORPUS / "naming" / "node_name_from_argument" / "args.launch.xml"
    assert run(capsys, "check", str(tree), "--format", "json", "right:=camera_right")[0] == 0
    with pytest.raises(SystemExit) as stop:
        main(["check", str(tree), "--bogus"])
    assert stop.value.code == 2


def test_command_line_argument_typo(capsys: pytest.CaptureFixture[str]) -> None:
    tree = CORPUS / "naming" / "node_name_from_argument" / "args.launch.xml"
    _code, out, _ = run(capsys, "check", str(tree), "rihgt:=camera_right", "--format", "json")
    finding = next(f for f in json.loads(out)["findings"] if f["code"] == "LV204")
    assert "rihgt:=camera_right" in finding["message"]
    assert "did you mean 'right'" in finding["message"]
    assert finding["line"] == 1


def test_graph_says_whether_the_file_is_launched_directly(tmp_path: Path,
                                                          capsys: pytest.CaptureFixture[str]
                                                          ) -> None:
    (tmp_path / "part.launch.xml").write_text('<launch><node pkg="a" exec="b" name="c"/>'
                                              "</launch>")
    (tmp_path / "top.launch.xml").write_text('<launch><include file="$(dirname)/'
                                             'part.launch.xml"/></launch>')
    assert main(["graph", str(tmp_path / "part.launch.xml")]) == 0
    view = json.loads(capsys.readouterr().out)["view"]
    assert view["launched_directly"] is False and "includes it" in view["why"]
    assert main(["graph", str(tmp_path / "top.launch.xml"), "--format", "text"]) == 0
    text = capsys.readouterr().out
    assert text.startswith("launched directly: ")
    assert "includes:\n" in text and "part.launch.xml  (" in text  # the includes too


# ---------------------------------------------------------------- issue 16: no surprises

def test_no_color_is_honoured_for_findings(capsys: pytest.CaptureFixture[str],
                                           monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("FORCE_COLOR", "1")  # as a terminal would get
    monkeypatch.delenv("NO_COLOR", raising=False)
    assert "\x1b[" in run(capsys, "check", str(DUPLICATE))[1]
    monkeypatch.setenv("NO_COLOR", "1")
    assert "\x1b[" not in run(capsys, "check", str(DUPLICATE))[1]
    assert "\x1b[" in run(capsys, "check", str(DUPLICATE), "--color", "always")[1]


def test_a_folder_without_launch_files_is_a_usage_error(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "notes.txt").write_text("nothing to launch\n")
    code, _, err = run(capsys, "check", str(tmp_path))
    assert code == 2 and f"no launch files found in {tmp_path}" in err


@pytest.mark.parametrize("option", ["-o", "--write-baseline", "--xunit-file"])
def test_output_into_a_missing_folder_is_refused_up_front(
        option: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    target = tmp_path / "missing" / "out.txt"
    code, _, err = run(capsys, "check", str(DUPLICATE), option, str(target))
    assert code == 2 and "no folder" in err and "internal error" not in err
    code, _, err = run(capsys, "report", str(DUPLICATE), "-o", str(target))
    assert code == 2 and "no folder" in err


def test_repeated_selection_flags_add_up(capsys: pytest.CaptureFixture[str]) -> None:
    tree = CORPUS / "arguments" / "unknown_include_argument"
    both = run(capsys, "check", str(tree), "--format", "json", "--select", "LV204",
               "--select", "LV101")[1]
    codes = {f["code"] for f in json.loads(both)["findings"]}
    assert codes == {"LV204"}
    dup = run(capsys, "check", str(DUPLICATE), "--format", "json", "--select", "LV204",
              "--select", "LV101")[1]
    assert {f["code"] for f in json.loads(dup)["findings"]} == {"LV101"}
    ignored = run(capsys, "check", str(DUPLICATE), "--format", "json", "--ignore", "LV204",
                  "--ignore", "LV101")[1]
    assert json.loads(ignored)["findings"] == []


def test_paths_may_follow_options(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "check", str(CLEAN), "--format", "json", str(DUPLICATE))
    document = json.loads(out)
    assert code == 1 and {Path(f["file"]).name for f in document["findings"]} == {
        DUPLICATE.name}
    assert document["summary"]["files"] == 2


def test_graph_of_a_file_that_does_not_parse_exits_1(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    broken = tmp_path / "broken.launch.xml"
    broken.write_text('<launch>\n  <node pkg="a" exec="b"\n</launch>\n')
    code, _, err = run(capsys, "graph", str(broken))
    assert code == 1 and "invalid XML" in err and "incomplete" in err
    assert run(capsys, "graph", str(CLEAN))[0] == 0


def _complete_in_bash(script: Path, words: list[str]) -> list[str]:
    """Run the bash completion function on a command line; return its candidates."""
    line = " ".join(words)
    program = (f'source "{script}"; COMP_WORDS=({line}); COMP_CWORD={len(words) - 1}; '
               '_launchverify; printf "%s\\n" "${COMPREPLY[@]}"')
    done = subprocess.run(["bash", "-c", program], capture_output=True, text=True,
                          check=True)
    return done.stdout.split()


def test_shell_completion(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "completion", "bash")
    script = tmp_path / "lv.bash"
    script.write_text(out)
    assert code == 0
    assert "check" in _complete_in_bash(script, ["launchverify", "ch"])
    assert _complete_in_bash(script, ["launchverify", "check", "--form"]) == ["--format"]
    assert "sarif" in _complete_in_bash(script, ["launchverify", "check", "--format", "s"])
    assert "LV101" in _complete_in_bash(script, ["launchverify", "check", "--select", "LV1"])
    assert "LV404" in _complete_in_bash(script, ["launchverify", "explain", "LV4"])
    code, out, _ = run(capsys, "completion", "zsh")
    assert code == 0 and "bashcompinit" in out and "--no-cache" in out
    code, out, _ = run(capsys, "completion", "fish")
    assert code == 0 and "-l no-cache" in out
    assert "-a 'text concise json sarif junit github'" in out


STDIN_CLEAN = '<launch>\n  <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>\n</launch>\n'
STDIN_DUPLICATE = ('<launch>\n  <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>\n'
                   '  <node pkg="demo_nodes_cpp" exec="listener" name="talker"/>\n</launch>\n')
STDIN_PYTHON = '''from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='talker'),
        Node(package='demo_nodes_cpp', executable='listener', name='talker'),
    ])
'''


@pytest.mark.parametrize(("name", "buffer", "line"), [
    ("robot.launch.xml", STDIN_DUPLICATE, 3), ("bringup.launch.py", STDIN_PYTHON, 8)])
def test_stdin_is_checked_as_the_named_file(name: str, buffer: str, line: int,
                                            tmp_path: Path) -> None:
    """What editors call: the unsaved buffer, checked where its file is; nothing written."""
    saved = tmp_path / name
    saved.write_text(STDIN_CLEAN if name.endswith(".xml") else
                     STDIN_PYTHON.replace("        Node(package='demo_nodes_cpp', "
                                          "executable='listener', name='talker'),\n", ""))
    before = saved.read_bytes()
    done = subprocess.run([sys.executable, "-m", "launchverify", "check", "-",
                           "--stdin-filename", str(saved), "--format", "json"],
                          input=buffer, capture_output=True, text=True, check=False)
    findings = json.loads(done.stdout)["findings"]
    assert done.returncode == 1
    assert [(f["code"], Path(f["file"]).name, f["line"]) for f in findings] == [
        ("LV101", name, line)]
    assert saved.read_bytes() == before
    on_disk = subprocess.run([sys.executable, "-m", "launchverify", "check", str(saved)],
                             capture_output=True, text=True, check=False)
    assert on_disk.returncode == 0


def test_stdin_needs_a_file_name(capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = run(capsys, "check", "-")
    assert code == 2 and "--stdin-filename" in err
    code, _, err = run(capsys, "check", str(CLEAN), "--stdin-filename", str(CLEAN))
    assert code == 2 and "goes with the path '-'" in err
