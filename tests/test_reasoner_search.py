"""The reasoner's concrete search answers as z3 would, only sooner.

Each question is settled by the search when it can (``smt.search``) and goes to z3
otherwise. These tests generate small launch files mixing switches, choices, arguments
without default, environment variables, command output, configurations read unset and
guards without a model, and check that whenever the search settles a question, z3 asked
the same question says the same: a collision, a way to hold together or a value launch
rejects exists for both or for neither, a condition always holds for both or neither.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any
from xml.sax.saxutils import quoteattr

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from launchverify.evaluate.runner import evaluate
from launchverify.graph import LaunchGraph
from launchverify.ir.symbolic import Truthy
from launchverify.smt import reasoner_for
from launchverify.smt.domains import Mode
from launchverify.smt.reasoner import _ANSWERS
from launchverify.smt.search import _nearest_first, _words
from launchverify.workspace.packages import PackageIndex

HEADER = """<launch>
  <arg name="sim" default="false"/>
  <arg name="mode" default="a">
    <choice value="a"/><choice value="b"/><choice value="c"/>
  </arg>
  <arg name="ns" default="r1"/>
  <arg name="robot"/>
  <arg name="side">
    <choice value="left"/><choice value="right"/>
  </arg>
"""

NAMESPACES = ["", "$(var ns)", "$(var robot)", "$(env ROBOT_NS)", "$(command 'hostname')",
              "$(var mode)", "fixed", "$(var undeclared)"]
CONDITIONS = [None, "$(var sim)", "$(var undeclared)_on", "$(var mode)", "$(not $(var sim))",
              "$(equals $(var mode) a)",
              "$(equals $(var mode) b)", "$(var robot)", "$(env USE_X)",
              "$(eval '\"$(var mode)\" == \"c\"')", "$(var undeclared)",
              "$(eval \"'$(var robot)' == 'scout'\")", "$(command 'probe')",
              "$(not $(command 'probe'))", "$(find-exec lidar_driver)", "$(var side)",
              "$(equals $(var side) left)", "$(eval \"'$(env MODE_X 0)' == '1'\")",
              "$(eval \"'$(env ROBOT_NS)' == 'scout' and '$(var robot)' == 'r1'\")"]

# a condition is written ``if=`` or, with a leading "!", ``unless=``
nodes = st.lists(st.tuples(st.sampled_from(["cam", "lidar"]), st.sampled_from(NAMESPACES),
                           st.sampled_from([c for c in CONDITIONS if c is not None]
                                           + [f"!{c}" for c in CONDITIONS if c is not None]
                                           + [None])), min_size=2, max_size=4)


def launch_text(entries: list[tuple[str, str, str | None]]) -> str:
    lines = [HEADER]
    for name, namespace, condition in entries:
        guard = "" if condition is None else (
            f" unless={quoteattr(condition[1:])}" if condition.startswith("!")
            else f" if={quoteattr(condition)}")
        lines.append(f'  <node pkg="p" exec="e" name="{name}" namespace={quoteattr(namespace)}'
                     f"{guard}/>")
    lines.append("</launch>\n")
    return "\n".join(lines)


def graph_of(folder: Path, entries: list[tuple[str, str, str | None]]) -> LaunchGraph:
    path = folder / "gen.launch.xml"
    path.write_text(launch_text(entries))
    graph = evaluate(path, index=PackageIndex(), workspace=folder)
    assert len(graph.nodes) == len(entries), graph.problems
    return graph


def settled(graph: LaunchGraph, question: str, *args: Any) -> tuple[Any, Any] | None:
    """Return (search's answer, z3's) when the search settles the question alone."""
    reasoner = reasoner_for(graph)
    before = reasoner.queries
    answer = getattr(reasoner, question)(*args)
    if reasoner.queries != before:
        return None  # z3 was asked: nothing to compare
    return answer, getattr(reasoner.z3, question)(*args)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(entries=nodes)
def test_the_search_agrees_with_z3(tmp_path: Path, entries: list[tuple[str, str, str | None]]
                                   ) -> None:
    _ANSWERS.clear()  # answers shared between roots would hide what the search says
    graph = graph_of(tmp_path, entries)
    named = [n for n in graph.nodes if n.fqn is not None]
    for i, first in enumerate(named):
        for second in named[i + 1:]:
            both = settled(graph, "same_name", first.fqn, first.origin.path, second.fqn,
                           second.origin.path)
            if both is not None:
                assert (both[0] is None) == (both[1] is None), (first.fqn, second.fqn)
            paths = (first.origin.path, second.origin.path)
            reasoner = reasoner_for(graph)
            before = reasoner.queries
            search = reasoner.together(*paths)
            if reasoner.queries == before:
                merged = tuple(dict.fromkeys(g for p in paths for g in p))
                assert (search is None) == (reasoner.z3.together((merged,)) is None), paths
        for guard in first.origin.path:
            rest = tuple(g for g in first.origin.path if g is not guard)
            both = settled(graph, "always", rest, guard)
            if both is not None:
                assert both[0] == both[1], (rest, guard)
            if isinstance(guard, Truthy):
                both = settled(graph, "invalid_value", rest, guard)
                if both is not None:
                    assert (both[0] is None) == (both[1] is None), (rest, guard)


def test_names_with_unknowns_are_compared_without_z3(tmp_path: Path) -> None:
    """Two nodes named after a command's output under exclusive modes: no collision."""
    graph = graph_of(tmp_path, [
        ("cam", "$(command 'hostname')", "$(equals $(var mode) a)"),
        ("cam", "$(command 'hostname')", "$(equals $(var mode) b)"),
        ("cam", "$(env ROBOT_NS)", "$(equals $(var mode) c)"),
        ("cam", "$(env ROBOT_NS)", "$(var sim)"),
    ])
    reasoner = reasoner_for(graph)
    first, second, third, fourth = graph.nodes
    assert reasoner.same_name(first.fqn, first.origin.path, second.fqn, second.origin.path) \
        is None
    found = reasoner.same_name(third.fqn, third.origin.path, fourth.fqn, fourth.origin.path)
    assert found is not None and found[0].values == {"mode": "c", "sim": "true"}
    assert reasoner.queries == 0


