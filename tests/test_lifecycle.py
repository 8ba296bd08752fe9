"""The lifecycle bring-up: the state machine, the search, and what the rules promise."""

from __future__ import annotations

import doctest
import importlib
import json
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from launchverify.cli import main
from launchverify.engine import CheckOptions, run_check
from launchverify.graph import LaunchGraph
from launchverify.lifecycle import analyse
from launchverify.models import distros
from launchverify.models import lifecycle as lc

CORPUS = Path(__file__).resolve().parent.parent / "corpus" / "lifecycle"

HEADER = """\
from launch import LaunchDescription
from launch.actions import EmitEvent, RegisterEventHandler
from launch.events import matches_action
from launch_ros.actions import LifecycleNode, Node
from launch_ros.event_handlers import OnStateTransition
from launch_ros.events.lifecycle import ChangeState
from lifecycle_msgs.msg import Transition


def change(node, transition):
    return EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(node),
                                       transition_id=transition))

"""


def write(tmp_path: Path, body: str, name: str = "bringup.launch.py") -> Path:
    path = tmp_path / name
    path.write_text(HEADER + body, encoding="utf-8")
    return path


def graph_of(path: Path) -> LaunchGraph:
    return run_check(CheckOptions(paths=[path], workspace=path.parent,
                                  select=["LV503", "LV504", "LV505"])).graphs[0]


def reached(path: Path) -> dict[str, list[str]]:
    analysis = analyse(graph_of(path))
    return {node.fqn: sorted(analysis.exploration.reached.get(i, {}))
            for i, node in enumerate(analysis.system.nodes)}


def test_state_machine_doctests() -> None:
    assert doctest.testmod(lc).failed == 0
    assert doctest.testmod(distros).failed == 0


@pytest.mark.parametrize(("state", "transition", "goal"), [
    ("unconfigured", 1, "inactive"),
    ("inactive", 3, "active"),
    ("active", 4, "inactive"),
    ("inactive", 2, "unconfigured"),
    ("active", 7, "finalized"),
])
def test_successful_transitions_end_where_rcl_says(state: str, transition: int,
                                                   goal: str) -> None:
    result = lc.request(state, transition, "success")
    assert result is not None
    after, events = result
    assert after == goal and events[-1].goal == goal
    assert [e.transition for e in events] == [lc.TRANSITIONS[transition].label,
                                         "transition_success"]


def test_an_error_in_a_callback_goes_through_errorprocessing() -> None:
    result = lc.request("inactive", 3, outcome="error")
    assert result is not None
    assert [e.goal for e in result[1]] == ["activating", "errorprocessing", "unconfigured"]


@pytest.mark.parametrize(("state", "transition"), [
    ("unconfigured", 3), ("active", 1), ("inactive", 4), ("finalized", 1)])
def test_transitions_refused_from_the_wrong_state(state: str, transition: int) -> None:
    assert lc.request(state, transition, "success") is None


def test_chain_reaches_active_and_a_shortest_trace_leads_there(tmp_path: Path) -> None:
    path = write(tmp_path, """
def generate_launch_description():
    a = LifecycleNode(package='p', executable='a', name='a', namespace='')
    return LaunchDescription([
        a, change(a, Transition.TRANSITION_CONFIGURE),
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=a, goal_state='inactive',
            entities=[change(a, Transition.TRANSITION_ACTIVATE)])),
    ])
""")
    assert reached(path) == {"/a": ["activating", "active", "configuring", "inactive",
                                    "unconfigured"]}
    analysis = analyse(graph_of(path))
    steps = [step.text for step in analysis.exploration.trace(
        analysis.exploration.reached[0]["active"])]
    assert steps[0] == "the launch starts"
    assert any("configure: it becomes inactive" in s for s in steps)
    assert steps[-1].endswith("it becomes active") or "handler" in steps[-1]


