"""The SMT layer: questions about every argument assignment, answered with z3.

Rules ask ``reasoner_for(graph)`` (``reasoner.Reasoner``): can these path conditions hold
together, can this condition never or always hold, can it take a value launch rejects, can
two names be equal. They get plain answers (``types.Witness``, ``types.Contradiction``)
and never see z3, which is imported only when the first question is asked.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING

from launchverify.smt.types import Contradiction, Witness

if TYPE_CHECKING:
    from launchverify.graph import LaunchGraph
    from launchverify.rule import Finding
    from launchverify.smt.reasoner import Reasoner

__all__ = ["Contradiction", "Witness", "budget_notes", "reasoner_for", "share_solver_time"]


def solver_queries(graphs: Iterable[LaunchGraph]) -> int:
    """Return how many times z3 was asked about these graphs (``check --statistics``)."""
    return sum(graph.queries_elsewhere + (found.queries if found is not None else 0)
               for graph in graphs
               if (found := getattr(graph, "_reasoner", None)) is not None
               or graph.queries_elsewhere)


def reasoner_for(graph: LaunchGraph) -> Reasoner:
    """Return the graph's reasoner (one per graph, created on first use)."""
    found: Reasoner | None = getattr(graph, "_reasoner", None)
    if found is None:
        from launchverify.smt.budget import SolverBudget
        from launchverify.smt.reasoner import Reasoner

        found = Reasoner(graph, SolverBudget(account=getattr(graph, "_solver_time", None)))
        graph._reasoner = found  # type: ignore[attr-defined]
    return found


def share_solver_time(graphs: list[LaunchGraph]) -> None:
    """Make every process forked from now on count each root's solver time in one place.

    Each process has reasoners of its own; the budget of a root is one for all of them.
    """
    from launchverify.smt.budget import shared_accounts

    reasoners = [getattr(graph, "_reasoner", None) for graph in graphs]
    spent = [r.budget.account.spent() if r is not None else 0.0 for r in reasoners]
    for graph, reasoner, account in zip(graphs, reasoners, shared_accounts(len(graphs), spent),
                                        strict=True):
        graph._solver_time = account  # type: ignore[attr-defined]
        if reasoner is not None:
            reasoner.budget.account = account


def budget_notes(graph: LaunchGraph) -> list[Finding]:
    """Return the LV003 info saying a root's solver budget ran out, if it did (here).

    Whoever runs rules adds it to each rule's findings on the graph once it ran out (the
    merge keeps one): a question left unanswered claims nothing, so the root was not
    fully judged, and the user should know.
    """
    found: Reasoner | None = getattr(graph, "_reasoner", None)
    if found is None or not found.budget.ran_out:
        return []
    from launchverify.rules.health.unmodeled_construct import UnmodeledConstruct
    from launchverify.span import Span

    seconds = f"{found.budget.seconds:g}"
    return [UnmodeledConstruct().finding(Span.of_file(graph.root), text=(
        f"not fully judged: the questions about its argument values took {seconds} s of "
        "solver time, the most one launch file may take; those left are unanswered, and "
        "no finding rests on them"))]
