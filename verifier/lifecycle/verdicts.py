"""What the lifecycle search means: deadlocks, refused transitions, unknown managed nodes.

Each function turns one analysis into verdicts that the lifecycle rules print. Claims of
absence ("never fires", "no such node") are made only when the system is complete: every
trigger followed, every name known, the search not cut short. They come as answers to
questions (a place and what is asked of it) that the rules put to every evaluation of a
file (``rule.Poll``): a file evaluated alone may lack what an includer supplies.
"""

from __future__ import annotations

import dataclasses
from collections import Counter
from dataclasses import dataclass
from typing import NamedTuple

from launchverify.findings.trace import Step
from launchverify.graph import LaunchGraph, Origin
from launchverify.lifecycle import Analysis
from launchverify.lifecycle.explore import Source, Where, verb
from launchverify.lifecycle.labels import dead_handlers
from launchverify.lifecycle.system import Block, Reaction
from launchverify.models import lifecycle as lc
from launchverify.models.ros_names import node_fqn
from launchverify.rule import Finding, Related, Rule
from launchverify.span import Span
from launchverify.suggest import typo_of
from launchverify.workspace.package_contents import unnamed_node_names
from launchverify.workspace.packages import PackageIndex

# The events of a bring-up that succeeds: configure, then activate.
BRINGUP_EVENTS = (
    lc.TransitionEvent("configure", "unconfigured", "configuring"),
    lc.TransitionEvent("transition_success", "configuring", "inactive"),
    lc.TransitionEvent("activate", "inactive", "activating"),
    lc.TransitionEvent("transition_success", "activating", "active"),
)
ORDER = ("unconfigured", "configuring", "inactive", "activating", "active")


Question = tuple[str, int, int, str]  # file, line, column, what is asked there (numbered)


class Questions:
    """Asks questions in one evaluation, numbering those asked at one place.

    A helper function in a launch file makes many handlers at one line; the k-th of them
    is the same handler in every evaluation of the file.
    """

    def __init__(self) -> None:
        self.asked: Counter[Question] = Counter()

    def __call__(self, origin: Origin | Span, words: str = "") -> Question:
        """Return a question about a place, the same in every evaluation of its file."""
        span = origin.span if isinstance(origin, Origin) else origin
        base = (str(span.file), span.line, span.column, words)
        self.asked[base] += 1
        return (*base[:3], f"{words}#{self.asked[base]}")


@dataclass(frozen=True)
class Verdict:
    """One thing to report: where, what, the places that explain it, how to get there."""

    origin: Origin | Span
    message: str
    related: tuple[tuple[Span, str], ...] = ()
    trace: tuple[Step, ...] = ()


def report(rule: Rule, verdict: Verdict) -> Finding:
    """Return the finding a lifecycle rule makes of a verdict (message template ``{text}``)."""
    return rule.finding(verdict.origin, text=verdict.message, trace=verdict.trace,
                        related=tuple(Related(span, words) for span, words in verdict.related))


def judged(graph: LaunchGraph, analysis: Analysis) -> bool:
    """Return whether absence claims can be made on this graph."""
    return analysis.system.complete and analysis.exploration.complete


# ----------------------------------------------------------------------------- LV504


def unanswerable_requests(graph: LaunchGraph,
                          analysis: Analysis) -> list[tuple[Question, Verdict | None]]:
    """Ask of every request whether it has a lifecycle node to go to (absence claims)."""
    if not judged(graph, analysis):
        return []
    system, ask = analysis.system, Questions()
    answers: list[tuple[Question, Verdict | None]] = [
        (ask(r.origin, r.label), None) for r in system.requests]
    answers += [(ask(refusal.origin, refusal.label),
                 Verdict(refusal.origin, f"{refusal.label}: {refusal.reason}"))
                for refusal in system.refusals]
    return answers


# ----------------------------------------------------------------------------- LV508


def impossible_handler_pairs(graph: LaunchGraph) -> list[Verdict]:
    """``OnStateTransition`` labels rcl publishes, but never together in one event.

    The handler awaits a transition the node cannot take from that state
    (``'unconfigured'`` -> ``'inactive'`` passes through ``'configuring'``): LV504.
    """
    return _dead_label_verdicts(graph, pair=True)