def test_unrelated_nodes_are_searched_as_independent_parts(tmp_path: Path) -> None:
    body = "\n".join(
        f"    n{i} = LifecycleNode(package='p', executable='x', name='n{i}', namespace='')"
        for i in range(12))
    actions = ", ".join(f"n{i}, change(n{i}, Transition.TRANSITION_CONFIGURE)"
                        for i in range(12))
    path = write(tmp_path, f"""
def generate_launch_description():
{body}
    return LaunchDescription([{actions}])
""")
    analysis = analyse(graph_of(path))
    assert len(analysis.exploration.searches) == 12
    # twelve nodes interleaved would be 2**12 states; searched apart, a handful each
    assert analysis.exploration.states < 100
    assert all("inactive" in states for states in reached(path).values())


def fleet(tmp_path: Path, nodes: int, managers: int) -> Path:
    """Write ``nodes`` lifecycle nodes brought up by ``managers`` nav2 managers."""
    lines = ["def generate_launch_description():", "    actions = []"]
    for m in range(managers):
        names = [f"node_{m}_{i}" for i in range(m, nodes, managers)]
        lines += [f"    for name in {names!r}:",
                  "        actions.append(Node(package='nav2_amcl', executable='amcl', "
                  "name=name))",
                  "    actions.append(Node(package='nav2_lifecycle_manager', "
                  f"executable='lifecycle_manager', name='manager_{m}', "
                  f"parameters=[{{'autostart': True, 'node_names': {names!r}}}]))"]
    lines.append("    return LaunchDescription(actions)")
    return write(tmp_path, "\n".join(lines) + "\n")


def test_fifty_nodes_under_three_managers_all_become_active(tmp_path: Path) -> None:
    path = fleet(tmp_path, 50, 3)
    analysis = analyse(graph_of(path))
    assert len(analysis.system.nodes) == 50 and len(analysis.system.managers) == 3
    assert analysis.exploration.complete
    assert analysis.exploration.managers_done == {0, 1, 2}
    assert all("active" in states for states in reached(path).values())


def test_json_findings_carry_the_trace(capsys: pytest.CaptureFixture[str]) -> None:
    main(["check", str(CORPUS / "activate_at_start" / "activate.launch.py"),
          "--format", "json"])
    finding = next(f for f in json.loads(capsys.readouterr().out)["findings"]
                   if f["code"] == "LV504")
    assert finding["trace"][0] == {"step": "the launch starts", "file": None, "line": None}
    last = finding["trace"][-1]
    assert "refused" in last["step"] and last["line"] == 18


def test_explain_prints_the_trace_in_text(capsys: pytest.CaptureFixture[str]) -> None:
    path = str(CORPUS / "activation_cycle" / "never_activated.launch.py")
    main(["check", path])
    assert "(--explain prints the trace)" in capsys.readouterr().out
    main(["check", path, "--explain"])
    out = capsys.readouterr().out
    assert "trace:" in out and "1. the launch starts" in out
    assert "asks /map_server to configure: it becomes inactive" in out


def test_graph_lists_reachable_states(capsys: pytest.CaptureFixture[str]) -> None:
    path = CORPUS / "nav2_localization_clean" / "nav_bringup" / "launch"
    main(["graph", str(path / "localization.launch.yaml")])
    lifecycle = json.loads(capsys.readouterr().out)["lifecycle"]
    assert lifecycle["complete"] is True
    assert [m["completes"] for m in lifecycle["managers"]] == [True]
    states = {n["fqn"]: list(n["states"]) for n in lifecycle["nodes"]}
    assert states["/robot1/amcl"] == ["unconfigured", "configuring", "inactive",
                                      "activating", "active"]


INCLUDER = """\
from launch import LaunchDescription
from launch.actions import IncludeLaunchDescription
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node


def generate_launch_description():
    here = __file__.rsplit('/', 1)[0]
    return LaunchDescription([
        {extra}
        IncludeLaunchDescription(PythonLaunchDescriptionSource(here + '/manager.launch.py')),
    ])
"""

MANAGER = """\
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_launch_description():
    return LaunchDescription([
        Node(package='nav2_lifecycle_manager', executable='lifecycle_manager',
             name='lifecycle_manager', parameters=[{'node_names': ['amcl'], 'autostart': True}]),
    ])
"""


