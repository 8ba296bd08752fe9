"""One worker evaluates several Python files of a repository, and no file pays for another.

A file that crashes its worker, patches the launch API models, changes a table of
launchverify's or of a library in place, leaves a thread or a timer running, or changes a
signal handler costs only itself: the files after it are evaluated as a fresh worker
would (``isolation/reuse.py``). Each file has its own environment variables.
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import pytest

from launchverify.engine import CheckOptions, run_check
from launchverify.ir import actions as a
from launchverify.isolation.pool import IsolatedPython, _Worker
from launchverify.problems import ProblemSink
from launchverify.workspace.packages import PackageIndex

PLAIN = """\
import os, signal, threading, builtins, time
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument
from launch_ros.actions import Node


def generate_launch_description():
    description = LaunchDescription([
        DeclareLaunchArgument('robot', default_value='r1'),
        Node(package='demo_nodes_cpp', executable='talker', name='{name}')])
    {disturb}
    return description
"""
# what a file does once its description is built (a file broken by it fails alone anyway)
DISTURBING = {
    "crash": "os._exit(3)",
    "patch": "DeclareLaunchArgument.__init__ = lambda self, *a, **k: None",
    "builtins": "builtins.sorted = lambda value, **k: []",
    "thread": "threading.Thread(target=time.sleep, args=(30,), daemon=True).start()",
    "timer": "signal.setitimer(signal.ITIMER_VIRTUAL, 30)",
    "handler": "signal.signal(signal.SIGUSR1, lambda *a: None)",
    # changed in place, no name rebound: a YAML tag for the file's own loading, the
    # sandbox's state (what a hostile file would clear), a module taken away
    "yaml-tag": "import yaml.constructor as c; c.SafeConstructor.add_constructor('!x', min)",
    "sandbox-state": "import sys; "
                     "sys.modules['launchverify.frontends.python.sandbox']._armed.clear()",
    "unload": "import sys; del sys.modules['json']",
    "setting": "import sys; sys.setswitchinterval(0.5)",
}
# files after b that reuse a worker: c takes a fresh one after a disturbance; a crash
# also costs b's retry in a fresh worker, and the sandbox refuses threads (nothing is left)
REUSED = {"crash": 1, "thread": 3}


def _package(root: Path, files: dict[str, str]) -> list[Path]:
    (root / "package.xml").write_text(
        "<package format='3'><name>demo</name><version>0.0.0</version><description>d"
        "</description><maintainer email='a@b.c'>a</maintainer><license>MIT</license>"
        "</package>\n")
    (root / "launch").mkdir()
    paths = []
    for name, text in files.items():
        path = root / "launch" / f"{name}.launch.py"
        path.write_text(text)
        paths.append(path)
    return paths


def _plain(name: str, disturb: str = "pass") -> str:
    return PLAIN.format(name=name, disturb=disturb)


def _names(launch: a.LaunchFile | None) -> list[str]:
    assert launch is not None
    return [action.name.describe() for action in launch.actions  # type: ignore[attr-defined]
            if isinstance(action, a.Node) and action.name is not None]


def test_files_of_one_package_share_a_worker(tmp_path: Path) -> None:
    paths = _package(tmp_path, {f"f{n}": _plain(f"node{n}") for n in range(6)})
    with IsolatedPython(PackageIndex([tmp_path]), tmp_path, jobs=1) as python:
        python.prefetch(paths)
        names = [_names(python.load(path, ProblemSink())) for path in paths]
        assert python.reused == 5 and python.evaluated == 6
    assert names == [[f"node{n}"] for n in range(6)]


@pytest.mark.parametrize("kind", sorted(DISTURBING))
def test_a_file_that_disturbs_its_worker_costs_only_itself(kind: str, tmp_path: Path) -> None:
    paths = _package(tmp_path, {"a_first": _plain("first"), "b_disturbing":
                                _plain("disturbing", DISTURBING[kind]),
                                "c_after": _plain("after"), "d_last": _plain("last")})
    with IsolatedPython(PackageIndex([tmp_path]), tmp_path, jobs=1) as python:
        python.prefetch(paths)
        sinks = [ProblemSink() for _ in paths]
        loaded = [python.load(path, sink) for path, sink in zip(paths, sinks, strict=True)]
        assert python.reused == REUSED.get(kind, 2)
    assert _names(loaded[0]) == ["first"] and not sinks[0].problems
    assert _names(loaded[2]) == ["after"] and not sinks[2].problems, sinks[2].problems
    assert _names(loaded[3]) == ["last"] and not sinks[3].problems


def _fresh_only(self: IsolatedPython, worker: _Worker) -> None:
    """``IsolatedPython._park`` for a check where every file has a worker of its own."""
    self._release(worker.process)


def _findings(tree: Path) -> list[tuple[str, str, int, int, str]]:
    report = run_check(CheckOptions(paths=[tree], workspace=tree, jobs=2,
                                    exclude=["*endless_loop*"]))
    return sorted((f.code, str(f.span.file), f.span.line, f.span.column, f.message)
                  for f in report.findings)


def test_reuse_gives_the_findings_of_fresh_workers(tmp_path: Path,
                                                  monkeypatch: pytest.MonkeyPatch) -> None:
    files = {f"f{n}": _plain("twin" if n % 2 else f"node{n}") for n in range(6)}
    files["g"] = _plain("twin", DISTURBING["patch"])
    _package(tmp_path, files)
    reused = _findings(tmp_path)
    monkeypatch.setattr(IsolatedPython, "_park", _fresh_only)
    assert _findings(tmp_path) == reused


def test_the_python_corpus_is_judged_alike_by_reused_and_fresh_workers(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """What one evaluation leaves in a worker (the assumptions it explains) never shows."""
    tree = Path(__file__).resolve().parent.parent / "corpus" / "python"
    reused = _findings(tree)
    monkeypatch.setattr(IsolatedPython, "_park", _fresh_only)
    assert _findings(tree) == reused


OPAQUE = """\
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch_ros.actions import Node


