"""Worker isolation: the codec and channel between workers and launchverify, -j, LV005.

The hostile suite (test_hostile.py) attacks the whole; these pin the parts down.
"""

from __future__ import annotations

import contextlib
import gc
import io
import json
import socket
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from launchverify.engine import CheckOptions, run_check
from launchverify.frontends.python import PythonFrontend
from launchverify.ir import actions as a
from launchverify.isolation.channel import Channel, ChannelError, Closed, dumps
from launchverify.isolation.codec import MAX_DEPTH, CodecError, Decoder, Encoder
from launchverify.isolation.pool import IsolatedPython
from launchverify.problems import ProblemSink
from launchverify.render.json_out import render_json
from launchverify.workspace.packages import PackageIndex

CORPUS = Path(__file__).resolve().parent.parent / "corpus"
PYTHON_FILES = sorted(p for p in (CORPUS / "python").rglob("*.py")
                      if "endless_loop" not in str(p) and p.name.endswith("launch.py"))


def _roundtrip(value: object) -> tuple[object, object]:
    """Encode, send through JSON, decode; return both encodings (they must be equal)."""
    first = Encoder(lambda function: 0).encode(value)
    decoded = Decoder(lambda number: (lambda *args: None)).decode(json.loads(json.dumps(first)))
    second = Encoder(lambda function: 0).encode(decoded)
    return first, second


@pytest.mark.parametrize("path", PYTHON_FILES, ids=lambda p: str(p.relative_to(CORPUS)))
def test_every_corpus_description_survives_the_trip(path: Path) -> None:
    frontend = PythonFrontend(PackageIndex([path.parent]), path.parent)
    launch = frontend.load(path, ProblemSink())
    first, second = _roundtrip(launch)
    assert first == second


def test_records_shared_by_identity_stay_shared() -> None:
    from launchverify.span import Span

    span = Span(Path("/x.launch.py"), 3)
    node = a.ExecuteProcess(span=span, cmd=())
    handler = a.RegisterEventHandler(span=span, handler=a.EventHandler(
        event="process_exit", entities=(), span=span, target=node))
    launch = a.LaunchFile(path=Path("/x.launch.py"), format="python", actions=(node, handler),
                          span=span)
    data = Encoder(lambda function: 0).encode(launch)
    decoded = Decoder(lambda number: (lambda *args: None)).decode(json.loads(json.dumps(data)))
    assert isinstance(decoded, a.LaunchFile)
    first, second = decoded.actions
    assert isinstance(second, a.RegisterEventHandler) and second.handler.target is first


def test_equal_places_are_sent_once() -> None:
    """A loop's calls have equal spans (other objects): one record, then references."""
    from launchverify.span import Span

    actions = tuple(a.ExecuteProcess(span=Span(Path("/x.launch.py"), 3), cmd=())
                    for _ in range(50))
    launch = a.LaunchFile(path=Path("/x.launch.py"), format="python", actions=actions,
                          span=Span(Path("/x.launch.py"), 1))
    data = Encoder(lambda function: 0).encode(launch)
    assert json.dumps(data).count('"Span"') == 2
    first, second = _roundtrip(launch)
    assert first == second == data  # actions compare by identity: compare what is sent


SPAN = ["Span", ["#p", "/x"], 1, 1, None, None]
MALFORMED = {
    "not a record": ["Popen", "rm -rf /"],
    "a private class": ["_Worker", 1],
    "too few fields": ["Text"],
    "a number where text goes": ["Text", 5],
    "text where a substitution goes": ["LaunchConfig", "x", None],
    "a reference to nothing": ["#r", 3],
    "a reference to itself": ["Concat", ["#t", ["#r", 0]]],
    "a bool as a reference": ["#r", True],
    "an unknown tag": ["#x", 1],
    "an empty list": [],
    "a bare object": {"op": "loaded"},
    "a mapping with a number key": ["#d", 1, 2],
    "an unknown enumeration": ["#e", "Signals", 9],
    "a callback named by text": ["#f", "os.system"],
    "a span outside its type": ["Span", ["#p", "/x"], "one", 1, None, None],
    "an action without its place": ["Log", None, None, ["#d"], ["Text", "x"], "info"],
    "deeper than allowed": ["Concat", ["#t"] * 1],
}


def _deep(levels: int) -> object:
    value: object = ["Text", "x"]
    for _ in range(levels):
        value = ["Concat", ["#t", value]]
    return value


@pytest.mark.parametrize("name", sorted(MALFORMED))
def test_the_decoder_refuses_what_is_not_a_description(name: str) -> None:
    data = MALFORMED[name] if name != "deeper than allowed" else _deep(MAX_DEPTH + 5)
    with pytest.raises(CodecError):
        Decoder(lambda number: (lambda *args: None)).decode(data)