def lv505(tmp_path: Path) -> list[int]:
    report = run_check(CheckOptions(paths=[tmp_path], workspace=tmp_path))
    return [f.span.line for f in report.findings if f.code == "LV505"]


def test_an_includer_that_launches_the_node_settles_the_question(tmp_path: Path) -> None:
    (tmp_path / "manager.launch.py").write_text(MANAGER)
    (tmp_path / "bringup.launch.py").write_text(INCLUDER.format(
        extra="Node(package='nav2_amcl', executable='amcl', name='amcl'),"))
    assert lv505(tmp_path) == []  # alone, manager.launch.py lacks amcl; its includer has it


def test_a_file_included_elsewhere_is_still_judged(tmp_path: Path) -> None:
    (tmp_path / "manager.launch.py").write_text(MANAGER)
    (tmp_path / "bringup.launch.py").write_text(INCLUDER.format(
        extra="Node(package='nav2_amcl', executable='amlc', name='amlc'),"))
    assert lv505(tmp_path) == [7]


WIDE = """
def generate_launch_description():
    hub = Node(package='demo_nodes_cpp', executable='talker', name='hub')
    nodes = [LifecycleNode(package='p', executable='x', name=f's{k}', namespace='')
             for k in range(16)]
    actions = [hub, *nodes, RegisterEventHandler(OnProcessStart(
        target_action=hub,
        on_start=[change(n, Transition.TRANSITION_CONFIGURE) for n in nodes]))]
    for n in nodes:
        actions.append(RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=n, goal_state='inactive',
            entities=[change(n, Transition.TRANSITION_ACTIVATE)])))
    return LaunchDescription(actions)
"""


def test_one_handler_bringing_up_many_nodes_stays_small(tmp_path: Path) -> None:
    path = write(tmp_path, "from launch.event_handlers import OnProcessStart\n" + WIDE)
    analysis = analyse(graph_of(path))
    assert analysis.exploration.complete
    assert analysis.exploration.states < 500  # 3**16 interleavings without the reduction
    assert all("active" in states for states in reached(path).values())


def summary(path: Path) -> tuple[object, ...]:
    exploration = analyse(graph_of(path)).exploration
    return ({n: set(states) for n, states in exploration.reached.items()},
            set(exploration.refused), set(exploration.fired), exploration.managers_done,
            set(exploration.manager_stuck))


@pytest.mark.parametrize("path", sorted(CORPUS.rglob("*.launch.*")),
                         ids=lambda p: f"{p.parent.name}/{p.name}")