def unknown_handler_labels(graph: LaunchGraph) -> list[Verdict]:
    """``OnStateTransition`` labels rcl never publishes in their field: LV508."""
    return _dead_label_verdicts(graph, pair=False)


def _dead_label_verdicts(graph: LaunchGraph, pair: bool) -> list[Verdict]:
    """Return the handlers that never fire, of one kind (``pair`` or not).

    Each at the argument to change, with the label the author most likely meant.
    """
    out = []
    for dead in dead_handlers(graph):
        problem = dead.problem
        if problem.pair != pair:
            continue
        message = (f"{problem.argument} matches no lifecycle event, so this handler never "
                   f"fires and what it runs never starts: {problem.reason}")
        if problem.hint is not None:
            message += (f" ({problem.hint})" if problem.hint.startswith("leave out") else
                        f" (did you mean {problem.hint}?)")
        related = (() if dead.span == dead.handler.origin.span else
                   ((dead.handler.origin.span, "the handler that never fires"),))
        out.append(Verdict(dataclasses.replace(dead.handler.origin, span=dead.span), message,
                           related))
    return out


class _Case(NamedTuple):
    """One refusal the search found: who asked, of which node, in which state, and why."""

    source: Source
    node: int
    state: str
    where: Where
    cause: tuple[str, int] | None  # the asker that last moved the node (None: its start)


def refused_transitions(graph: LaunchGraph, analysis: Analysis) -> list[Verdict]:
    """Requests that can reach a node in a state where rcl refuses them (or too early).

    A refusal caused by another asker that is refused on its own is left to that one (an
    ``activate`` sent at launch makes the handler's later ``activate`` fail too). Askers
    that fail only because of each other (autostart and a manager both driving a node)
    are one finding: whichever comes second is refused.
    """
    cases_of: dict[tuple[str, int], list[_Case]] = {}
    for (source, node, state), where in analysis.exploration.refused.items():
        cause = _cause(analysis, where, node)
        cases_of.setdefault((source.kind, source.ref), []).append(_Case(
            source, node, state, where, None if cause is None else (cause.kind, cause.ref)))
    for cases in cases_of.values():
        cases.sort(key=lambda case: (case.cause is not None, case.where.state))
    alone = {asker for asker, cases in cases_of.items()
             if any(case.cause is None or case.cause not in cases_of for case in cases)
             or all(case.cause == asker for case in cases)}  # refused after its own move
    out = [_refusal_verdict(analysis, cases_of[asker][0]) for asker in sorted(alone)]
    rivals = {asker: {c.cause for c in cases if c.cause not in (None, asker)}
              for asker, cases in cases_of.items() if asker not in alone}
    for group in _rival_groups({a: causes for a, causes in rivals.items()
                                if not causes & alone}):
        out.append(_rivals_verdict(analysis, [
            next(c for c in cases_of[asker] if c.cause not in (None, asker)) for asker in group]))
    return out


def _rival_groups(rivals: dict[tuple[str, int], set[tuple[str, int]]]
                  ) -> list[list[tuple[str, int]]]:
    """Return the askers that fail only because of each other, in groups."""
    import networkx as nx

    graph = nx.Graph()
    graph.add_nodes_from(rivals)
    graph.add_edges_from((a, b) for a, causes in rivals.items() for b in causes if b in rivals)
    return sorted(sorted(group) for group in nx.connected_components(graph))


def _cause(analysis: Analysis, where: Where, node: int) -> Source | None:
    """Return what last moved a node on the way to a refusal (``None``: its start)."""
    search = analysis.exploration.searches[where.part]
    state_id = where.state
    while state_id > 0:
        parent, _move, effects = search.parents[state_id]
        for effect in reversed(effects):
            if (effect.kind == "state" and effect.key == node
                    and effect.label in lc.PRIMARY_STATES):
                return effect.source
        state_id = parent
    return None


