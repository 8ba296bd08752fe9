"""Property tests: namespaces and scoping computed by the evaluator match launch_ros's rules.

Random trees of groups, pushed namespaces and nodes are written as XML and as YAML; a small
reference interpreter written here from launch_ros's documented behaviour says which fully
qualified names must come out.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from launchverify.evaluate.runner import evaluate
from launchverify.evaluate.values import argument_names, is_literal, is_unset
from launchverify.graph import LaunchGraph
from launchverify.ir.subst import Concat, LaunchConfig, Sub, Text, walk
from launchverify.ir.symbolic import Arg, Select, Truthy, Unset
from launchverify.render.graph_out import GraphView
from launchverify.workspace.packages import PackageIndex

NAMESPACES = st.sampled_from(["robot", "/fleet", "arm/", "", "a/b", "/"])


@dataclass(frozen=True)
class Node:
    name: str
    namespace: str | None


@dataclass(frozen=True)
class Push:
    namespace: str


@dataclass(frozen=True)
class Group:
    scoped: bool
    items: tuple[object, ...]


items = st.deferred(lambda: st.lists(item, max_size=4).map(tuple))
item = st.one_of(
    st.builds(Node, st.sampled_from(["talker", "listener"]), st.none() | NAMESPACES),
    st.builds(Push, NAMESPACES.filter(lambda ns: ns != "")),
    st.builds(Group, st.booleans(), items),
)


def prefix(base: str | None, ns: str | None) -> str | None:
    """launch_ros prefix_namespace, restated."""
    if base is None and ns is None:
        return None
    if ns is None:
        combined = base
    elif not base or ns.startswith("/"):
        combined = ns
    else:
        combined = ("" if base == "/" else base) + "/" + ns
    assert combined is not None
    return combined if combined == "/" else combined.rstrip("/")


def absolute(ns: str | None) -> str | None:
    return None if ns is None else ns if ns.startswith("/") else "/" + ns


def expected(tree: tuple[object, ...]) -> list[str]:
    out: list[str] = []

    def run(entries: tuple[object, ...], pushed: str | None) -> str | None:
        for entry in entries:
            if isinstance(entry, Push):
                pushed = absolute(prefix(pushed, entry.namespace))
            elif isinstance(entry, Node):
                ns = absolute(prefix(pushed, entry.namespace)) or "/"
                out.append(("/" if ns == "/" else ns + "/") + entry.name)
            elif isinstance(entry, Group):
                inner = run(entry.items, pushed)
                if not entry.scoped:
                    pushed = inner
        return pushed

    run(tree, None)
    return out


def to_xml(entries: tuple[object, ...], depth: int = 1) -> str:
    pad = "  " * depth
    lines = []
    for entry in entries:
        if isinstance(entry, Push):
            lines.append(f'{pad}<push_ros_namespace namespace="{entry.namespace}"/>')
        elif isinstance(entry, Node):
            ns = "" if entry.namespace is None else f' namespace="{entry.namespace}"'
            lines.append(f'{pad}<node pkg="demo_nodes_cpp" exec="x" name="{entry.name}"{ns}/>')
        elif isinstance(entry, Group):
            lines.append(f'{pad}<group scoped="{str(entry.scoped).lower()}">')
            lines.append(to_xml(entry.items, depth + 1))
            lines.append(f"{pad}</group>")
    return "\n".join(line for line in lines if line)


def to_yaml(entries: tuple[object, ...], depth: int = 0) -> str:
    pad = "  " * depth
    lines = []
    for entry in entries:
        if isinstance(entry, Push):
            lines.append(f'{pad}- push_ros_namespace: {{namespace: "{entry.namespace}"}}')
        elif isinstance(entry, Node):
            ns = "" if entry.namespace is None else f', namespace: "{entry.namespace}"'
            lines.append(f"{pad}- node: {{pkg: demo_nodes_cpp, exec: x, name: {entry.name}{ns}}}")
        elif isinstance(entry, Group):
            lines.append(f"{pad}- group:")
            lines.append(f"{pad}    scoped: {str(entry.scoped).lower()}")
            if entry.items:
                lines.append(f"{pad}    children:")
                lines.append(to_yaml(entry.items, depth + 3))
            else:
                lines.append(f"{pad}    children: []")
    return "\n".join(line for line in lines if line)


def fqns(path: Path) -> list[str]:
    graph = evaluate(path, index=PackageIndex(), workspace=path.parent)
    assert not [p for p in graph.problems], graph.problems
    return [node["fqn"] for node in GraphView(graph, symbolic=False).document()["nodes"]]


@settings(max_examples=60, deadline=None)
@given(items)
def test_xml_namespaces_match_launch_ros(tmp_path_factory: object, tree: tuple[object, ...]
                                         ) -> None:
    folder = tmp_path_factory.mktemp("xml")
    path = folder / "t.launch.xml"
    path.write_text(f"<launch>\n{to_xml(tree)}\n</launch>\n")
    assert fqns(path) == expected(tree)


@settings(max_examples=60, deadline=None)
@given(items)
def test_yaml_matches_xml(tmp_path_factory: object, tree: tuple[object, ...]) -> None:
    folder = tmp_path_factory.mktemp("yaml")
    path = folder / "t.launch.yaml"
    body = to_yaml(tree)
    path.write_text("launch:\n" + (body + "\n" if body else "  []\n"))
    assert fqns(path) == expected(tree)


# ----------------------------------------------------------------------------- summaries


def _values() -> st.SearchStrategy[Sub]:
    leaves = st.one_of(
        st.sampled_from(["a", "b", ""]).map(Text),
        st.sampled_from(["x", "y"]).map(Unset),
        st.sampled_from(["x", "y", "z"]).map(Arg),
    )

    def branches(inner: st.SearchStrategy[Sub]) -> st.SearchStrategy[Sub]:
        return st.one_of(
            st.lists(inner, min_size=1, max_size=3).map(lambda parts: Concat(tuple(parts))),
            st.tuples(st.sampled_from(["x", "y"]), inner).map(lambda p: Arg(p[0], p[1])),
            st.tuples(inner, inner).map(
                lambda p: Select((Truthy(Arg("c")),), p[0], p[1])),
            inner.map(LaunchConfig),
        )

    return st.recursive(leaves, branches, max_leaves=12)


@settings(max_examples=200, deadline=None)
@given(st.lists(_values(), min_size=1, max_size=6), st.data())
def test_value_summaries_are_those_of_a_full_walk(values: list[Sub], data: st.DataObject
                                                  ) -> None:
    """Summaries reuse those of shared parts (a chain of assignments): same answers.

    (Of the literal kinds, the values generated here hold only ``Text`` and ``Concat``.)
    """
    chain = values[0]
    for value in values[1:]:  # each link holds the previous value, as assignments do
        chain = Select((Truthy(Arg("c")),), value, chain) if data.draw(st.booleans()) \
            else Concat((chain, value))
        for part in (chain, value):
            walked = walk(part)
            assert is_unset(part) == any(isinstance(x, Unset) for x in walked)
            assert argument_names(part) == {x.name for x in walked if isinstance(x, Arg)}
            assert is_literal(part) == all(isinstance(x, (Text, Concat)) for x in walked)


# ---- issue 42: what one root may expand (evaluate/budget.py) ----


def _fan_out(folder: Path, levels: int) -> Path:
    """``levels`` files, each including the next twice: 2 ** levels include instances."""
    for level in range(levels):
        body = ('  <node pkg="demo_nodes_cpp" exec="talker"/>\n' if level == levels - 1 else
                f'  <include file="$(dirname)/f{level + 1}.launch.xml"/>\n' * 2)
        (folder / f"f{level}.launch.xml").write_text(f"<launch>\n{body}</launch>\n")
    return folder / "f0.launch.xml"


def _bounded(path: Path) -> tuple[LaunchGraph, list[str]]:
    graph = evaluate(path, index=PackageIndex(), workspace=path.parent)
    notes = [r.problem.message for r in graph.problems
             if r.problem.kind.value == "unmodeled" and r.problem.span.file == path]
    return graph, notes


def test_an_include_fan_out_stops_at_its_bound(tmp_path: Path) -> None:
    """13 levels make 16,382 include instances: the walk stops at the bound, keeps what
    it had, and says so on the root."""
    from launchverify.evaluate.budget import MAX_INCLUDES

    graph, notes = _bounded(_fan_out(tmp_path, 13))
    assert graph.cut_short and not graph.complete and graph.stopped_early
    followed = [i for i in graph.includes if i.status == "loaded"]
    assert MAX_INCLUDES <= len(followed) <= MAX_INCLUDES + 1
    assert graph.nodes
    assert [n for n in notes if f"{MAX_INCLUDES:,} include instances" in n
            and "stopped at f" in n], notes


def test_a_tree_within_the_bounds_is_not_cut(tmp_path: Path) -> None:
    graph, notes = _bounded(_fan_out(tmp_path, 8))
    assert not graph.cut_short and graph.complete and not notes
    assert len(graph.nodes) == 128


NESTED_LOOPS = """<launch>
  <for len="256" name="i"><for len="256" name="j">
    {body}
  </for></for>
