"""The event graph of a launch: which actions trigger which handlers, which start what.

Built from what the evaluator recorded (``LaunchGraph.handlers``, ``.executed``): an edge
from an action to each handler that its events fire (``OnProcessExit``/``OnProcessStart``/
``OnProcessIO`` on a process, ``OnExecutionComplete`` on any action; a handler without a
target listens to every action of its kind), and an edge from a handler to each action
its entities execute. Actions are identified as launch identifies them: by the action
object, so re-running an action is a loop back to it. A cycle whose handlers are all
registered without ``handle_once`` re-triggers without bound.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING

from launchverify.graph import HandlerRecord, LaunchGraph
from launchverify.ir import actions as a

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
    return events


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
            if handlers and not any(h.once for h in handlers):
                yield Cycle(tuple(cycle))
                found += 1
                if found >= limit:
                    return
                break  # one cycle per strongly connected part is enough to show


def describe_action(action: object) -> str:
    """Return how an action is called in messages (a node's name, a command...)."""
    if isinstance(action, a.Node):
        for part in (action.name, action.executable):
            if part is not None:
                return part.describe()
        return "a node"
    if isinstance(action, a.ExecuteProcess) and action.cmd:
        return action.cmd[0].describe()
    return f"the {getattr(action, 'kind', 'action')}"
