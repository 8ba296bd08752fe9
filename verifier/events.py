"""The event graph of a launch: which actions trigger which handlers, which start what.

Built from what the evaluator recorded (``LaunchGraph.handlers``, ``.executed``): an edge
from an action to each handler that its events fire (``OnProcessExit``/``OnProcessStart``/
``OnProcessIO`` on a process, ``OnExecutionComplete`` on any action; a handler without a
target listens to every action of its kind), and an edge from a handler to each action
its entities execute. Actions are identified as launch identifies them: by the action
object, so re-running an action is a loop back to it. A cycle whose handlers are all
registered without ``handle_once`` re-triggers without bound; one that runs a process
object again makes launch raise (``executed more than once``), once or not.

The same links order actions in time: what a handler runs starts after the handler's
event, so after its target executed and, for ``OnProcessExit``, after the target's
process exited (``overlap_guards``: can two processes run at the same time).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING

from launchverify.graph import HandlerRecord, LaunchGraph, NodeRecord, Origin, RerunRecord
from launchverify.ir import actions as a
from launchverify.ir import subst as s
from launchverify.ir.symbolic import PathCondition, Truthy
from launchverify.models.booleans import InvalidBoolean, typed_truth

if TYPE_CHECKING:
    import networkx as nx

PROCESS_EVENTS = ("process_exit", "process_start", "process_io")
PROCESS_ACTIONS = (a.ExecuteProcess, a.Node)


@dataclass(frozen=True)
class Cycle:
    """Handlers and actions that re-trigger each other, in order."""

    steps: tuple[tuple[str, int], ...]  # ("handler", index) or ("action", id)


def fires(handler: HandlerRecord, action: object) -> bool:
    """Return whether an action's events fire a handler."""
    if handler.event in PROCESS_EVENTS:
        if not isinstance(action, PROCESS_ACTIONS):
            return False
    elif handler.event != "execution_complete":
        return False
    return handler.target is None or handler.target is action


def event_graph(graph: LaunchGraph) -> nx.DiGraph:
    """Return the directed event graph (nodes: ("action", id) and ("handler", index))."""
    import networkx as nx

    events = nx.DiGraph()
    actions = {id(record.action): record.action for record in graph.executed}
    for index, handler in enumerate(graph.handlers):
        events.add_node(("handler", index))
        for key, action in actions.items():
            if fires(handler, action):
                events.add_edge(("action", key), ("handler", index))
    for record in graph.executed:
        if record.within is not None:
            events.add_edge(("handler", record.within), ("action", id(record.action)))
    for rerun in graph.reruns:  # launch refuses these, but the loop is there
        events.add_edge(("handler", rerun.within), ("action", id(rerun.action)))
    return events


def loop_closing_reruns(graph: LaunchGraph) -> list[RerunRecord]:
    """Return the refused reruns that their own action's events lead back to (loops)."""
    if not graph.reruns:
        return []
    import networkx as nx

    events = event_graph(graph)
    return [rerun for rerun in graph.reruns
            if ("action", id(rerun.action)) in events
            and nx.has_path(events, ("action", id(rerun.action)), ("handler", rerun.within))]


def rerun_edges(graph: LaunchGraph) -> set[tuple[int, int]]:
    """Return the (handler, action) pairs of refused reruns."""
    return {(rerun.within, id(rerun.action)) for rerun in graph.reruns}


# Order in time: which processes ended before an action executes.

EXITED = "exited"  # its process exited; it runs again only if it respawns
COMPLETED = "completed"  # its execution completed: its process ended for good


def meeting_origin(graph: LaunchGraph, first: NodeRecord,
                   second: NodeRecord) -> Origin | None:
    """Return ``first``'s origin with what it takes to run while ``second`` does.

    ``None`` when the event structure keeps them apart for good; else ``first``'s place
    and path condition, extended by the guards under which they can still meet
    (``overlap_guards``): what LV101 and the wiring rules ask the reasoner about.
    """
    overlap = overlap_guards(graph, first.execution, second.execution)
    if overlap is None:
        return None
    if not overlap:
        return first.origin
    return dataclasses.replace(first.origin, path=(*first.origin.path, *overlap))


def overlap_guards(graph: LaunchGraph, first: int | None,
                   second: int | None) -> PathCondition | None:
    """Return what must hold for two executions' processes to run at the same time.

    ``first`` and ``second`` index ``graph.executed`` (``None``: not known). Returns
    ``None`` when the event structure keeps them apart, ``()`` when nothing does, else the
    guards under which they can still meet (the earlier process's ``respawn`` flag).

    This follows launch: a handler's entities execute when it handles an event, so after
    the handler was registered and, with a target, after the target executed.
    ``OnProcessExit`` fires on each exit of its target (``ProcessExited`` is emitted before
    launch decides to respawn), so what it starts can only meet the target again when the
    target respawns (``respawn`` true, ``respawn_max_retries`` not 0).
    ``OnExecutionComplete`` of a process fires when its last run has ended, respawns
    included. A process object executes only once (``executed more than once``), so the
    target of a handler is the execution of that object in the same evaluation of its
    file. Processes are never started in ``OnShutdown`` handlers: the walker does not
    record them at all.
    """
    if first is None or second is None or first == second:
        return ()
    timeline = _timeline(graph)
    for earlier, later in ((first, second), (second, first)):
        how = timeline.ended_before(later).get(earlier)
        if how == COMPLETED:
            return None
        if how == EXITED:
            return respawn_guards(graph, earlier)
    return ()


