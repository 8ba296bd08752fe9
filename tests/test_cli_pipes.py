"""A reader that goes away (``launchverify ... | head``) stops the command quietly.

Each command runs as a real process whose output pipe is closed before it writes: no
message, no traceback, and exit status 141, as a shell shows for a tool SIGPIPE stopped.
"""

from __future__ import annotations

import subprocess
import sys
import threading
from pathlib import Path

import pytest

from launchverify.cli import EXIT_READER_GONE

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT / "corpus"
DUPLICATE = CORPUS / "naming" / "duplicate_same_scope" / "dup.launch.xml"
CLEAN = CORPUS / "naming" / "scoped_namespaces_clean" / "robots.launch.xml"


def closed_early(argv: list[str], closed: str = "stdout") -> tuple[int, str]:
    """Run ``launchverify argv`` with one output pipe closed at once; return status, other."""
    process = subprocess.Popen([sys.executable, "-m", "launchverify", *argv], cwd=ROOT,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    gone, kept = ((process.stdout, process.stderr) if closed == "stdout"
                  else (process.stderr, process.stdout))
    assert gone is not None and kept is not None
    gone.close()  # the reader leaves before a single byte was written
    stuck = threading.Timer(60, process.kill)  # a hang fails the test, not the suite
    stuck.start()
    try:
        other = kept.read()
        status = process.wait()
    finally:
        stuck.cancel()
    assert status != -9, "still running after 60 s: killed"
    return status, other


@pytest.mark.parametrize("argv", [
    ["check", str(DUPLICATE)],
    ["check", str(DUPLICATE), "--format", "json"],
    ["graph", str(CLEAN), "--format", "text"],
    ["rules"],
    ["explain", "LV101"],
    ["completion", "bash"],
    ["interfaces", "corpus"],
    ["run", str(CLEAN), "--dry-run"],
], ids=lambda argv: " ".join(argv[:1] + argv[2:]))
def test_a_closed_output_pipe_stops_the_command_quietly(argv: list[str]) -> None:
    status, err = closed_early([*argv, *(["--no-cache"] if argv[0] == "check" else [])])
    assert (status, err) == (EXIT_READER_GONE, "")


def test_a_closed_error_pipe_stops_report_after_the_file_is_written(tmp_path: Path) -> None:
    """``report`` writes its summary on stderr; the HTML file is written before that."""
    written = tmp_path / "report.html"
    status, out = closed_early(["report", str(DUPLICATE), "-o", str(written)],
                               closed="stderr")
    assert (status, out) == (EXIT_READER_GONE, "")
    assert "<html" in written.read_text(encoding="utf-8")


def test_a_broken_pipe_of_our_own_is_still_a_bug(monkeypatch: pytest.MonkeyPatch,
                                                 capsys: pytest.CaptureFixture[str]) -> None:
    """Only a reader of standard output or error leaving is quiet (not a worker's pipe)."""
    import launchverify.cli

    def broken(args: object) -> int:
        raise BrokenPipeError(32, "Broken pipe")

    monkeypatch.setattr(launchverify.cli, "_rules", broken)
    assert launchverify.cli.main(["rules"]) == 2
    assert "internal error: BrokenPipeError" in capsys.readouterr().err


def test_a_launch_goes_on_when_its_screen_reader_leaves(tmp_path: Path) -> None:
    """``run FILE | head``: the processes run to their end, as under ros2 launch; their
    output is in the run folder's logs (before, the launch hung on its first line)."""
    worker = CORPUS / "executor" / "nodes" / "worker.py"
    launch = tmp_path / "two.launch.xml"
    launch.write_text(f"""<launch>
  <executable cmd="{sys.executable} {worker} a --finish-after 0.2" name="a" output="screen"/>
  <executable cmd="{sys.executable} {worker} b --finish-after 0.4" name="b" output="screen"/>
</launch>
""")
    status, err = closed_early(["run", str(launch), "--log-dir", str(tmp_path)])
    assert status == 0 and "Error" not in err and "Traceback" not in err
    (run,) = tmp_path.glob("launchverify-*")
    events = [line.split()[1:3] for line in (run / "events.log").read_text().splitlines()]
    assert sorted(events) == [["exit", "a-1"], ["exit", "b-1"], ["start", "a-1"],
                              ["start", "b-1"]]
    assert "ready a" in (run / "launch.log").read_text()