def _refusal_verdict(analysis: Analysis, case: _Case) -> Verdict:
    system = analysis.system
    source, node, state, where = case.source, case.node, case.state, case.where
    fqn = system.nodes[node].fqn
    related: list[tuple[Span, str]] = []
    if case.cause is not None:
        label, origin = _source_label(analysis, Source(*case.cause, 0))
        related.append((origin.span, f"{fqn} was made {state} by {label}"))
    trace = analysis.exploration.trace(where)
    if source.kind == "manager":
        manager = system.managers[source.ref]
        name = manager.spec.fqn or "the lifecycle manager"
        wanted = where.move.action if where.move is not None else "configure"
        return Verdict(manager.spec.record.origin,
                       f"{name} asks {fqn} to {wanted} while it is {state}: rcl refuses the "
                       "transition and the manager aborts the whole bring-up",
                       tuple(related), trace)
    request = system.requests[source.ref]
    transition = request.transitions[source.step]
    if not state:
        message = (f"{request.label} can reach launch before {fqn} is started: launch "
                   f"drops it and {fqn} is never asked to {verb(transition)}")
    else:
        message = (f"{request.label} can reach {fqn} while it is {state}: rcl refuses to "
                   f"{verb(transition)} from {state} and the node stays {state}")
    return Verdict(request.origin, message, tuple(related), trace)


def _rivals_verdict(analysis: Analysis, cases: list[_Case]) -> Verdict:
    """One finding for askers that each drive a node the others have already moved."""
    labelled = sorted(((_source_label(analysis, case.source), case) for case in cases),
                      key=lambda item: (item[0][0], item[0][1].span.line))
    (label, origin), first = labelled[0]
    others = [other for (other, _), _ in labelled[1:]]
    fqns = sorted({analysis.system.nodes[case.node].fqn for case in cases})
    wanted = (first.where.move.action if first.source.kind == "manager"
              and first.where.move is not None else
              verb(analysis.system.requests[first.source.ref].transitions[first.source.step])
              if first.source.kind == "request" else "configure")
    message = (f"{label} and {' and '.join(others)} both drive {', '.join(fqns)}: whichever "
               f"comes second finds it {first.state}, and rcl refuses to {wanted} from "
               f"{first.state}")
    if any(case.source.kind == "manager" for case in cases):
        message += " (a refused manager aborts its whole bring-up)"
    related = tuple((o.span, f"{other} also drives {', '.join(fqns)}")
                    for (other, o), _ in labelled[1:])
    return Verdict(origin, message + "; let one of them drive it", related,
                   analysis.exploration.trace(first.where))


def _source_label(analysis: Analysis, source: Source) -> tuple[str, Origin]:
    system = analysis.system
    if source.kind == "manager":
        manager = system.managers[source.ref]
        return manager.spec.fqn or "the lifecycle manager", manager.spec.record.origin
    request = system.requests[source.ref]
    return request.label, request.origin


# ----------------------------------------------------------------------------- LV503


