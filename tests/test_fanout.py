"""Rules shared out between processes give exactly the findings of one process."""

from __future__ import annotations

from pathlib import Path

import pytest

from launchverify import fanout
from launchverify.engine import CheckOptions, Report, run_check
from launchverify.fanout import RuleRun, Share, plan
from launchverify.registry import all_rules

CORPUS = Path(__file__).resolve().parent.parent / "corpus"
TREES = [CORPUS / "conditions", CORPUS / "naming", CORPUS / "arguments", CORPUS / "parameters"]


def _check(jobs: int) -> Report:
    return run_check(CheckOptions(paths=TREES, workspace=CORPUS, jobs=jobs))


def _seen(report: Report) -> list[tuple[object, ...]]:
    return [(f.code, str(f.span.file), f.span.line, f.span.column, f.message, f.severity,
             f.chain, f.witness) for f in report.findings]


@pytest.fixture(scope="module")
def alone() -> Report:
    return _check(jobs=1)


def test_shared_out_findings_are_those_of_one_process(alone: Report,
                                                      monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(fanout, "MIN_WORK", 0)
    shared = _check(jobs=3)
    assert len(alone.findings) > 50  # the trees hold many findings of many rules
    assert _seen(shared) == _seen(alone)


def test_a_child_says_how_many_solver_queries_it_asked(alone: Report) -> None:
    """--statistics counts the z3 queries asked in forked children too."""
    from launchverify.engine import _isolated, dead
    from launchverify.rule import RuleContext

    graphs = alone.graphs
    for graph in graphs:  # as a child that makes its own reasoners
        if hasattr(graph, "_reasoner"):
            delattr(graph, "_reasoner")
    rules = list(all_rules())
    run = RuleRun(graphs, rules, RuleContext(), _isolated, dead)
    fanout._SHARED["run"] = run
    try:
        _, queries = fanout._child(Share(tuple(range(len(rules))), (), ()))
    finally:
        fanout._SHARED.clear()
    assert sum(queries.values()) == sum(g._reasoner.queries for g in graphs  # type: ignore[attr-defined]
                                        if hasattr(g, "_reasoner")) > 0


def test_a_failed_child_share_is_run_here(alone: Report,
                                          monkeypatch: pytest.MonkeyPatch) -> None:
    def broken(share: Share) -> tuple[fanout.PerGraph, dict[int, int]]:
        raise RuntimeError("child lost")

    monkeypatch.setattr(fanout, "MIN_WORK", 0)
    monkeypatch.setattr(fanout, "_child", broken)
    assert _seen(_check(jobs=2)) == _seen(alone)


def test_the_plan_covers_each_rule_and_graph_once(alone: Report) -> None:
    rules = list(all_rules())
    run = RuleRun(alone.graphs, rules, None, None, None)  # type: ignore[arg-type]
    gathering = [r for r, rule in enumerate(rules) if rule.finish is not fanout.Rule.finish]
    shares = plan(run, 3, exclude=gathering)
    assert plan(run, 3, exclude=gathering) == shares  # deterministic
    assert 1 < len(shares) <= 3
    covered = [(r, g) for share in shares for r in share.whole for g in range(len(alone.graphs))]
    covered += [(r, g) for share in shares for r in share.split for g in share.graphs]
    expected = [(r, g) for r in range(len(rules)) if r not in gathering
                for g in range(len(alone.graphs))]
    assert sorted(covered) == sorted(expected)
    whole = {r for share in shares for r in share.whole}
    assert whole == {r for r, rule in enumerate(rules) if getattr(rule, "every_context", False)}