def test_a_required_argument_does_not_keep_a_settled_question_open(tmp_path: Path) -> None:
    """``$(var robot)`` has no default, but the modes alone keep the nodes apart."""
    graph = graph_of(tmp_path, [
        ("cam", "$(var robot)", "$(equals $(var mode) a)"),
        ("cam", "$(var robot)", "$(equals $(var mode) b)"),
    ])
    first, second = graph.nodes
    reasoner = reasoner_for(graph)
    assert reasoner.together(first.origin.path, second.origin.path) is None
    assert reasoner.queries == 0


def test_literals_suggest_the_values_they_compare_with() -> None:
    """A literal between substitutions may start inside quotes (``' == 'r2'``)."""
    assert list(_words("' == 'r2'")) == ["r2"]
    assert "obstacle_cruise_planner" in set(_words("' == 'obstacle_cruise_planner'"))
    assert list(_words("' >= 40")) == ["40", "41", "39"]


def test_a_long_product_tries_few_changes_first() -> None:
    choices = [(f"a{i}", ("x", "y", "z")) for i in range(6)]
    tried = list(_nearest_first(choices))
    assert len(tried) == 3 ** 6 and len({tuple(t.items()) for t in tried}) == 3 ** 6
    assert tried[0] == {f"a{i}": "x" for i in range(6)}
    assert all(sum(v != "x" for v in t.values()) == 1 for t in tried[1:13])