def deadlocks(graph: LaunchGraph, analysis: Analysis) -> list[tuple[Question, Verdict | None]]:
    """Ask of every bring-up handler and manager whether it can wait forever."""
    if not judged(graph, analysis):
        return []
    system, exploration = analysis.system, analysis.exploration
    refused_nodes = {node for (_, node, _) in exploration.refused}
    driven = _driven_nodes(analysis)
    waiting: dict[int, int] = {}  # never-firing bring-up handler -> the node it waits for
    dead: list[int] = []  # handlers whose labels no event carries
    asked: dict[int, Question] = {}
    ask = Questions()
    for key, reaction in system.reactions.items():
        if (reaction.event != "state_transition"
                or reaction.registered not in exploration.happened):
            continue
        if reaction.never is not None:
            asked[key] = ask(reaction.origin, "handler")
            dead.append(key)
            continue
        if (reaction.nodes is None or len(reaction.nodes) != 1
                or not any(reaction.matches(e) for e in BRINGUP_EVENTS)):
            continue
        asked[key] = ask(reaction.origin, "handler")
        if key in exploration.fired:
            continue
        node = next(iter(reaction.nodes))
        if (node in exploration.incomplete_nodes or node not in driven
                or node in refused_nodes):
            continue
        waiting[key] = node
    verdicts: dict[int, Verdict] = {}
    for key in dead:
        found = _dead_verdict(graph, analysis, key)
        if found is not None:
            verdicts[key] = found
    # a handler waiting for what only a dead handler would do is that one's consequence
    blockers = set(waiting) | set(verdicts)
    needs = {key: _needs(analysis, key, node, blockers) for key, node in waiting.items()}
    in_cycle: set[int] = set()
    for cycle in _cycles(needs):
        in_cycle.update(cycle)
        verdicts[cycle[0]] = _cycle_verdict(analysis, cycle, waiting)
    for key, node in waiting.items():
        if key in in_cycle or needs[key]:
            continue  # part of a cycle, or waiting on another handler that never fires
        verdicts[key] = _waiting_verdict(analysis, system.reactions[key], node)
    out = [(words, verdicts.get(key)) for key, words in asked.items()
           if key in verdicts or key not in waiting]  # the rest of a cycle is not asked
    stuck = _stuck_managers(analysis)
    out += [(ask(m.spec.record.origin, "manager"), stuck.get(index))
            for index, m in enumerate(system.managers)]
    return out


def _driven_nodes(analysis: Analysis) -> set[int]:
    """Return the nodes the launch itself moves (requests, managers that start up)."""
    system = analysis.system
    driven = {request.node for request in system.requests}
    for manager in system.managers:
        if manager.spec.autostart:
            driven.update(n for n in manager.nodes if n is not None)
    return driven


def _needs(analysis: Analysis, key: int, node: int, blockers: set[int]) -> set[int]:
    """Return the never-firing handlers whose blocks hold what would move ``node`` on.

    Only requests rcl would accept where the node stops count (an ``activate`` does not
    help a node that was never configured), and a handler never waits for itself.
    """
    system, exploration = analysis.system, analysis.exploration
    reached = exploration.reached.get(node, {})
    furthest = max((s for s in reached if s in ORDER), key=ORDER.index,
                   default="unconfigured")
    found: set[int] = set()
    blocks: list[Block] = [r.block for r in system.requests if r.node == node
                           and lc.resolve(furthest, r.transitions[0]) is not None]
    if node not in exploration.reached:
        blocks.append(system.nodes[node].block)
    for block in blocks:
        if block not in exploration.happened and block[0] in blockers and block[0] != key:
            found.add(block[0])
    return found


def _furthest(analysis: Analysis, node: int) -> str | None:
    """Return the furthest bring-up state a node reaches (``None``: never started)."""
    reached = analysis.exploration.reached.get(node, {})
    return max((s for s in reached if s in ORDER), key=ORDER.index, default=None)


def _nested(graph: LaunchGraph, key: int) -> set[int]:
    """Return a handler and every handler registered, directly or not, by what it runs."""
    out = set()
    for index in range(len(graph.handlers)):
        within: int | None = index
        while within is not None and within != key:
            within = graph.handlers[within].within
        if within == key:
            out.add(index)
    return out


