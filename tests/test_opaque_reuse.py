"""An OpaqueFunction's result is reused between roots only where a run would give it again.

Roots that include the same Python file mostly pass its OpaqueFunctions the same values;
``FileCache.opaque_result`` hands a later root the earlier result when every configuration
the body read has the same value and the current file is the same. A check gives the same
findings and graphs with reuse as without it.
"""

from __future__ import annotations

import tempfile
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from launchverify.engine import CheckOptions, run_check
from launchverify.evaluate import files
from launchverify.evaluate.files import FileCache
from launchverify.ir import actions as a
from launchverify.problems import Problem, ProblemKind
from launchverify.span import Span
from launchverify.workspace.packages import PackageIndex

HERE = Span(Path("/w/body.launch.py"), 3)


class Body:
    """An OpaqueFunction's body that reads ``robot`` and counts its runs."""

    def __init__(self, **result: Any) -> None:
        self.runs = 0
        self.result = result

    def __call__(self, configurations: Mapping[str, Any], current: Path) -> a.OpaqueResult:
        self.runs += 1
        found = "robot" in configurations
        return a.OpaqueResult(actions=(), reads=(("robot", found, False),), **self.result)


def _run(cache: FileCache, action: a.OpaqueFunction, root: int, robot: str | None = "r1",
         current: str = "/w/body.launch.py") -> a.OpaqueResult:
    configurations = {"other": str(root)} if robot is None else {"robot": robot,
                                                                  "other": str(root)}
    return cache.opaque_result(action, configurations, Path(current), root)


def _action(body: Body) -> a.OpaqueFunction:
    return a.OpaqueFunction(span=HERE, condition=None, description="setup", run=body)


@pytest.fixture
def cache(tmp_path: Path) -> FileCache:
    return FileCache(PackageIndex(), tmp_path, python=object())  # type: ignore[arg-type]


def test_another_root_with_the_same_values_gets_the_same_result(cache: FileCache) -> None:
    body = Body()
    action = _action(body)
    first = _run(cache, action, root=1)
    assert _run(cache, action, root=2) is first  # "other" differs: the body never read it
    assert body.runs == 1
    assert _run(cache, action, root=3, robot="r2") is not first  # what it read differs
    assert _run(cache, action, root=4, robot=None) is not first  # unset is a value too
    assert _run(cache, action, root=5, current="/w/other.launch.py") is not first
    assert body.runs == 4


def test_a_root_never_gets_one_result_twice(cache: FileCache) -> None:
    """Launch runs an object once: a body run again makes new actions."""
    body = Body()
    action = _action(body)
    _run(cache, action, root=1)
    _run(cache, action, root=1)
    assert body.runs == 2
    _run(cache, action, root=2)
    _run(cache, action, root=2)  # one result each from root 1's two runs
    _run(cache, action, root=2)
    assert body.runs == 3


@pytest.mark.parametrize("result", [
    {"problems": (Problem(ProblemKind.UNMODELED, "a file only the robot has", HERE),)},
    {"reads_all": True},
])
def test_results_that_may_not_repeat_are_not_reused(cache: FileCache,
                                                    result: dict[str, Any]) -> None:
    body = Body(**result)
    action = _action(body)
    _run(cache, action, root=1)
    _run(cache, action, root=2)
    assert body.runs == 2


def test_reading_the_configurations_as_a_whole_is_noticed() -> None:
    from launchverify.models.launch_api.context import RecordingDict

    for read in (dict, list, len, str, lambda d: {**d}, lambda d: sorted(d.items()),
                 lambda d: d == {}, lambda d: d.copy()):
        configurations = RecordingDict({"robot": "r1"})
        read(configurations)
        assert configurations.whole, read
    configurations = RecordingDict({"robot": "r1"})
    _ = configurations["robot"], configurations.get("x"), "y" in configurations
    assert not configurations.whole
    assert [name for name, *_ in configurations.read] == ["robot", "x", "y"]


BODY = """
import os
import tempfile

from launch import LaunchDescription
from launch.actions import DeclareLaunchArgument, OpaqueFunction, RegisterEventHandler
from launch.event_handlers import OnShutdown
from launch.substitutions import LaunchConfiguration
from launch_ros.actions import Node


def setup(context):
    robot = LaunchConfiguration('robot').perform(context)
    return [Node(package='demo_nodes_cpp', executable='talker', name='talker',
                 namespace=robot)]


def everything(context):
    return [Node(package='demo_nodes_cpp', executable='listener',
                 name='listener_' + str(len(context.launch_configurations)))]


WORLD = tempfile.mktemp(suffix='.sdf')  # a process of the launch would write it


def cleanup(context):
    os.path.getsize(WORLD)  # a last look at what the run wrote


def generate_launch_description():
    return LaunchDescription([
        DeclareLaunchArgument('robot', default_value='r0'),
        OpaqueFunction(function=setup),
        OpaqueFunction(function=everything),
        RegisterEventHandler(OnShutdown(on_shutdown=[OpaqueFunction(function=cleanup)])),
    ])
"""


def _root(robots: list[str]) -> str:
    includes = "".join(
        f'<group><push-ros-namespace namespace="g{i}"/>'
        f'<include file="$(dirname)/body.launch.py"><arg name="robot" value="{robot}"/>'
        "</include></group>" for i, robot in enumerate(robots))
    return f'<launch><arg name="unused_{len(robots)}" default="x"/>{includes}</launch>'