def setup(context):  # (what a later file's patch of DeclareLaunchArgument would break)
    return [DeclareLaunchArgument('robot', default_value='r1'),
            Node(package='demo_nodes_cpp', executable='talker', name='{name}')]


def generate_launch_description():
    description = LaunchDescription([OpaqueFunction(function=setup)])
    {disturb}
    return description
"""


def _run(launch: a.LaunchFile | None) -> list[str]:
    """Run a file's OpaqueFunctions; return the node names they give."""
    assert launch is not None
    names = []
    for action in launch.actions:
        assert isinstance(action, a.OpaqueFunction)
        result = action.run({}, launch.path)
        assert not result.problems, result.problems
        names += _names(dataclasses.replace(launch, actions=result.actions))
    return names


def test_files_with_opaque_functions_share_a_worker(tmp_path: Path) -> None:
    paths = _package(tmp_path, {f"f{n}": OPAQUE.format(name=f"node{n}", disturb="pass")
                                for n in range(4)})
    with IsolatedPython(PackageIndex([tmp_path]), tmp_path, jobs=1) as python:
        python.prefetch(paths)
        loaded = [python.load(path, ProblemSink()) for path in paths]
        assert python.reused == 3
        # called after every file was taken, last file first, then again
        assert [_run(launch) for launch in reversed(loaded)] == [
            [f"node{n}"] for n in reversed(range(4))]
        assert [_run(launch) for launch in loaded] == [[f"node{n}"] for n in range(4)]
    with IsolatedPython(PackageIndex([tmp_path]), tmp_path, jobs=1) as python:
        python.prefetch(paths)  # each call waits for the next file, started meanwhile
        assert [_run(python.load(path, ProblemSink())) for path in paths] == [
            [f"node{n}"] for n in range(4)]
        assert python.reused == 3


def test_a_file_that_disturbs_the_worker_never_runs_anothers_opaque_functions(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The earlier file's OpaqueFunctions run in a fresh worker, as if alone."""
    paths = _package(tmp_path, {
        "a_first": OPAQUE.format(name="first", disturb="pass"),
        "b_patching": OPAQUE.format(name="patching", disturb=DISTURBING["patch"])})
    revived: list[Path] = []
    revive = IsolatedPython._revive

    def counted(self: IsolatedPython, worker: _Worker) -> str | None:
        revived.append(worker.path)
        return revive(self, worker)

    monkeypatch.setattr(IsolatedPython, "_revive", counted)
    with IsolatedPython(PackageIndex([tmp_path]), tmp_path, jobs=1) as python:
        python.prefetch(paths)
        first, patching = (python.load(path, ProblemSink()) for path in paths)
        assert python.reused == 1  # b was taken: a left the worker as it found it
        assert _run(first) == ["first"] and revived == [paths[0]]
        with pytest.raises(AssertionError):  # its own patch breaks its own function
            _run(patching)
        assert _run(first) == ["first"] and revived == [paths[0]]  # (once)


ENVIRONMENT = """\
import os
from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch_ros.actions import Node

BEFORE = sorted(os.environ.copy())  # the variables set so far: none, whatever came before
os.environ['ROBOT_{name}'] = '{name}'


def setup(context):
    return [Node(package='demo_nodes_cpp', executable='talker',
                 name='_'.join(['now', *sorted(os.environ.copy())]))]


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name='_'.join(['seen', *BEFORE])),
        OpaqueFunction(function=setup)])
"""


def test_each_file_has_its_own_environment_variables(tmp_path: Path) -> None:
    """As each file is its own ``ros2 launch``: what one sets, the next never reads."""
    paths = _package(tmp_path, {f"f{n}": ENVIRONMENT.format(name=n) for n in range(3)})
    with IsolatedPython(PackageIndex([tmp_path]), tmp_path, jobs=1) as python:
        python.prefetch(paths)
        loaded = [python.load(path, ProblemSink()) for path in paths]
        assert python.reused == 2
        assert [_names(launch) for launch in loaded] == [["seen"]] * 3
        called = []
        for launch in reversed(loaded):  # after every file was taken
            assert launch is not None
            [function] = [x for x in launch.actions if isinstance(x, a.OpaqueFunction)]
            result = function.run({}, launch.path)
            called.append(_names(dataclasses.replace(launch, actions=result.actions)))
    assert called == [[f"now_ROBOT_{n}"] for n in reversed(range(3))]