def test_a_condition_read_unset_can_hold(tmp_path: Path) -> None:
    """z3 takes an unset configuration as any string; so does the search, for "can"."""
    graph = graph_of(tmp_path, [("cam", "", "$(eval \"'$(var undeclared)' == 'yes'\")")])
    (node,) = graph.nodes
    reasoner = reasoner_for(graph)
    (guard,) = node.origin.path
    assert reasoner.never((), guard) is None
    assert reasoner.always((), guard) is False
    assert reasoner.queries == 0


def test_free_strings_inside_values_are_tried_with_the_literals_they_meet(
        tmp_path: Path) -> None:
    """An argument without default over the switches, an environment variable: z3 takes
    each as any string; the search tries the literals they are compared with."""
    graph = graph_of(tmp_path, [
        ("cam", "", "$(eval \"'$(var robot)' == 'scout'\")"),
        ("cam", "", "$(var sim)"),
        ("lidar", "", "$(eval \"'$(env MODE_X 0)' == '1'\")"),
    ])
    first, second, third = graph.nodes
    reasoner = reasoner_for(graph)
    witness = reasoner.together(first.origin.path, second.origin.path)
    assert witness is not None and witness.values == {"sim": "true"}  # robot: never a witness
    (guard,) = third.origin.path
    assert reasoner.never((), guard) is None
    assert reasoner.always((), guard) is False
    assert reasoner.queries == 0


def test_the_search_knows_what_z3_models() -> None:
    """A value the encoder does not model is a free string to z3: the search agrees."""
    from launchverify.smt.encode import Encoder
    from launchverify.smt.search import _ENCODED

    assert set(Encoder({}, Mode.ANY)._dispatch) == set(_ENCODED)


def test_a_boolean_condition_is_valid_whatever_its_path(tmp_path: Path) -> None:
    """The path reads an argument without default; the condition's value settles it."""
    path = tmp_path / "nested.launch.xml"
    path.write_text("""<launch>
  <arg name="sim" default="false"/>
  <arg name="robot"/>
  <group if="$(var robot)">
    <node pkg="p" exec="e" name="cam" if="$(var sim)"/>
    <node pkg="p" exec="e" name="lidar" namespace="$(var sim)"/>
    <node pkg="p" exec="e" name="lidar" namespace="real"/>
  </group>
</launch>
""")
    graph = evaluate(path, index=PackageIndex(), workspace=tmp_path)
    cam, first, second = graph.nodes
    reasoner = reasoner_for(graph)
    outer, inner = cam.origin.path
    assert reasoner.invalid_value((outer,), inner) is None
    assert reasoner.same_name(first.fqn, first.origin.path, second.fqn, second.origin.path) \
        is None  # /false/lidar or /true/lidar, never /real/lidar
    assert reasoner.queries == 0


def test_no_invalid_value_is_guessed_for_a_configuration_read_unset(tmp_path: Path) -> None:
    """z3 judges no value that reads an unset configuration: neither does the search."""
    graph = graph_of(tmp_path, [("cam", "", "$(var undeclared)_on")])
    (node,) = graph.nodes
    (guard,) = node.origin.path
    assert reasoner_for(graph).invalid_value((), guard) is None


# ---- issue 42: the solver time of a root is bounded (smt/budget.py) ----


def _pigeonhole(pigeons: int) -> object:
    """A z3 solver holding the pigeonhole formula: hard for z3 from 10 pigeons on."""
    import z3

    holes = [[z3.Bool(f"p{i}_{j}") for j in range(pigeons - 1)] for i in range(pigeons)]
    solver = z3.Solver()
    for row in holes:
        solver.add(z3.Or(*row))
    for j in range(pigeons - 1):
        for i in range(pigeons):
            for k in range(i + 1, pigeons):
                solver.add(z3.Not(z3.And(holes[i][j], holes[k][j])))
    return solver


