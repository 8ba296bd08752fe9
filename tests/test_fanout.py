"""Rules shared out between processes give exactly the findings of one process."""

from __future__ import annotations

from pathlib import Path

import pytest

from launchverify.engine import CheckOptions, Report, run_check
from launchverify.parallel import fanout
from launchverify.parallel.fanout import NextPiece, Piece, RuleRun, pieces
from launchverify.registry import all_rules

CORPUS = Path(__file__).resolve().parent.parent / "corpus"
TREES = [CORPUS / "conditions", CORPUS / "naming", CORPUS / "arguments", CORPUS / "parameters",
         CORPUS / "lifecycle", CORPUS / "wiring"]  # (the last two: rules gathering by poll)


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
    assert {"LV503", "LV602", "LV604"} <= {f.code for f in alone.findings}  # polled
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
    fanout._SHARED.update(run=run, pieces=[Piece(tuple(range(len(rules))), (), ())],
                          counter=NextPiece(1))
    try:
        *_, queries, _ = fanout._child()
    finally:
        fanout._SHARED.clear()
    assert sum(queries.values()) == sum(g._reasoner.queries for g in graphs  # type: ignore[attr-defined]
                                        if hasattr(g, "_reasoner")) > 0


def test_pieces_a_failed_child_took_are_run_here(alone: Report,
                                                monkeypatch: pytest.MonkeyPatch) -> None:
    def broken() -> fanout.Collected:
        counter = fanout._SHARED["counter"]
        assert isinstance(counter, NextPiece)
        while counter.take() is not None:  # takes everything, then is lost
            pass
        raise RuntimeError("child lost")

    monkeypatch.setattr(fanout, "MIN_WORK", 0)
    monkeypatch.setattr(fanout, "_child", broken)
    assert _seen(_check(jobs=2)) == _seen(alone)


def test_a_lock_never_given_back_stops_no_one(alone: Report,
                                              monkeypatch: pytest.MonkeyPatch) -> None:
    """A child killed holding the counter's lock: the checking process does the rest."""
    real = NextPiece.__init__

    def held(self: NextPiece, count: int) -> None:
        real(self, count)
        self._next.get_lock().acquire()

    monkeypatch.setattr(fanout, "MIN_WORK", 0)
    monkeypatch.setattr(fanout, "LOCK_SECONDS", 0.01)
    monkeypatch.setattr(NextPiece, "__init__", held)
    assert _seen(_check(jobs=2)) == _seen(alone)


def test_without_semaphores_everything_runs_here(alone: Report,
                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    def refused(self: NextPiece, count: int) -> None:
        raise PermissionError("no /dev/shm")

    monkeypatch.setattr(fanout, "MIN_WORK", 0)
    monkeypatch.setattr(NextPiece, "__init__", refused)
    assert _seen(_check(jobs=2)) == _seen(alone)


def test_the_pieces_cover_each_rule_and_graph_once(alone: Report) -> None:
    rules = list(all_rules())
    run = RuleRun(alone.graphs, rules, None, None, None)  # type: ignore[arg-type]
    gathering = fanout.gathering(rules)
    assert gathering == []  # polling and gathering rules are shared out too
    found = pieces(run, exclude=gathering)
    assert pieces(run, exclude=gathering) == found  # deterministic
    covered = [(r, g) for piece in found for r in piece.whole for g in range(len(alone.graphs))]
    covered += [(r, g) for piece in found for r in piece.split for g in piece.graphs]
    expected = [(r, g) for r in range(len(rules)) if r not in gathering
                for g in range(len(alone.graphs))]
    assert sorted(covered) == sorted(expected)
    whole = {r for piece in found for r in piece.whole}
    assert whole == {r for r, rule in enumerate(rules) if getattr(rule, "every_context", False)}