def _check(tree: Path) -> tuple[list[tuple[object, ...]], list[list[str]], list[bool],
                               list[bool]]:
    report = run_check(CheckOptions(paths=[tree], workspace=tree))
    found = [(f.code, f.span.file.name, f.span.line, f.message, f.chain)
             for f in report.findings]
    nodes = [sorted(str(n.fqn.describe()) for n in g.nodes if n.fqn is not None)
             for g in report.graphs]
    told = [any("temporary file" in p.problem.message for p in g.problems)
            for g in report.graphs]  # each root's run says what it met
    return found, nodes, [g.complete for g in report.graphs], told


def test_a_check_gives_the_same_with_and_without_reuse(tmp_path: Path,
                                                       monkeypatch: pytest.MonkeyPatch) -> None:
    (tmp_path / "body.launch.py").write_text(BODY)
    for name, robots in {"a": ["r1"], "b": ["r1"], "c": ["r2", "r2"], "d": ["r1", "r3"]}.items():
        (tmp_path / f"{name}.launch.xml").write_text(_root(robots))
    runs: list[str] = []
    original = a.OpaqueFunction.__init__

    def counted(self: a.OpaqueFunction, **fields: Any) -> None:
        run = fields["run"]

        def counting(configurations: Mapping[str, Any], current: Path) -> a.OpaqueResult:
            runs.append(fields["description"])
            return run(configurations, current)

        original(self, **{**fields, "run": counting})

    monkeypatch.setattr(a.OpaqueFunction, "__init__", counted)
    reused = _check(tmp_path)
    with_reuse = len(runs)
    monkeypatch.setattr(files, "MAX_OPAQUE_RUNS", 0)
    runs.clear()
    assert _check(tmp_path) == reused
    assert with_reuse < len(runs)
    found, _, complete, told = reused
    assert all(told)
    assert all(complete)  # the body failing at shutdown leaves every evaluation complete
    assert any(code == "LV003" and "temporary file" in str(message)
               for code, _, _, message, _ in found)


NAMES = ("a", "b", "c")
reads = st.lists(st.sampled_from(["get", "item", "perform", "in", "whole"]),
                 min_size=1, max_size=2)
bodies = st.lists(st.tuples(st.frozensets(st.sampled_from(NAMES), min_size=1), reads,
                            st.booleans()), min_size=1, max_size=3)
roots = st.lists(st.lists(st.dictionaries(st.sampled_from(NAMES), st.sampled_from("xyz")),
                          min_size=1, max_size=2), min_size=2, max_size=4)


def _generated_body(functions: list[tuple[frozenset[str], list[str], bool]]) -> str:
    """Bodies that read some configurations in various ways; some raise on a value."""
    lines = ["from launch import LaunchDescription",
             "from launch.actions import DeclareLaunchArgument, OpaqueFunction",
             "from launch.substitutions import LaunchConfiguration",
             "from launch_ros.actions import Node", ""]
    for index, (names, ways, raises) in enumerate(functions):
        lines.append(f"def body{index}(context):")
        lines.append("    seen = []")
        for name in sorted(names):
            for way in ways:
                lines.append({
                    "get": f"    seen.append(context.launch_configurations.get('{name}', '-'))",
                    "item": f"    seen.append(context.launch_configurations['{name}'])",
                    "perform": f"    seen.append(LaunchConfiguration('{name}').perform(context))",
                    "in": f"    seen.append(str('{name}' in context.launch_configurations))",
                    "whole": "    seen.append(str(len(context.launch_configurations)))",
                }[way])
        if raises:
            lines.append("    if 'z' in seen:\n        raise ValueError('z is not a value')")
        lines.append(f"    return [Node(package='p', executable='e', name='n{index}_' + "
                     "'_'.join(s.replace('/', '') for s in seen))]")
        lines.append("")
    lines.append("def generate_launch_description():")
    lines.append("    return LaunchDescription([")
    lines += [f"        DeclareLaunchArgument('{name}', default_value='x')," for name in NAMES]
    lines += [f"        OpaqueFunction(function=body{index})," for index in range(len(functions))]
    lines.append("    ])")
    return "\n".join(lines) + "\n"


@settings(max_examples=5, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(functions=bodies, includes=roots)
def test_generated_trees_give_the_same_with_and_without_reuse(
        functions: list[tuple[frozenset[str], list[str], bool]],
        includes: list[list[dict[str, str]]]) -> None:
    with tempfile.TemporaryDirectory() as folder:
        tree = Path(folder)
        (tree / "body.launch.py").write_text(_generated_body(functions))
        for index, arguments in enumerate(includes):
            (tree / f"r{index}.launch.xml").write_text("<launch>" + "".join(
                f'<group><push-ros-namespace namespace="g{i}"/>'
                '<include file="$(dirname)/body.launch.py">'
                + "".join(f'<arg name="{k}" value="{v}"/>' for k, v in sorted(passed.items()))
                + "</include></group>" for i, passed in enumerate(arguments)) + "</launch>")
        reused = _check(tree)
        with pytest.MonkeyPatch.context() as patch:
            patch.setattr(files, "MAX_OPAQUE_RUNS", 0)
            assert _check(tree) == reused
