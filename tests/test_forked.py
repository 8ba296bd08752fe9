"""A computation in a forked child answers as it would here, and never hangs the check."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from launchverify.engine import CheckOptions, run_check
from launchverify.parallel import forked
from launchverify.parallel.forked import Background
from launchverify.workspace.includers import Includers

CORPUS = Path(__file__).resolve().parent.parent / "corpus"


@pytest.fixture(autouse=True)
def _forking(monkeypatch: pytest.MonkeyPatch) -> None:
    """Fork even if an earlier test left a thread behind (these children take no lock)."""
    monkeypatch.setattr(forked, "can_fork", lambda: True)


def test_the_child_computes_the_answer() -> None:
    with Background(lambda: {"pid": os.getpid(), "names": frozenset({"a.launch.py"})}) as job:
        answer = job.result()
    assert answer["names"] == frozenset({"a.launch.py"})
    assert answer["pid"] != os.getpid()  # it ran in the child


def test_a_failing_child_leaves_the_computation_to_the_parent() -> None:
    calls: list[int] = []

    def compute() -> int:
        calls.append(os.getpid())
        if os.getpid() != parent:
            raise RuntimeError("only in the child")
        return 7

    parent = os.getpid()
    with Background(compute) as job:
        assert job.result() == 7
    assert calls == [parent]  # the child's call is not seen here; the parent's is


def test_an_answer_never_asked_for_ends_the_child() -> None:
    job = Background(lambda: b"x" * (1 << 20))  # more than a pipe holds: the child blocks
    assert job._child is not None
    pid = job._child[0]
    job.close()
    with pytest.raises(ChildProcessError):
        os.waitpid(pid, os.WNOHANG)  # reaped


def test_without_fork_it_runs_here(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(forked, "can_fork", lambda: False)
    job = Background(os.getpid)
    assert job.result() == os.getpid()


def test_the_forked_scan_finds_the_includers_outside_the_check(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """Checked alone, a file another file includes holds its includer's arguments."""
    included = (CORPUS / "arguments" / "includer_any_file_name" / "planner_bringup" / "launch"
                / "planner_launch.py")

    def codes() -> list[str]:
        report = run_check(CheckOptions(paths=[included], workspace=CORPUS, jobs=1))
        return [f.code for f in report.findings]

    assert codes() == []
    monkeypatch.setattr(forked, "can_fork", lambda: False)
    assert codes() == []
    monkeypatch.setattr(Includers, "of_workspace", classmethod(
        lambda cls, folders: cls([])))  # the scan sees no includer: it is a root
    assert codes() == ["LV201"]
