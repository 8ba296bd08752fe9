"""``OnStateTransition`` handlers whose labels no lifecycle event carries.

launch_ros compares ``transition``, ``start_state`` and ``goal_state`` with the event's
labels by ``==``: a misspelled state (``'activated'``, ``'Active'``), a state pair no single
event has (``'unconfigured'`` -> ``'inactive'``) or, before rolling, any ``transition``
makes a handler that never fires, silently. The model (``models/lifecycle.py``) says why;
this module finds the handlers, with where the frontend saw their labels written, so
that LV508 points at the argument to fix and the bring-up search never fires them.
"""

from __future__ import annotations

from dataclasses import dataclass

from launchverify.graph import HandlerRecord, LaunchGraph
from launchverify.models import distros
from launchverify.models import lifecycle as lc
from launchverify.span import Span


@dataclass(frozen=True)
class DeadHandler:
    """A handler that never fires: which, why, and where the label to change is written."""

    handler: HandlerRecord
    problem: lc.NeverMatches
    span: Span  # the argument at fault (the handler when it cannot be found)


def never_fires(handler: HandlerRecord) -> lc.NeverMatches | None:
    """Return why a state-transition handler can never fire (``None``: it may).

    A handler with its own matcher ignores the labels (launch_ros uses the matcher alone).
    """
    if handler.event != "state_transition" or handler.custom or not handler.filters:
        return None
    return lc.never_matches(handler.filters, distros.current())


def dead_handlers(graph: LaunchGraph) -> list[DeadHandler]:
    """Return the handlers of a graph whose labels no event carries (those that may run)."""
    cache = graph.derived.setdefault("lifecycle_labels", {})
    found = cache.get(distros.current())
    if isinstance(found, list):
        return found
    out = []
    for handler in graph.handlers:
        problem = never_fires(handler)
        if problem is None or graph.runs(handler.origin) is False:
            continue
        out.append(DeadHandler(handler, problem,
                               argument_span(handler, problem.field)))
    cache[distros.current()] = out
    return out


def argument_span(handler: HandlerRecord, field: str) -> Span:
    """Return where ``field=`` is written for a handler (the registration when unknown)."""
    return dict(handler.filter_spans).get(field, handler.origin.span)