</launch>
"""


def test_nested_loops_stop_at_the_node_bound(tmp_path: Path,
                                             monkeypatch: pytest.MonkeyPatch) -> None:
    from launchverify.evaluate import budget, walker

    monkeypatch.setattr(walker, "ExpansionBudget",
                        lambda: budget.ExpansionBudget(max_nodes=500))
    path = tmp_path / "loops.launch.xml"
    path.write_text(NESTED_LOOPS.format(
        body='<node pkg="demo_nodes_cpp" exec="talker" name="n$(index i)_$(index j)"/>'))
    graph, notes = _bounded(path)
    assert graph.cut_short and len(graph.nodes) == 501
    assert ["500 nodes" in n for n in notes] == [True]


def test_nested_loops_stop_at_the_action_bound(tmp_path: Path,
                                               monkeypatch: pytest.MonkeyPatch) -> None:
    """No node at all, only work: each loop iteration's actions count."""
    from launchverify.evaluate import budget, walker

    monkeypatch.setattr(walker, "ExpansionBudget",
                        lambda: budget.ExpansionBudget(max_actions=5_000))
    path = tmp_path / "loops.launch.xml"
    path.write_text(NESTED_LOOPS.format(body='<let name="x" value="$(index j)"/>'))
    graph, notes = _bounded(path)
    assert graph.cut_short and ["5,000 actions" in n for n in notes] == [True]