def test_the_reduction_finds_what_the_full_search_finds(
        path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    reduced = summary(path)
    monkeypatch.setattr(importlib.import_module("launchverify.lifecycle.explore"), "REDUCE",
                        False)
    assert summary(path) == reduced


TRANSITIONS = ["CONFIGURE", "ACTIVATE", "DEACTIVATE", "CLEANUP"]
STATES = ["inactive", "active", "unconfigured", "finalized"]


@st.composite
def bringups(draw: st.DrawFn) -> str:
    """A random bring-up: lifecycle nodes, requests at launch and in handlers, a manager."""
    count = draw(st.integers(1, 4))
    lines = ["def generate_launch_description():", "    actions = []"]
    for k in range(count):
        autostart = draw(st.booleans())
        lines.append(f"    n{k} = LifecycleNode(package='p', executable='x', name='n{k}', "
                     f"namespace='', autostart={autostart})")
        lines.append(f"    actions.append(n{k})")
    for _ in range(draw(st.integers(0, 3))):
        node, transition = draw(st.integers(0, count - 1)), draw(st.sampled_from(TRANSITIONS))
        lines.append(f"    actions.append(change(n{node}, Transition.TRANSITION_{transition}))")
    for _ in range(draw(st.integers(0, 4))):
        watched, goal = draw(st.integers(0, count - 1)), draw(st.sampled_from(STATES))
        node, transition = draw(st.integers(0, count - 1)), draw(st.sampled_from(TRANSITIONS))
        lines.append(f"    actions.append(RegisterEventHandler(OnStateTransition("
                     f"target_lifecycle_node=n{watched}, goal_state='{goal}', "
                     f"entities=[change(n{node}, Transition.TRANSITION_{transition})])))")
    managed = draw(st.lists(st.integers(0, count - 1), max_size=count, unique=True))
    if managed:
        names = [f"n{k}" for k in managed]
        lines.append("    actions.append(Node(package='nav2_lifecycle_manager', "
                     "executable='lifecycle_manager', name='manager', "
                     f"parameters=[{{'autostart': True, 'node_names': {names!r}}}]))")
    lines.append("    return LaunchDescription(actions)")
    return "\n".join(lines) + "\n"


@settings(max_examples=15, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(bringups())
def test_the_reduction_agrees_on_random_bringups(tmp_path: Path, body: str) -> None:
    path = write(tmp_path, body)
    reduced = summary(path)
    module = importlib.import_module("launchverify.lifecycle.explore")
    module.REDUCE = False
    try:
        assert summary(path) == reduced
    finally:
        module.REDUCE = True


@pytest.mark.parametrize(("distro", "codes"), [
    (None, []),
    ("rolling", []),
    ("jazzy", ["LV001"]),  # <lifecycle_node> is a rolling tag; autostart exists in jazzy
    ("humble", ["LV001", "LV002"]),  # and humble has no autostart at all
])
def test_lifecycle_features_follow_the_distribution(
        distro: str | None, codes: list[str], capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("ROS_DISTRO", raising=False)
    tree = CORPUS / "configure_activate_chain"
    autostart = CORPUS / "double_management" / "double.launch.py"
    argv = ["check", str(tree / "chain.launch.xml"), str(autostart), "--format", "json",
            "--select", "LV001,LV002"]
    main([*argv, *(["--distro", distro] if distro else [])])
    found = sorted({f["code"] for f in json.loads(capsys.readouterr().out)["findings"]})
    assert found == codes


def test_ros_distro_of_a_sourced_installation_is_the_default(
        capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("ROS_DISTRO", "humble")
    main(["check", str(CORPUS / "double_management" / "double.launch.py"), "--format",
          "json", "--select", "LV002"])
    messages = [f["message"] for f in json.loads(capsys.readouterr().out)["findings"]]
    assert messages and "is not in humble (since jazzy)" in messages[0]


# ----------------------------------------------------------------------------- handler labels


def test_the_events_are_those_rcl_publishes() -> None:
    pairs = {(e.start, e.goal) for e in lc.EVENTS}
    assert ("configuring", "inactive") in pairs and ("unconfigured", "inactive") not in pairs
    assert ("errorprocessing", "unconfigured") in pairs
    assert not any(e.start in ("finalized", "unknown") or e.goal == "unknown"
                   for e in lc.EVENTS)
    assert {e.transition for e in lc.EVENTS} == set(lc.EVENT_TRANSITION_LABELS)


@pytest.mark.parametrize(("filters", "field", "hint"), [
    ({"goal_state": "activated"}, "goal_state", "goal_state='active'"),
    ({"goal_state": "configured"}, "goal_state", "goal_state='inactive'"),
    ({"goal_state": "Active"}, "goal_state", "goal_state='active'"),
    ({"goal_state": "PRIMARY_STATE_INACTIVE"}, "goal_state", "goal_state='inactive'"),
    ({"start_state": "cleaning_up"}, "start_state", "start_state='cleaningup'"),
    ({"goal_state": "unknown"}, "goal_state", None),
    ({"start_state": "finalized"}, "start_state", "goal_state='finalized'"),
    ({"transition": "activating"}, "transition", "transition='activate'"),
    ({"transition": "on_configure_success"}, "transition", "transition='transition_success'"),
    ({"start_state": "unconfigured", "goal_state": "inactive"}, "start_state",
     "start_state='configuring'"),
    ({"start_state": "active", "goal_state": "unconfigured"}, "start_state", None),
    ({"transition": "configure", "goal_state": "inactive"}, "transition",
     "leave out transition='configure'"),
    ({"goal_state": lc.NOT_TEXT}, "goal_state", None),
])
def test_labels_no_event_carries_are_named_with_the_one_meant(
        filters: dict[str, str], field: str, hint: str | None) -> None:
    problem = lc.never_matches(tuple(filters.items()))
    assert problem is not None and problem.field == field and problem.hint == hint


@pytest.mark.parametrize("filters", [
    {"goal_state": "inactive"}, {"start_state": "configuring", "goal_state": "inactive"},
    {"start_state": "activating", "goal_state": "active"}, {"goal_state": "finalized"},
    {"goal_state": "errorprocessing"}, {"transition": "configure"},
    {"transition": "transition_success", "goal_state": "active"},
])
def test_labels_rcl_publishes_match(filters: dict[str, str]) -> None:
    assert lc.never_matches(tuple(filters.items())) is None


@given(st.dictionaries(st.sampled_from(lc.FILTER_FIELDS),
                       st.sampled_from([*lc.STATE_LABELS, *lc.EVENT_TRANSITION_LABELS])))
def test_a_filter_never_matches_exactly_when_no_event_passes_it(
        filters: dict[str, str]) -> None:
    values = [{"transition": e.transition, "start_state": e.start, "goal_state": e.goal}
              for e in lc.EVENTS]
    some = any(all(v[k] == label for k, label in filters.items()) for v in values)
    assert (lc.never_matches(tuple(filters.items()), "rolling") is None) == some
    if "transition" in filters:  # before rolling the events carry no transition label
        assert lc.never_matches(tuple(filters.items()), "humble") is not None


@given(st.dictionaries(st.sampled_from(lc.FILTER_FIELDS),
                       st.sampled_from([*lc.STATE_LABELS, *lc.EVENT_TRANSITION_LABELS])))
def test_a_pair_is_labels_each_published_alone(filters: dict[str, str]) -> None:
    # LV504 (a pair no single event carries) or LV508 (a label never published in its field)
    problem = lc.never_matches(tuple(filters.items()), "rolling")
    if problem is not None:
        alone = all(lc.never_matches(((field, label),), "rolling") is None
                    for field, label in filters.items())
        assert problem.pair == alone


def test_transition_labels_follow_the_distribution() -> None:
    assert [lc.transition_labels(d) for d in distros.DISTROS] == [
        False, False, False, False, True]
    problem = lc.never_matches((("transition", "configure"),), "kilted")
    assert problem is not None and "ros2/rcl#1019" in problem.reason
    assert problem.hint == "goal_state='configuring'"


def codes_at(path: Path, distro: str | None = None) -> list[tuple[int, str]]:
    report = run_check(CheckOptions(paths=[path], workspace=path.parent, distro=distro,
                                    select=["LV503", "LV504", "LV508"]))
    return sorted((f.span.line, f.code) for f in report.findings)


def test_a_transition_filter_never_fires_before_rolling() -> None:
    path = CORPUS / "handler_labels_clean" / "localization.launch.py"
    line = next(i for i, text in enumerate(path.read_text().splitlines(), 1)
                if "transition='configure'" in text)
    assert codes_at(path) == codes_at(path, "rolling") == []
    assert codes_at(path, "jazzy") == codes_at(path, "humble") == [(line, "LV508")]


GATED = """
def generate_launch_description():
    a = LifecycleNode(package='p', executable='a', name='a', namespace='')
    on_inactive = OnStateTransition(
        target_lifecycle_node=a, transition='transition_success',
        goal_state='inactive', entities=[change(a, Transition.TRANSITION_ACTIVATE)])
    return LaunchDescription([
        a, change(a, Transition.TRANSITION_CONFIGURE),
        RegisterEventHandler(on_inactive),
    ])
"""


def test_a_dead_handler_gates_the_activation_in_the_search(tmp_path: Path) -> None:
    path = write(tmp_path, GATED)
    assert "active" in reached(path)["/a"]  # any distribution: rolling's events have labels
    with distros.checking("jazzy"):
        graph = graph_of(path)
        assert "active" not in {s for s in analyse(graph).exploration.reached[0]}
        assert not analyse(graph).exploration.fired
    # LV508 at the argument, though the handler is built apart from its registration;
    # LV503 at the registration, naming the activation that is never sent
    lines = (HEADER + GATED).splitlines()
    label = next(i for i, text in enumerate(lines, 1) if "transition=" in text)
    register = next(i for i, text in enumerate(lines, 1) if "RegisterEventHandler(" in text)
    assert codes_at(path, "jazzy") == [(label, "LV508"), (register, "LV503")]
    report = run_check(CheckOptions(paths=[path], workspace=tmp_path, distro="jazzy",
                                    select=["LV503"]))
    assert "/a is never asked to activate and stays inactive" in report.findings[0].message


WAITING = """
def generate_launch_description():
    a = LifecycleNode(package='p', executable='a', name='a', namespace='')
    return LaunchDescription([
        a, change(a, Transition.TRANSITION_CONFIGURE),
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=a, goal_state='inactve',
            entities=[change(a, Transition.TRANSITION_ACTIVATE)])),
        RegisterEventHandler(OnStateTransition(
            target_lifecycle_node=a, goal_state='active',
            entities=[Node(package='p', executable='b', name='b')])),
    ])
"""


def test_what_waits_on_a_dead_handler_is_not_reported_apart(tmp_path: Path) -> None:
    path = write(tmp_path, WAITING)
    lines = (HEADER + WAITING).splitlines()
    label = next(i for i, text in enumerate(lines, 1) if "'inactve'" in text)
    report = run_check(CheckOptions(paths=[path], workspace=tmp_path,
                                    select=["LV503", "LV504", "LV508"]))
    found = sorted((f.span.line, f.code) for f in report.findings)
    assert found == [(label - 1, "LV503"), (label, "LV508")]  # not the 'active' handler
    assert "did you mean goal_state='inactive'?" in next(
        f.message for f in report.findings if f.code == "LV508")


CONTAINERS = """
from launch.actions import ExecuteProcess, GroupAction
from launch.substitutions import EnvironmentVariable
from launch_ros.actions import ComposableNodeContainer, LoadComposableNodes, PushRosNamespace
from launch_ros.descriptions import ComposableNode


def generate_launch_description():
    container = ComposableNodeContainer(name='c', namespace='', package='rclcpp_components',
                                        executable='component_container')
    return LaunchDescription([{host}GroupAction([
        PushRosNamespace('r1'), container,
        LoadComposableNodes(target_container=container, composable_node_descriptions=[
            ComposableNode(package='p', plugin='p::A', name='a')]),
        LoadComposableNodes(target_container='c', composable_node_descriptions=[
            ComposableNode(package='p', plugin='p::B', name='b')]),
    ])])
"""


def lv506(tmp_path: Path, host: str = "") -> list[tuple[int, str]]:
    path = write(tmp_path, CONTAINERS.format(host=host))
    report = run_check(CheckOptions(paths=[path], workspace=tmp_path, select=["LV506"]))
    return [(f.span.line, f.severity.value) for f in report.findings]


def test_a_load_waits_for_its_container_as_launch_ros_names_it(tmp_path: Path) -> None:
    path = write(tmp_path, CONTAINERS.format(host=""))
    graph = run_check(CheckOptions(paths=[path], workspace=tmp_path,
                                   select=["LV506"])).graphs[0]
    # the container action is its full name; a relative name is resolved in /
    assert [graph.base(load.target) for load in graph.loads] == ["/r1/c", "c"]
    assert {graph.base(n.fqn): graph.base(n.container) for n in graph.nodes
            if n.composable} == {"/r1/a": "/r1/c", "/r1/b": "c"}
    line = next(i for i, text in enumerate((HEADER + CONTAINERS).splitlines(), 1)
                if "target_container='c'" in text)
    assert lv506(tmp_path) == [(line, "error")]


@pytest.mark.parametrize("host", [
    "Node(package='p', executable='x', name='c', namespace='/'),",  # any node named so
    "Node(package='p', executable=EnvironmentVariable('EXE')),",  # may be a container
    "ExecuteProcess(cmd=['ros2', 'run', 'rclcpp_components', 'component_container']),",
])
def test_what_may_be_the_container_keeps_the_load_quiet(tmp_path: Path, host: str) -> None:
    assert lv506(tmp_path, host) == []