def respawn_guards(graph: LaunchGraph, execution: int) -> PathCondition | None:
    """Return when an execution's process starts again after it exits.

    ``None``: never; ``()``: it may (``respawn=True``, or what cannot be read);
    else the guard that its ``respawn`` value is true.
    """
    settings = next((launch.settings for launch in graph.launches
                     if launch.execution == execution), None)
    if settings is None:
        return ()
    if settings.respawn_max_retries == 0:
        return None
    respawn = settings.respawn
    if isinstance(respawn, bool):
        return () if respawn else None
    if isinstance(respawn, s.Text):
        try:
            return () if typed_truth(respawn.text) else None
        except InvalidBoolean:
            return ()  # launch raises when it executes the process; no guess here
    action = graph.executed[execution].action
    where = action.at("respawn") if isinstance(action, a.Action) else None
    return (Truthy(respawn, where=where),)


class _Timeline:
    """What has ended before each execution of one graph (computed on demand, once)."""

    def __init__(self, graph: LaunchGraph) -> None:
        self.graph = graph
        self.runs: dict[int, list[int]] = {}  # id(action) -> its executions
        for index, record in enumerate(graph.executed):
            self.runs.setdefault(id(record.action), []).append(index)
        self.before: dict[int, dict[int, str]] = {}

    def ended_before(self, execution: int) -> dict[int, str]:
        """Return the processes that ended before an action executes, and how."""
        found = self.before.get(execution)
        if found is not None:
            return found
        self.before[execution] = {}  # a loop back here adds nothing (it never fires)
        within = self.graph.executed[execution].within
        found = {} if within is None else self.after_handler(within)
        self.before[execution] = found
        return found

    def after_handler(self, index: int) -> dict[int, str]:
        """Return the processes that ended before a handler's entities execute."""
        handler = self.graph.handlers[index]
        found: dict[int, str] = {}
        if handler.execution is not None:  # it fires once registered
            _merge(found, self.ended_before(handler.execution))
        elif handler.within is not None:
            _merge(found, self.after_handler(handler.within))
        if handler.target is None or handler.custom:
            return found
        target = self.target_execution(handler)
        if target is None:
            return found
        _merge(found, self.ended_before(target))  # its events come after it executed
        if isinstance(self.graph.executed[target].action, PROCESS_ACTIONS):
            if handler.event == "process_exit":
                _merge(found, {target: EXITED})
            elif handler.event == "execution_complete":
                _merge(found, {target: COMPLETED})
        return found

    def target_execution(self, handler: HandlerRecord) -> int | None:
        """Return the execution of a handler's target in the handler's run, if only one."""
        runs = self.runs.get(id(handler.target), [])
        if len(runs) > 1 and handler.execution is not None:
            here = self.graph.executed[handler.execution]
            runs = [i for i in runs if self.graph.executed[i].same_run(here)]
        return runs[0] if len(runs) == 1 else None


def _merge(into: dict[int, str], more: dict[int, str]) -> None:
    for execution, how in more.items():
        if into.get(execution) != COMPLETED:
            into[execution] = how


def _timeline(graph: LaunchGraph) -> _Timeline:
    cache = graph.derived.setdefault("timeline", {})
    found = cache.get(0)
    if not isinstance(found, _Timeline):
        found = _Timeline(graph)
        cache[0] = found
    return found


def unbounded_cycles(graph: LaunchGraph, limit: int = 20) -> Iterator[Cycle]:
    """Yield cycles through handlers that are not ``handle_once`` (at most ``limit``)."""
    if not graph.handlers:
        return
    import networkx as nx

    events = event_graph(graph)
    found = 0
    for component in nx.strongly_connected_components(events):
        if len(component) < 2 and not any(events.has_edge(n, n) for n in component):
            continue
        sub = events.subgraph(component)
        for cycle in nx.simple_cycles(sub):
            handlers = [graph.handlers[i] for kind, i in cycle if kind == "handler"]
            if handlers and (not any(h.once for h in handlers) or refuses(graph, cycle)):
                yield Cycle(tuple(cycle))
                found += 1
                if found >= limit:
                    return
                break  # one cycle per strongly connected part is enough to show


def refuses(graph: LaunchGraph, steps: list[tuple[str, int]] | tuple[tuple[str, int], ...]
             ) -> bool:
    """Return whether a loop runs a process object again (launch raises, once or not)."""
    reruns = rerun_edges(graph)
    return any(kind == "handler" and (key, steps[(p + 1) % len(steps)][1]) in reruns
               for p, (kind, key) in enumerate(steps))


def describe_action(action: object) -> str:
    """Return how an action is called in messages (a node's name, a command...)."""
    if isinstance(action, a.Node):
        for part in (action.name, action.executable):
            if part is not None:
                return part.describe()
        return "a node"
    if isinstance(action, a.ExecuteProcess) and action.process.name is not None:
        return action.process.name.describe()
    if isinstance(action, a.ExecuteProcess) and action.cmd:
        return action.cmd[0].describe()
    return f"the {getattr(action, 'kind', 'action')}"
