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

@pytest.fixture(autouse=True)
def _no_ros(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    monkeypatch.setenv("LAUNCHVERIFY_NO_CACHE", "1")


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


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
    assert code == 1 and (tmp_path / "-").read_text().startswith(str(DUPLICATE))


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