JSON = st.recursive(
    st.none() | st.booleans() | st.integers(-(2 ** 70), 2 ** 70) | st.floats()
    | st.sampled_from(["#t", "#l", "#d", "#p", "#e", "#f", "#r", "Text", "Span", "Node",
                       "LaunchFile", "Concat", "ProblemKind", "x"]),
    lambda inner: st.lists(inner, max_size=6) | st.dictionaries(st.text(max_size=3), inner,
                                                                max_size=3),
    max_leaves=30)


@settings(max_examples=300, deadline=None)
@given(JSON)
def test_the_decoder_never_fails_otherwise(data: object) -> None:
    with contextlib.suppress(CodecError):
        Decoder(lambda number: (lambda *args: None)).decode(data)


def test_huge_integers_are_refused_before_they_leave_the_worker() -> None:
    with pytest.raises(CodecError, match="bits"):
        Encoder(lambda function: 0).encode(10 ** 5000)


def test_the_channel_refuses_oversized_and_malformed_messages() -> None:
    mine, theirs = socket.socketpair()
    channel = Channel(mine.detach(), limit=1000)
    theirs.sendall(dumps({"op": "loaded", "data": "x" * 10}))
    assert channel.receive(deadline=None) == {"op": "loaded", "data": "x" * 10}
    theirs.sendall(dumps("y" * 5000))
    with pytest.raises(ChannelError):
        channel.receive(deadline=None)
    mine2, theirs2 = socket.socketpair()
    channel2 = Channel(mine2.detach())
    theirs2.sendall(b"\x00\x00\x00\x00\x00\x00\x00\x03{x}")
    with pytest.raises(ChannelError):
        channel2.receive(deadline=None)
    theirs2.close()
    with pytest.raises(Closed):
        channel2.receive(deadline=None)
    channel.close()
    channel2.close()
    theirs.close()


DUPLICATE = """<launch>
  <node pkg="demo_nodes_cpp" exec="talker" name="twin"/>
  <node pkg="demo_nodes_cpp" exec="listener" name="twin"/>
</launch>
"""


def test_a_failing_rule_is_lv005_and_the_check_goes_on(tmp_path: Path,
                                                       monkeypatch: pytest.MonkeyPatch) -> None:
    from launchverify.rules.naming.invalid_name import InvalidName

    (tmp_path / "a.launch.xml").write_text(DUPLICATE)
    (tmp_path / "b.launch.xml").write_text(DUPLICATE)

    def broken(self: object, graph: object, ctx: object) -> object:
        raise RecursionError("maximum recursion depth exceeded")

    monkeypatch.setattr(InvalidName, "check", broken)
    report = run_check(CheckOptions(paths=[tmp_path], workspace=tmp_path))
    codes = sorted((f.span.file.name, f.code) for f in report.findings)
    assert codes == [("a.launch.xml", "LV005"), ("a.launch.xml", "LV101"),
                     ("b.launch.xml", "LV005"), ("b.launch.xml", "LV101")]
    assert "rule LV102 failed" in report.findings[0].message


def test_a_failing_evaluation_is_lv005_on_its_root(tmp_path: Path,
                                                   monkeypatch: pytest.MonkeyPatch) -> None:
    from launchverify.evaluate.walker import Walker

    (tmp_path / "a.launch.xml").write_text(DUPLICATE)
    (tmp_path / "b.launch.xml").write_text(DUPLICATE)
    run = Walker.run

    def fails_on_a(self: Walker) -> None:
        if self.graph.root.name == "a.launch.xml":
            raise KeyError("boom")
        run(self)

    monkeypatch.setattr(Walker, "run", fails_on_a)
    report = run_check(CheckOptions(paths=[tmp_path], workspace=tmp_path))
    codes = sorted((f.span.file.name, f.code) for f in report.findings)
    assert ("a.launch.xml", "LV005") in codes and ("b.launch.xml", "LV101") in codes


def test_output_is_the_same_for_every_number_of_jobs() -> None:
    tree = CORPUS / "python"
    rendered = []
    for jobs in (1, 3):
        report = run_check(CheckOptions(paths=[tree], workspace=tree, jobs=jobs,
                                        exclude=["*endless_loop*"]))
        out = io.StringIO()
        render_json(report, out)
        document = json.loads(out.getvalue())
        document["summary"].pop("seconds")
        rendered.append(document)
    assert rendered[0] == rendered[1] and rendered[0]["findings"]


def test_workers_say_which_protections_hold(tmp_path: Path) -> None:
    path = tmp_path / "x.launch.py"
    path.write_text("from launch import LaunchDescription\n"
                    "def generate_launch_description():\n    return LaunchDescription([])\n")
    with IsolatedPython(PackageIndex([tmp_path]), tmp_path) as python:
        assert python.load(path, ProblemSink()) is not None
        assert python.protections is not None
        assert python.protections.startswith("active: resource limits")