def test_a_spent_budget_answers_nothing(tmp_path: Path) -> None:
    """Each question's "cannot tell" claims nothing; a root with time answers them all,
    and what the spent one could not answer is not handed to it."""
    from launchverify.smt.budget import SolverBudget
    from launchverify.smt.reasoner import Reasoner

    graph = graph_of(tmp_path, [("cam", "r1", "$(var sim)"), ("cam", "r1", "$(var sim)"),
                                ("cam", "r1", "$(equals $(var mode) a)"),
                                ("lidar", "r1", "$(equals $(var mode) b)"),
                                ("lidar", "r2", "$(var mode)")])
    first, second, in_a, in_b, any_mode = graph.nodes
    [mode_a], [mode_b], [raw_mode] = (in_a.origin.path, in_b.origin.path,
                                      any_mode.origin.path)
    assert isinstance(raw_mode, Truthy)

    def answers(reasoner: Reasoner) -> list[object]:
        return [reasoner.together(first.origin.path, second.origin.path) is not None,
                reasoner.apart(in_a.origin.path, in_b.origin.path),
                reasoner.same_name(first.fqn, first.origin.path, second.fqn,
                                   second.origin.path) is not None,
                reasoner.never((mode_a,), mode_b) is not None,
                reasoner.always((mode_a,), mode_a),
                reasoner.invalid_value((), raw_mode) is not None]

    _ANSWERS.clear()
    spent = Reasoner(graph, SolverBudget(0.0))
    assert answers(spent) == [False] * 6 and spent.budget.ran_out
    assert answers(Reasoner(graph)) == [True] * 6  # the next root: time of its own


