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
    from launchverify.smt.reasoner import Reasoner

__all__ = ["Contradiction", "Witness", "reasoner_for"]


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
        from launchverify.smt.reasoner import Reasoner

        found = Reasoner(graph)
        graph._reasoner = found  # type: ignore[attr-defined]
    return found