PART = """\
from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction
from launch_ros.actions import Node


def setup(context):
    robot = context.launch_configurations['robot']
    return [Node(package='demo_nodes_cpp', executable='talker', name='part{n}_' + robot),
            Node(package='demo_nodes_cpp', executable='talker', name='part{n}_' + robot)]


def generate_launch_description():
    return LaunchDescription([DeclareLaunchArgument('robot', default_value='r0'),
                              OpaqueFunction(function=setup)])
"""
ALL = """\
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource


def generate_launch_description():
    here = __file__.rsplit('/', 1)[0]
    return LaunchDescription([
        IncludeLaunchDescription(PythonLaunchDescriptionSource(f'{here}/part{n}.launch.py'),
                                 launch_arguments={'robot': robot}.items())
        for robot in ('r1', 'r2') for n in range(6)])
"""


def test_recycled_workers_give_the_same_findings(tmp_path: Path,
                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    from launchverify.isolation import pool

    for n in range(6):
        (tmp_path / f"part{n}.launch.py").write_text(PART.replace("{n}", str(n)))
    (tmp_path / "all.launch.py").write_text(ALL)

    def findings() -> list[tuple[str, str, int, str]]:
        report = run_check(CheckOptions(paths=[tmp_path], workspace=tmp_path))
        return [(f.code, f.span.file.name, f.span.line, f.message) for f in report.findings]

    everyone = findings()
    monkeypatch.setattr(pool, "MAX_ALIVE", 2)  # (each file in a process of its own)
    monkeypatch.setattr(pool.IsolatedPython, "_park",
                        lambda self, worker: self._release(worker.process))
    revived = []
    revive = pool.IsolatedPython._revive

    def counted(self: pool.IsolatedPython, worker: object) -> str | None:
        revived.append(worker)
        return revive(self, worker)  # type: ignore[arg-type]

    monkeypatch.setattr(pool.IsolatedPython, "_revive", counted)
    assert findings() == everyone
    assert revived
    assert sum(code == "LV101" for code, *_ in everyone) == 6 + 12  # alone, and r1/r2


def test_a_worker_that_cannot_start_is_a_finding(tmp_path: Path,
                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    from launchverify.isolation.zygote import Zygote

    def refuse(self: Zygote, request: dict[str, object]) -> tuple[int, int]:
        raise BlockingIOError(11, "Resource temporarily unavailable")

    monkeypatch.setattr(Zygote, "spawn", refuse)
    (tmp_path / "a.launch.py").write_text("from launch import LaunchDescription\n"
                                          "def generate_launch_description():\n"
                                          "    return LaunchDescription([])\n")
    (tmp_path / "b.launch.xml").write_text(DUPLICATE)
    report = run_check(CheckOptions(paths=[tmp_path], workspace=tmp_path))
    found = sorted((f.span.file.name, f.code, f.message) for f in report.findings)
    assert found[0][:2] == ("a.launch.py", "LV002") and "no process could be started" \
        in found[0][2]
    assert found[1][:2] == ("b.launch.xml", "LV101")


def test_hundreds_of_python_files_do_not_stall_the_zygote(tmp_path: Path) -> None:
    """Each worker's end is reported; unread, the reports filled the socket after ~270
    workers and the zygote, blocked, started no more (every later file timed out)."""
    launch = tmp_path / "launch"
    launch.mkdir()
    for number in range(360):
        (launch / f"f{number}.launch.py").write_text(
            "from launch import LaunchDescription\n\n\n"
            "def generate_launch_description():\n    return LaunchDescription([])\n")
    report = run_check(CheckOptions(paths=[tmp_path], workspace=tmp_path, time_limit=2))
    assert report.python_files == 360
    assert [f.code for f in report.findings] == []


def test_the_collector_pauses_for_a_check_but_not_for_launch_files(tmp_path: Path) -> None:
    """A check pauses Python's cycle collector (its graphs live to its end) and resumes
    it; the workers running a launch file's code have it on, as that code expects."""
    (tmp_path / "gc.launch.py").write_text(
        "import gc\n\nfrom launch import LaunchDescription\nfrom launch_ros.actions import Node\n"
        "\n\ndef generate_launch_description():\n"
        "    name = 'collector_on' if gc.isenabled() else 'collector_off'\n"
        "    return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker',\n"
        "                                   name=name)])\n")
    assert gc.isenabled()
    report = run_check(CheckOptions(paths=[tmp_path], workspace=tmp_path))
    assert gc.isenabled()
    names = [node.name.describe() for graph in report.graphs for node in graph.nodes
             if node.name is not None]
    assert names == ["collector_on"]
    gc.disable()
    try:
        run_check(CheckOptions(paths=[tmp_path], workspace=tmp_path))
        assert not gc.isenabled()  # as it found it
    finally:
        gc.enable()


def test_an_enumeration_named_by_a_list_is_a_codec_error() -> None:
    # found by the property test above: the enumeration's name was looked up unhashed
    with pytest.raises(CodecError):
        Decoder(lambda number: (lambda *args: None)).decode(["#e", [], None])


TOKEN = "LV-ZYGOTE-TOKEN-93c1"
PY_TALKER = """\
from launch import LaunchDescription
from launch_ros.actions import Node

def generate_launch_description():
    return LaunchDescription([Node(package='demo_nodes_cpp', executable='talker')])
"""


def _memory_holds(pid: int, needle: bytes) -> bool | None:
    """Return whether a process's readable memory holds ``needle`` (None: cannot look)."""
    try:
        maps = Path(f"/proc/{pid}/maps").read_text().splitlines()
        memory = Path(f"/proc/{pid}/mem").open("rb")  # noqa: SIM115
    except OSError:
        return None
    with memory:
        for line in maps:
            span, perms = line.split()[:2]
            if not perms.startswith("r") or line.endswith(("[vvar]", "[vsyscall]")):
                continue
            start, end = (int(part, 16) for part in span.split("-"))
            try:
                memory.seek(start)
                if needle in memory.read(end - start):
                    return True
            except (OSError, ValueError, OverflowError):
                continue
    return False


def test_workers_never_hold_the_callers_environment(tmp_path: Path,
                                                    monkeypatch: pytest.MonkeyPatch) -> None:
    """The zygote, which every worker is forked from, is a fresh interpreter: a secret in
    launchverify's environment is neither in its environment nor anywhere in its memory."""
    from launchverify.isolation.pool import IsolatedPython
    from launchverify.problems import ProblemSink
    from launchverify.workspace.packages import PackageIndex

    monkeypatch.setenv("LV_CI_TOKEN", TOKEN)
    path = tmp_path / "talker.launch.py"
    path.write_text(PY_TALKER)
    with IsolatedPython(PackageIndex([tmp_path]), tmp_path) as python:
        assert python.load(path, ProblemSink()) is not None
        zygote = python._zygote
        assert zygote is not None
        environ = Path(f"/proc/{zygote.pid}/environ").read_bytes()
        assert TOKEN.encode() not in environ and b"LV_CI_TOKEN" not in environ
        held = _memory_holds(zygote.pid, TOKEN.encode())
        assert held is not True


def test_the_time_limit_is_for_a_files_whole_evaluation(tmp_path: Path) -> None:
    """Under a 2 s limit, OpaqueFunctions of 0.8 s and 1.2 s run; the third is not run.

    Each alone is well within the limit (a limit per request would run all three); the
    two together reach it whatever the machine's load, since the busy loops are timed by
    the clock the limit is measured with. The first leaves 1.2 s for the file's start-up
    and messages, so the second is started even on a loaded machine.
    """
    from launchverify.engine import CheckOptions, run_check

    path = tmp_path / "slow.launch.py"
    path.write_text("""\
import time
from launch import LaunchDescription
from launch.actions import OpaqueFunction
from launch_ros.actions import Node

def busy(context, name, seconds):
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        pass
    return [Node(package='demo_nodes_cpp', executable='talker', name=name)]

def generate_launch_description():
    return LaunchDescription([OpaqueFunction(function=busy, args=[n, s])
                              for n, s in (('a', 0.8), ('b', 1.2), ('c', 0.1))])
""")
    report = run_check(CheckOptions(paths=[path], workspace=tmp_path, time_limit=2.0))
    messages = [f.message for f in report.findings if f.code == "LV002"]
    assert len(messages) == 1 and "whole time limit (2 s" in messages[0], messages
    ran = {g.base(n.name) for g in report.graphs for n in g.nodes}
    assert {"a", "b"} <= ran and "c" not in ran, ran


def test_workers_may_read_launchverify_where_python_finds_it(tmp_path: Path) -> None:
    # A model may import one of launchverify's modules late, after the worker is
    # confined: the folders Python finds the packages in (a strict editable install's
    # tree of links) and the folders the links point into must both be readable.
    from launchverify.isolation.confine import readable_folders
    from launchverify.own_code import package_folders
    from launchverify.workspace.packages import PackageIndex

    readable = [Path(folder) for folder in readable_folders(PackageIndex([tmp_path]),
                                                            tmp_path)]
    for folder in package_folders():
        for path in (Path(folder), (Path(folder) / "__init__.py").resolve().parent):
            assert any(path.is_relative_to(root) for root in readable), path
