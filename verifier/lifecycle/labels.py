"""``OnStateTransition`` handlers whose labels no lifecycle event carries.

launch_ros compares ``transition``, ``start_state`` and ``goal_state`` with the event's
labels by ``==``: a misspelled state (``'activated'``, ``'Active'``), a state pair no single
event has (``'unconfigured'`` -> ``'inactive'``) or, before rolling, any ``transition``
makes a handler that never fires, silently. The model (``models/lifecycle.py``) says why;
this module finds the handlers and where their labels are written, so that LV504 points
at the argument to fix and the bring-up search never fires them.
"""

from __future__ import annotations

import ast
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path

from launchverify.graph import HandlerRecord, LaunchGraph
from launchverify.models import distros
from launchverify.models import lifecycle as lc
from launchverify.span import Span
from launchverify.workspace import reading


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
                               argument_span(handler.origin.span, problem.field,
                                             problem.value)))
    cache[distros.current()] = out
    return out


def argument_span(span: Span, field: str, value: str) -> Span:
    """Return where ``field=`` is written for the handler registered at ``span``.

    The keyword inside the registration comes first (a literal with that value before
    any other); else the one ``OnStateTransition(...)`` call of the file with that
    literal (a handler built apart and registered later); else the registration itself.
    """
    keywords = _keywords(span.file)
    if not keywords:
        return span
    end = span.end_line or span.line
    inside = [k for k in keywords if k.field == field and span.line <= k.line
              and k.end_line <= end]
    inside.sort(key=lambda k: k.value != value)
    if inside:
        return inside[0].span(span.file)
    elsewhere = [k for k in keywords if k.field == field and k.value == value and k.handler]
    return elsewhere[0].span(span.file) if len(elsewhere) == 1 else span


@dataclass(frozen=True)
class _Keyword:
    """One keyword argument of a call in a Python file."""

    field: str
    value: object  # the literal given (``None``: not a literal)
    handler: bool  # an argument of ``OnStateTransition(...)``
    line: int
    column: int
    end_line: int
    end_column: int

    def span(self, file: Path) -> Span:
        return Span(file, self.line, self.column + 1, self.end_line, self.end_column + 1)


def _keywords(file: Path) -> tuple[_Keyword, ...]:
    """Return the label keywords of a Python file (none when it cannot be read)."""
    if file.suffix != ".py":
        return ()
    try:
        stat = file.stat()
    except OSError:
        return ()
    return _parsed(file, stat.st_mtime_ns, stat.st_size)


@lru_cache(maxsize=64)
def _parsed(file: Path, mtime: int, size: int) -> tuple[_Keyword, ...]:
    """Return the label keywords of one version of a file (cached by its stamp)."""
    try:
        tree = ast.parse(reading.read_file(file), filename=str(file))
    except (OSError, SyntaxError, ValueError):
        return ()
    out = []
    for node in ast.walk(tree):
        if not isinstance(node, ast.Call):
            continue
        function = node.func
        name = (function.attr if isinstance(function, ast.Attribute) else
                function.id if isinstance(function, ast.Name) else "")
        for keyword in node.keywords:
            if keyword.arg not in lc.FILTER_FIELDS or keyword.end_lineno is None:
                continue
            value = keyword.value.value if isinstance(keyword.value, ast.Constant) else None
            out.append(_Keyword(keyword.arg, value, name == "OnStateTransition",
                                keyword.lineno, keyword.col_offset, keyword.end_lineno,
                                keyword.end_col_offset or keyword.col_offset))
    return tuple(out)
