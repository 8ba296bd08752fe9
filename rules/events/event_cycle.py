"""LV501 event-cycle."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.events import Cycle, describe_action, refuses, unbounded_cycles
from launchverify.graph import LaunchGraph
from launchverify.ir.symbolic import PathCondition
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity
from launchverify.smt import reasoner_for


class EventCycle(Rule):
    """Event handlers that re-trigger each other without end.

    ## What it does
    Builds the launch's event graph (which action's start, exit, output or completion
    fires which handler, and which actions each handler runs) and reports a loop through
    handlers that are not `handle_once`: two processes whose exits start each other, an
    `OnProcessExit` that restarts its own target, an `OnProcessStart` that starts the
    process it listens to. A loop that runs one process object again makes launch raise
    (`executed more than once`) the moment it closes, even through `handle_once`
    handlers: that failure is reported here, not as LV002. The message follows the loop.
    Loops whose conditions cannot hold together are not reported; `respawn` (bounded or
    not) is how ROS 2 restarts a process and is not a loop here.

    ## Why it matters
    The launch never settles: processes restart forever, each restart spawning the next,
    and a crash loop is hidden behind logs that scroll by; or, when the loop comes back to
    the same process object, launch stops with `Caught exception in launch`. Supervision belongs to
    `respawn=True` with `respawn_max_retries`, which is bounded and visible.

    ## Example
    ```python
    driver = Node(package='acme', executable='driver')
    RegisterEventHandler(OnProcessExit(target_action=driver, on_exit=[driver]))
    ```

    ## Fix
    Use `respawn=True, respawn_max_retries=N` on the node, or `handle_once=True` on the
    handler, or end the loop with `Shutdown()`.
    """

    code = "LV501"
    slug = "event-cycle"
    severity = Severity.ERROR
    message = "event handlers re-trigger each other {outcome}: {loop}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        for found in unbounded_cycles(graph):
            if reasoner_for(graph).together(*paths(graph, found)) is None:
                continue  # the conditions along the loop exclude each other
            cycle = starting_at_first_handler(found)
            first = cycle.steps[1][1]
            handler = graph.handlers[first]
            yield self.finding(
                handler.origin,
                related=tuple(Related(graph.handlers[i].origin.span, "part of the loop")
                              for kind, i in cycle.steps if kind == "handler" and i != first),
                loop=describe(graph, cycle),
                outcome=("and launch raises when the loop closes ('executed more than once')"
                         if refuses(graph, cycle.steps) else "without end"),
            )


def starting_at_first_handler(cycle: Cycle) -> Cycle:
    """Rotate a loop to start at the action before its earliest registered handler."""
    steps = list(cycle.steps)
    first = min((p for p, (kind, key) in enumerate(steps) if kind == "handler"),
                key=lambda p: steps[p][1])
    start = (first - 1) % len(steps)
    return Cycle(tuple(steps[start:] + steps[:start]))


def paths(graph: LaunchGraph, cycle: Cycle) -> list[PathCondition]:
    """Return the path conditions of every handler and action of a loop."""
    out: list[PathCondition] = []
    for kind, key in cycle.steps:
        if kind == "handler":
            out.append(graph.handlers[key].origin.path)
        else:
            record = next(r for r in graph.executed if id(r.action) == key)
            out.append(record.origin.path)
    return out


def describe(graph: LaunchGraph, cycle: Cycle) -> str:
    """Return the loop as text: ``driver exits -> OnProcessExit (a.py:12) runs ...``."""
    parts: list[str] = []
    steps = list(cycle.steps)
    for position, (kind, key) in enumerate(steps):
        if kind == "action":
            label = action_label(graph, key)
            following = steps[(position + 1) % len(steps)]
            event = graph.handlers[following[1]].event if following[0] == "handler" else ""
            parts.append(f"{label} {_EVENT_VERBS.get(event, 'runs')}")
        else:
            handler = graph.handlers[key]
            parts.append(f"{_HANDLER_NAMES.get(handler.event, handler.event)} "
                         f"({handler.origin.span.short()}) runs")
    first = steps[0]
    closing = action_label(graph, first[1]) if first[0] == "action" else "it"
    return " ".join(parts) + f" {closing} again"


def action_label(graph: LaunchGraph, key: int) -> str:
    """Return how the action with this identity is called in messages."""
    return describe_action(next(r.action for r in graph.executed if id(r.action) == key))


_EVENT_VERBS = {"process_exit": "exits ->", "process_start": "starts ->",
                "process_io": "prints ->", "execution_complete": "completes ->"}
_HANDLER_NAMES = {"process_exit": "OnProcessExit", "process_start": "OnProcessStart",
                  "process_io": "OnProcessIO", "execution_complete": "OnExecutionComplete"}