def _dead_verdict(graph: LaunchGraph, analysis: Analysis, key: int) -> Verdict | None:
    """What a handler that never fires would bring up, and so never happens (or ``None``).

    Counted: a ``configure``/``activate`` request its node would accept where it stops,
    a lifecycle node it starts that never starts, and any other process it starts. Nodes
    a lifecycle manager waits for are left to the manager's finding, which names the
    handler.
    """
    from launchverify.events import describe_action
    from launchverify.ir import actions as a

    system, exploration = analysis.system, analysis.exploration
    reaction = system.reactions[key]
    assert reaction.never is not None
    nested = _nested(graph, key)
    blocks = [b for b in system.blocks if b[0] in nested and b not in exploration.happened]
    managed = {n for m in system.managers for n in m.nodes if n is not None}
    by_execution = {node.record.execution: index for index, node in enumerate(system.nodes)
                    if node.record.execution is not None}
    lost: dict[tuple[str, int], str] = {}
    related: list[tuple[Span, str]] = []
    trace: tuple[Step, ...] = ()
    for request in system.requests:
        node = request.node
        if request.block not in blocks or node in exploration.incomplete_nodes:
            continue
        wanted = request.transitions[0]
        furthest = _furthest(analysis, node)
        if (furthest is None or verb(wanted) not in ("configure", "activate")
                or lc.resolve(furthest, wanted) is None or ("node", node) in lost):
            continue
        fqn = system.nodes[node].fqn
        lost[("node", node)] = f"{fqn} is never asked to {verb(wanted)} and stays {furthest}"
        related.append((request.origin.span, f"never sent: asks {fqn} to {verb(wanted)}"))
        if not trace:
            trace = exploration.trace(exploration.reached[node][furthest])
    for block in blocks:
        for execution in system.blocks[block].processes:
            record = system.executions[execution]
            started = by_execution.get(execution)
            if started is not None:
                if (started in exploration.reached or started in managed
                        or started in exploration.incomplete_nodes):
                    continue
                words = f"{system.nodes[started].fqn} is never started"
            else:
                kind = "node" if isinstance(record.action, a.Node) else "process"
                words = f"{kind} '{describe_action(record.action)}' never starts"
            if ("process", execution) not in lost:
                lost[("process", execution)] = words
                related.append((record.origin.span, "never started"))
    if not lost:
        return None
    return Verdict(reaction.origin, f"this handler never fires ({reaction.never.argument} "
                   "matches no lifecycle event), so the bring-up it drives never happens: "
                   + "; ".join(lost.values()), tuple(related), trace)


def _cycles(needs: dict[int, set[int]]) -> list[list[int]]:
    import networkx as nx

    graph = nx.DiGraph()
    for key, targets in needs.items():
        for target in targets:
            graph.add_edge(key, target)
    out = []
    for component in nx.strongly_connected_components(graph):
        if len(component) > 1 or any(graph.has_edge(n, n) for n in component):
            cycle = next(iter(nx.simple_cycles(graph.subgraph(component))))
            start = cycle.index(min(cycle))
            out.append(cycle[start:] + cycle[:start])
    return sorted(out)


def _wanted(reaction: Reaction) -> str:
    """Return what a handler waits for, in words."""
    words = {"goal_state": "reach '{}'", "start_state": "leave '{}'",
             "transition": "go through '{}'"}
    return " and ".join(words[name].format(label) for name, label in reaction.filters) or \
        "change state"


def _cycle_verdict(analysis: Analysis, cycle: list[int], waiting: dict[int, int]) -> Verdict:
    system = analysis.system
    parts = []
    for position, key in enumerate(cycle):
        reaction = system.reactions[key]
        previous = cycle[position - 1]  # this handler's block moves what it waits for
        target = system.nodes[waiting[previous]].fqn
        moves = sorted({verb(r.transitions[0]) for r in system.requests
                        if r.block == (key, None) and r.node == waiting[previous]})
        action = f"ask {target} to {'/'.join(moves)}" if moves else f"start {target}"
        parts.append(f"the handler at line {reaction.origin.span.line} waits for "
                     f"{system.nodes[waiting[key]].fqn} to {_wanted(reaction)} before it "
                     f"would {action}")
    first = system.reactions[cycle[0]]
    related = tuple((system.reactions[k].origin.span, "waits in the cycle") for k in cycle[1:])
    return Verdict(first.origin, "bring-up deadlock: " + "; ".join(parts) +
                   ": none of them ever fires", related)


def _waiting_verdict(analysis: Analysis, reaction: Reaction, node: int) -> Verdict:
    system, exploration = analysis.system, analysis.exploration
    fqn = system.nodes[node].fqn
    reached = exploration.reached.get(node, {})
    furthest = max((s for s in reached if s in ORDER), key=ORDER.index, default=None)
    if furthest is None:
        message = (f"the handler waits for {fqn} to {_wanted(reaction)}, but {fqn} is never "
                   "started: it never fires")
        trace: tuple[Step, ...] = ()
    else:
        message = (f"the handler waits for {fqn} to {_wanted(reaction)}, which never "
                   f"happens: {fqn} gets no further than {furthest} and nothing in the "
                   "launch moves it on, so the handler never fires")
        trace = exploration.trace(reached[furthest])
    return Verdict(reaction.origin, message, (), trace)