def test_questions_share_one_budget(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The CPU time of every question counts: one that runs out of it stops, proving
    nothing, the next one is not asked, and the root gets an LV003 info saying so."""
    import time

    from launchverify.smt import budget_notes
    from launchverify.smt import search as search_module
    from launchverify.smt.budget import SolverBudget
    from launchverify.smt.reasoner import Reasoner

    graph = graph_of(tmp_path, [("cam", "r1", "$(var sim)"), ("cam", "r1", "$(var sim)")])
    first, second = graph.nodes
    run = search_module.Search.run

    def slow(self: search_module.Search, *args: Any, **kwargs: Any) -> Any:
        started = time.thread_time()
        while time.thread_time() - started < 0.2:  # a costly question
            pass
        return run(self, *args, **kwargs)

    monkeypatch.setattr(search_module.Search, "run", slow)
    _ANSWERS.clear()
    graph._reasoner = reasoner = Reasoner(graph, SolverBudget(0.3))  # type: ignore[attr-defined]
    assert budget_notes(graph) == []
    assert reasoner.together(first.origin.path) is not None  # 0.2 s: answered
    assert not reasoner.budget.ran_out and budget_notes(graph) == []
    assert reasoner.same_name(first.fqn, first.origin.path, second.fqn,
                              second.origin.path) is None  # its search ran out of time
    assert reasoner.budget.ran_out and reasoner.budget.remaining() < 0
    asked = reasoner.budget.left
    assert reasoner.invalid_value((), first.origin.path[0]) is None
    assert reasoner.budget.left == asked  # not asked at all
    [note] = budget_notes(graph)
    assert note.code == "LV003" and "not fully judged" in note.message
    assert note.span.file == graph.root


def test_a_search_stops_when_the_time_is_spent(tmp_path: Path) -> None:
    from launchverify.smt.search import Search

    graph = graph_of(tmp_path, [("cam", "r1", "$(var sim)"), ("cam", "r1", "$(var sim)")])
    guards = list(graph.nodes[0].origin.path)
    reasoner = reasoner_for(graph)
    stopped = Search(reasoner.domains, graph.inputs(), out_of_time=lambda: True)
    tried = stopped.run(Mode.SWITCHES, guards, lambda r: True)
    assert tried.found is None and not tried.exhaustive  # proved nothing
    assert Search(reasoner.domains, graph.inputs()).run(
        Mode.SWITCHES, guards, lambda r: True).found is not None


def test_z3_waits_no_longer_than_the_budget_left() -> None:
    """A hard question (10 pigeons) with 0.3 s left is cut at 0.3 s, and that is no
    answer another root may reuse; with its own limit (2 s) it is "cannot tell"."""
    import time

    from launchverify.smt.budget import BudgetSpent, SolverBudget
    from launchverify.smt.solver import Z3Backend

    backend = Z3Backend({}, {}, SolverBudget(0.3))
    started = time.process_time()  # CPU time (z3's too): load stretches wall time alone
    with pytest.raises(BudgetSpent), backend.budget.question():
        backend._run(_pigeonhole(10))
    assert time.process_time() - started < 1.5 and backend.budget.ran_out


def test_an_unknown_answer_is_no_dangling_target(tmp_path: Path,
                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    """LV502 says a handler's target cannot run where it is registered only when that
    is proved: z3 giving up (a timeout) is no proof."""
    from launchverify.engine import CheckOptions, run_check
    from launchverify.smt import search as search_module
    from launchverify.smt import solver as solver_module
    from launchverify.smt.budget import CannotTell
    from launchverify.smt.search import Outcome

    (tmp_path / "handler.launch.py").write_text(
        "from launch import LaunchDescription\n"
        "from launch.actions import (DeclareLaunchArgument, ExecuteProcess, LogInfo,\n"
        "                            RegisterEventHandler)\n"
        "from launch.conditions import IfCondition\n"
        "from launch.event_handlers import OnProcessExit\n"
        "from launch.substitutions import LaunchConfiguration\n"
        "def generate_launch_description():\n"
        "    proc = ExecuteProcess(cmd=['sleep', '1'],\n"
        "                          condition=IfCondition(LaunchConfiguration('a')))\n"
        "    return LaunchDescription([\n"
        "        DeclareLaunchArgument('a', default_value='false'),\n"
        "        DeclareLaunchArgument('b', default_value='false'),\n"
        "        RegisterEventHandler(OnProcessExit(target_action=proc,\n"
        "                                           on_exit=[LogInfo(msg='x')]),\n"
        "                             condition=IfCondition(LaunchConfiguration('b'))),\n"
        "        proc])\n")
    options = CheckOptions(paths=[tmp_path], workspace=tmp_path, jobs=1)
    _ANSWERS.clear()
    assert run_check(options).findings == []  # a:=true b:=true: it runs where registered

    run = search_module.Search.run

    def undecided(self: search_module.Search, mode: Mode, items: Any, *args: Any,
                  **kwargs: Any) -> Outcome:
        items = list(items)
        if len(items) < 2:  # whether the handler is registered: answered
            return run(self, mode, items, *args, **kwargs)
        return Outcome(None, None, exhaustive=False)  # with its target: for z3

    def gives_up(self: object, solver: object) -> object:
        raise CannotTell  # as a timeout does

    monkeypatch.setattr(search_module.Search, "run", undecided)
    monkeypatch.setattr(solver_module.Z3Backend, "_run", gives_up)
    _ANSWERS.clear()
    assert [f.code for f in run_check(options).findings] == []


def test_forked_processes_share_a_roots_budget(tmp_path: Path) -> None:
    """A root's rules may run in several processes (``-j``): its budget is one."""
    import os
    import time

    from launchverify.smt import share_solver_time
    from launchverify.smt.budget import SOLVER_SECONDS

    for name in ("early", "late"):
        (tmp_path / name).mkdir()
    early = graph_of(tmp_path / "early", [("cam", "r1", "$(var sim)")])
    late = graph_of(tmp_path / "late", [("cam", "r1", "$(var sim)")])
    before = reasoner_for(early)  # made before the fork: it comes along
    share_solver_time([early, late])
    for reasoner in (before, reasoner_for(late)):
        child = os.fork()
        if child == 0:  # a forked process spends 0.3 s of the root's time
            with reasoner.budget.question():
                started = time.thread_time()
                while time.thread_time() - started < 0.3:
                    pass
            os._exit(0)
        os.waitpid(child, 0)
        assert reasoner.budget.left <= SOLVER_SECONDS - 0.3
