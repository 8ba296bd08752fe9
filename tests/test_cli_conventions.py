"""The command line behaves as users expect of one (issue 44, items 3 to 7).

A file given by name is read for what it is (a parameter file through the launch files
that load it; anything else is a usage error); Ctrl-C exits 130 with nothing
half-written; ``-o -`` is standard output; ``--affected`` shows paths as every other
check does; ``run``'s own messages keep their line breaks while what they quote of the
checked files stays inert.
"""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from launchverify.cli import main

ROOT = Path(__file__).resolve().parent.parent
DUPLICATE = ROOT / "corpus" / "naming" / "duplicate_same_scope" / "dup.launch.xml"
PACKAGE_XML = ('<?xml version="1.0"?>\n<package format="3">\n  <name>{name}</name>\n'
               "  <version>0.0.1</version>\n  <description>d</description>\n"
               '  <maintainer email="a@b.c">a</maintainer>\n  <license>MIT</license>\n'
               "  <export><build_type>ament_cmake</build_type></export>\n</package>\n")


@pytest.fixture(autouse=True)
def _no_ros(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    monkeypatch.setenv("LAUNCHVERIFY_NO_CACHE", "1")


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def _workspace(root: Path) -> Path:
    """Write a colcon workspace (``src/``, ``build/``, one git repository): its root.

    ``robot_bringup`` has a launch file loading ``config/controllers.yaml``, whose list
    mixes types (LV401), a README, a C++ source and a parameter file no launch file loads.
    """
    package = root / "src" / "robot_bringup"
    for folder in ("launch", "config", "src"):
        (package / folder).mkdir(parents=True)
    (root / "build").mkdir()
    (package / "package.xml").write_text(PACKAGE_XML.format(name="robot_bringup"))
    (package / "launch" / "control.launch.xml").write_text(
        '<launch>\n  <node pkg="demo_nodes_cpp" exec="talker" name="controller_manager">\n'
        '    <param from="$(find-pkg-share robot_bringup)/config/controllers.yaml"/>\n'
        "  </node>\n</launch>\n")
    (package / "config" / "controllers.yaml").write_text(
        "controller_manager:\n  ros__parameters:\n    update_rate: 100\n"
        "    gains: [1.0, 0]\n")
    (package / "config" / "unused.yaml").write_text(
        "nobody:\n  ros__parameters:\n    rate: 1.0\n")
    (package / "config" / "notes.yaml").write_text("- a list, not parameters\n")
    (package / "README.md").write_text("# robot_bringup\n\nusage: ros2 launch ...\n")
    (package / "src" / "talker.cpp").write_text("int main() { return 0; }\n")
    subprocess.run(["git", "init", "--quiet", str(root)], check=True)
    return root


# 3. a file given by name is read for what it is


def test_a_parameter_file_given_by_name_is_checked_through_its_launch_files(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(_workspace(tmp_path / "ws"))
    code, out, err = run(capsys, "check", "src/robot_bringup/config/controllers.yaml")
    assert code == 1, err
    assert "src/robot_bringup/config/controllers.yaml:4:" in out
    assert "LV401" in out and "LV001" not in out, out


@pytest.mark.parametrize("name", ["README.md", "src/talker.cpp", "config/notes.yaml",
                                  "package.xml"])
def test_a_file_that_is_not_for_launchverify_is_a_usage_error(
        name: str, tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(_workspace(tmp_path / "ws") / "src" / "robot_bringup")
    code, out, err = run(capsys, "check", name)
    assert code == 2 and out == ""
    assert f"'{name}' is neither a launch file nor a parameter file" in err
    assert "*.launch.py" in err and "parameter files" in err
    assert "LV001" not in err and "Traceback" not in err


def test_a_parameter_file_no_launch_file_loads_is_said(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(_workspace(tmp_path / "ws"))
    code, _, err = run(capsys, "check", "src/robot_bringup/config/unused.yaml")
    assert code == 2
    assert "no launch file of the workspace loads" in err and "unused.yaml" in err


def test_files_a_folder_walk_finds_are_judged_as_before(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(_workspace(tmp_path / "ws"))
    code, out, err = run(capsys, "check", "src")  # a README, C++, YAML notes below
    assert code == 1, err
    assert "LV401" in out and "LV001" not in out and "neither" not in err


# 4. Ctrl-C


def test_ctrl_c_exits_130_and_writes_nothing(tmp_path: Path) -> None:
    launch = tmp_path / "slow.launch.py"
    launch.write_text("def generate_launch_description():\n    while True:\n        pass\n")
    output = tmp_path / "report.txt"
    # a terminal's Ctrl-C goes to the whole foreground process group
    process = subprocess.Popen(
        [sys.executable, "-m", "launchverify", "check", str(launch), "--time-limit", "60",
         "--no-cache", "-o", str(output)], cwd=tmp_path, start_new_session=True,
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(3)  # the evaluation is under way
    os.killpg(process.pid, signal.SIGINT)
    out, err = process.communicate(timeout=60)
    assert process.returncode == 130, err
    assert "Traceback" not in err and out == ""
    assert sorted(path.name for path in tmp_path.iterdir()) == ["slow.launch.py"]


def test_ctrl_c_while_writing_leaves_the_old_output_whole(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    output = tmp_path / "findings.json"
    output.write_text("the last run's\n")

    def interrupted(descriptor: int) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(os, "fsync", interrupted)  # the data written, not yet in place
    code, out, err = run(capsys, "check", str(DUPLICATE), "--format", "json", "-o",
                         str(output))
    assert code == 130 and out == "" and err == ""
    assert output.read_text() == "the last run's\n"
    assert sorted(path.name for path in tmp_path.iterdir()) == ["findings.json"]


# 5. -o - is standard output


def test_output_dash_is_standard_output(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    code, out, _ = run(capsys, "check", str(DUPLICATE), "-o", "-", "--format", "concise")
    assert code == 1 and "LV101" in out
    code, out, err = run(capsys, "report", str(DUPLICATE), "-o", "-")
    assert code == 1 and out.lstrip().lower().startswith("<!doctype html")
    assert "standard output" in err
    other = tmp_path / "other.launch.xml"
    other.write_text('<launch><node pkg="demo_nodes_cpp" exec="talker"/></launch>\n')
    code, out, _ = run(capsys, "diff", "--against", str(other), str(DUPLICATE), "-o", "-",
                       "--format", "json")
    assert code in (0, 1) and out.startswith("{")
    assert list(tmp_path.iterdir()) == [other]  # no file named '-'
    code, _, _ = run(capsys, "check", str(DUPLICATE), "-o", "./-")  # one named so
    written = (tmp_path / "-").read_text().splitlines()
    assert code == 1 and any(line.startswith(str(DUPLICATE)) for line in written)


# 6. --affected shows paths as every other check does


@pytest.mark.parametrize("argv", [
    ["check", "--affected", "src/robot_bringup/config/controllers.yaml"],
    ["check", "--affected", "--", "src/robot_bringup/config/controllers.yaml"],  # the hook
])
def test_affected_paths_are_relative_to_the_current_folder(
        argv: list[str], tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    workspace = _workspace(tmp_path / "ws")
    launch = workspace / "src" / "robot_bringup" / "launch" / "control.launch.xml"
    launch.write_text(launch.read_text().replace("</launch>",
                                                 '  <node pkg="demo_nodes_cpp" exec="talker"'
                                                 ' name="controller_manager"/>\n</launch>'))
    monkeypatch.chdir(workspace)
    code, out, _ = run(capsys, *argv)
    assert code == 1
    assert "src/robot_bringup/launch/control.launch.xml:5:" in out  # LV101, found by name
    assert "src/robot_bringup/config/controllers.yaml:4:" in out
    assert str(workspace) not in out, out


# 7. run's own text keeps its line breaks; what it quotes stays inert


def test_run_cannot_start_message_is_lines_with_inert_names(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    launch = tmp_path / "missing.launch.yaml"
    launch.write_text('launch:\n- node: {pkg: demo_nodes_cpp, exec: "tal\\eker", name: a}\n'
                      "- node: {pkg: demo_nodes_cpp, exec: listener, name: b}\n")
    code, _, err = run(capsys, "run", str(launch), "--log-dir", str(tmp_path / "logs"))
    assert code == 2
    assert "launchverify: error: cannot start:\n  missing.launch.yaml:2: executable " in err
    assert "\n  missing.launch.yaml:3: executable 'listener'" in err
    assert "\\x0a" not in err
    assert "'tal\\x1bker'" in err and "\x1b" not in err  # the file's text, inert