def _stuck_managers(analysis: Analysis) -> dict[int, Verdict]:
    system, exploration = analysis.system, analysis.exploration
    out = {}
    for index, where in sorted(exploration.manager_stuck.items()):
        manager = system.managers[index]
        if index in exploration.managers_done or any(n is None for n in manager.nodes):
            continue  # completes in some order (a race), or a node is missing (LV505)
        if any(n in exploration.incomplete_nodes for n in manager.nodes if n is not None):
            continue
        missing = [n for n in manager.nodes if n is not None and n not in exploration.reached]
        name = manager.spec.fqn or "the lifecycle manager"
        if missing:
            node = system.nodes[missing[0]]
            starter = node.block[0]
            never = (system.reactions[starter].never
                     if starter is not None and starter in system.reactions else None)
            why = (f"{node.fqn} is started only by the handler at "
                   f"{system.reactions[starter].origin.span.short()}, which never fires"
                   + ("" if never is None else
                      f" ({never.argument} matches no lifecycle event)")
                   if starter is not None and starter in system.reactions else
                   f"{node.fqn} never starts")
        else:
            why = "its nodes never all become available"
        out[index] = Verdict(manager.spec.record.origin,
                             f"{name} never completes its bring-up: it waits for the services "
                             f"of every node it manages, and {why}", (),
                             exploration.trace(where))
    return out


# ----------------------------------------------------------------------------- LV505


@dataclass(frozen=True)
class UnknownManagedNode:
    """A ``node_names`` entry no launched node answers to."""

    manager: Origin
    manager_name: str
    name: str
    resolved: str
    names_span: Span | None
    elsewhere: str | None  # a node with that name in another namespace
    suggestion: str | None


def unknown_managed_nodes(graph: LaunchGraph, analysis: Analysis,
                          packages: PackageIndex | None = None,
                          ) -> list[tuple[Question, UnknownManagedNode | None]]:
    """Ask of every name a lifecycle manager waits for whether a node has it.

    A node named by its own code may be the one when its namespace matches and its
    package's sources give that name (or are not here): then the question is not answered.
    """
    if not graph.complete_as_given():
        return []
    running = [n for n in graph.nodes if graph.runs(n.origin) is not False]
    known = {f for f in (graph.base(n.fqn) for n in running) if f is not None}
    unnamed = [unnamed_node_names(graph, n, packages) for n in running
               if graph.base(n.fqn) is None]

    def may_be(resolved: str) -> bool:
        namespace, _, base = resolved.rpartition("/")
        return any(u is None or (u[0] == (namespace or "/") and (u[1] is None or base in u[1]))
                   for u in unnamed)

    out: list[tuple[Question, UnknownManagedNode | None]] = []
    ask = Questions()
    for manager in analysis.system.managers:
        spec = manager.spec
        if spec.resolved is None or spec.names is None:
            continue
        for name, resolved, node in zip(spec.names, spec.resolved, manager.nodes, strict=True):
            asked = ask(spec.record.origin, name)
            if node is not None or resolved in known:
                out.append((asked, None))
                continue
            if may_be(resolved):
                continue
            base = resolved.rsplit("/", 1)[-1]
            # a node of that name in one other namespace is likely the one meant; in a
            # fleet, where every robot has one, naming another robot's would mislead
            elsewhere = sorted(f for f in known if f.rsplit("/", 1)[-1] == base)
            elsewhere = elsewhere if len(elsewhere) == 1 else []
            siblings = [f for f in known if f.rsplit("/", 1)[0] == resolved.rsplit("/", 1)[0]]
            suggestion = None if elsewhere else typo_of(resolved, siblings)
            out.append((asked, UnknownManagedNode(
                spec.record.origin, spec.fqn or node_fqn(spec.namespace, "lifecycle_manager"),
                name, resolved, spec.names_span, elsewhere[0] if elsewhere else None,
                suggestion)))
    return out