CUT_ROOT = """<launch>
  <arg name="late" default="b"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="a">
    <param from="$(dirname)/params.yaml"/>
  </node>
  <include file="$(dirname)/f0.launch.xml"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="$(var late)">
    <param from="$(dirname)/params.yaml"/>
  </node>
</launch>
"""
CUT_PARAMS = "a:\n  ros__parameters:\n    x: 1\nb:\n  ros__parameters:\n    x: 2\n"
CUT_PYTHON = """from launch import LaunchDescription
from launch.actions import (ExecuteProcess, IncludeLaunchDescription, LogInfo,
                            RegisterEventHandler)
from launch.event_handlers import OnProcessExit
from launch.launch_description_sources import AnyLaunchDescriptionSource
from launch.substitutions import PathJoinSubstitution, ThisLaunchFileDir

def generate_launch_description():
    late = ExecuteProcess(cmd=['sleep', '1'], name='late')
    return LaunchDescription([
        RegisterEventHandler(OnProcessExit(target_action=late, on_exit=[LogInfo(msg='x')])),
        IncludeLaunchDescription(AnyLaunchDescriptionSource(
            PathJoinSubstitution([ThisLaunchFileDir(), 'f0.launch.xml']))),
        late,
    ])
"""


def test_no_absence_is_claimed_past_the_cut(tmp_path: Path,
                                            monkeypatch: pytest.MonkeyPatch) -> None:
    """What comes after the cut is unseen: an argument read there is not unused (LV202),
    a parameter block for a node started there matches one (LV402), a handler's target
    executed there is executed (LV502). Without the cut, none of them is reported either."""
    from launchverify.engine import CheckOptions, run_check
    from launchverify.evaluate import budget, walker

    _fan_out(tmp_path, 3)  # 6 include instances
    (tmp_path / "root.launch.xml").write_text(CUT_ROOT)
    (tmp_path / "params.yaml").write_text(CUT_PARAMS)
    (tmp_path / "handler.launch.py").write_text(CUT_PYTHON)
    options = CheckOptions(paths=[tmp_path / "root.launch.xml", tmp_path / "handler.launch.py"],
                           workspace=tmp_path, jobs=1)

    def codes() -> set[tuple[str, str]]:
        return {(f.code, f.span.file.name) for f in run_check(options).findings}

    assert codes() == set()
    monkeypatch.setattr(walker, "ExpansionBudget",
                        lambda: budget.ExpansionBudget(max_includes=3))
    assert codes() == {("LV003", "root.launch.xml"), ("LV003", "handler.launch.py")}
