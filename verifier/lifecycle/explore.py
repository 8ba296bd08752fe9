"""Explicit-state search of a lifecycle bring-up: every order in which things can happen.

A state holds each managed node's lifecycle state (``""`` before its process starts),
the blocks that have executed, the once-handlers and ``LifecycleTransition`` steps
already spent, the pending events (requests on their way to a node, process starts and
exits) and each lifecycle manager's position in its program. A move takes one pending
event, one manager step or, when nothing else can happen, the timer with the shortest
delay: timers are taken to outlast the bring-up events before them. Transitions are
atomic at the node (its service runs one request at a time) and callbacks succeed: a
bring-up that cannot complete even then is broken. Breadth-first search gives each
finding its shortest trace.

The system is first split into independent parts (nodes, the requests and handlers that
touch them, their managers), each searched alone: three managers of 17 nodes each are
three small searches, not one search of their product.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Hashable, Iterator
from dataclasses import dataclass, field
from typing import NamedTuple

from launchverify.findings.trace import Step
from launchverify.lifecycle.system import LAUNCH, Block, Request, System
from launchverify.models import lifecycle as lc

MAX_STATES = 50_000
REDUCE = True  # partial-order reduction (tests compare against the full search)
EMITTING = ("lifecycle_node", "composable_lifecycle_node")  # publish StateTransition events
EVENT_HANDLERS = {"start": ("process_start",), "exit": ("process_exit", "execution_complete"),
                  "done": ("execution_complete",)}


class Item(NamedTuple):
    """A pending event: a request step on its way, or a process start/exit/completion."""

    kind: str  # "event" | "request"
    ref: int  # execution (event) or request
    detail: str  # event: start/exit/done; request: the step, as text


class Source(NamedTuple):
    """What asked for a transition: a request's step, or a manager (for one node)."""

    kind: str  # "request" | "manager"
    ref: int  # the request, or the manager
    step: int  # the request's step, or the manager's node


class Effect(NamedTuple):
    """Something a move caused that findings and traces need."""

    kind: str  # "fired" (key: handler) | "refused" | "state" (key: node)
    key: int
    label: str = ""  # state reached; for a refusal, the node's state ("": not started)
    source: Source | None = None  # what asked (None: the node's process starting)


class Move(NamedTuple):
    """What one step of the search did."""

    kind: str  # "item" | "manager" | "timer" | "start"
    item: Item | None = None
    manager: int = -1
    action: str = ""  # manager: ready/configure/activate
    node: int = -1
    block: Block | None = None


class State(NamedTuple):
    """One state of a part."""

    nodes: tuple[str, ...]
    happened: frozenset[Block]
    spent: frozenset[tuple[str, int, int]]
    pending: tuple[Item, ...]
    timers: frozenset[Block]
    pcs: tuple[int, ...]


class Where(NamedTuple):
    """Where the search saw something: a state, and the move taken from it (if any)."""

    part: int
    state: int
    move: Move | None = None
    effects: tuple[Effect, ...] = ()


RefusalKey = tuple[Source, int, str]  # what asked, the node, the node's state


@dataclass
class Part:
    """One independent part of the system."""

    nodes: list[int]
    requests: set[int]
    reactions: set[int]
    managers: list[int]
    incomplete: bool = False  # holds something whose trigger launchverify cannot follow


@dataclass
class Exploration:
    """What the search found, in the system's own indices."""

    states: int = 0
    complete: bool = True  # False when a part hit ``MAX_STATES``
    parts: int = 0
    reached: dict[int, dict[str, Where]] = field(default_factory=dict)
    refused: dict[RefusalKey, Where] = field(default_factory=dict)
    fired: dict[int, Where] = field(default_factory=dict)
    happened: set[Block] = field(default_factory=set)
    managers_done: set[int] = field(default_factory=set)
    manager_stuck: dict[int, Where] = field(default_factory=dict)
    incomplete_nodes: set[int] = field(default_factory=set)
    searches: list[_Search] = field(default_factory=list, repr=False)

    def trace(self, where: Where) -> tuple[Step, ...]:
        """Return the steps from the start of the launch to a finding."""
        return self.searches[where.part].trace(where)


def explore(system: System) -> Exploration:
    """Search every part of a system."""
    result = Exploration()
    for part in split(system):
        search = _Search(system, part, len(result.searches))
        result.searches.append(search)
        search.run(result)
        result.parts += 1
    return result


# ----------------------------------------------------------------------------- parts


def split(system: System) -> list[Part]:
    """Return the independent parts of a system (union-find over what touches what)."""
    parent: dict[tuple[str, Hashable], tuple[str, Hashable]] = {}

    def find(x: tuple[str, Hashable]) -> tuple[str, Hashable]:
        parent.setdefault(x, x)
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    def union(x: tuple[str, Hashable], y: tuple[str, Hashable]) -> None:
        parent[find(x)] = find(y)

    def tie(element: tuple[str, Hashable], block: Block) -> None:
        """Join an element to whatever makes its block execute."""
        if block == LAUNCH:
            return
        key = block[0]
        if key is None:
            union(element, ("timer", block))
        elif key in system.reactions:
            union(element, ("r", key))
        elif (key, None) in system.unmodelled:
            union(element, ("x", key))

    emitting = [i for i, n in enumerate(system.nodes) if n.record.kind in EMITTING]
    by_execution: dict[int, tuple[str, Hashable]] = {}
    for index, managed in enumerate(system.nodes):
        find(("n", index))
        tie(("n", index), managed.block)
        if managed.record.execution is not None:
            by_execution[managed.record.execution] = ("n", index)
    for request in system.requests:
        union(("q", request.index), ("n", request.node))
        tie(("q", request.index), request.block)
        if request.command is not None:
            by_execution[request.command] = ("q", request.index)
    for key, reaction in system.reactions.items():
        find(("r", key))
        tie(("r", key), reaction.registered)
        watched = reaction.nodes
        if watched is None and reaction.event == "state_transition":
            watched = frozenset(emitting)
        for node in watched or ():
            union(("r", key), ("n", node))
        for execution in reaction.targets or ():
            if execution in by_execution:
                union(("r", key), by_execution[execution])
    for index, manager in enumerate(system.managers):
        find(("m", index))
        tie(("m", index), manager.block)
        for listed in manager.nodes:
            if listed is not None:
                union(("m", index), ("n", listed))
    groups: dict[tuple[str, Hashable], Part] = {}
    for element in list(parent):
        part = groups.setdefault(find(element), Part([], set(), set(), []))
        kind, value = element
        if kind == "x":
            part.incomplete = True
        elif isinstance(value, int):
            {"n": part.nodes.append, "q": part.requests.add, "r": part.reactions.add,
             "m": part.managers.append}[kind](value)
    return [p for p in groups.values() if p.nodes or p.managers]


# ----------------------------------------------------------------------------- search


class _Search:
    """Breadth-first search of one part."""

    def __init__(self, system: System, part: Part, number: int) -> None:
        self.system = system
        self.part = part
        self.number = number
        self.nodes = sorted(part.nodes)
        self.local = {g: i for i, g in enumerate(self.nodes)}
        self.managers = sorted(part.managers)
        self.reactions = {k: system.reactions[k] for k in sorted(part.reactions)}
        self.parents: list[tuple[int, Move, tuple[Effect, ...]]] = []
        self.sequences: dict[int, list[Request]] = {}
        self.commands: set[int] = set()
        for index in part.requests:
            request = system.requests[index]
            if len(request.transitions) > 1:
                self.sequences.setdefault(request.node, []).append(request)
            if request.command is not None:
                self.commands.add(request.command)
        self.timer_blocks = {b for b in system.blocks if b[1] is not None and self.touches(b)}
        self.reaches: dict[tuple[str, int], frozenset[tuple[str, int]]] = {}

    def touches(self, block: Block) -> bool:
        """Return whether a block holds anything of this part."""
        content = self.system.blocks[block]
        return (block[0] in self.reactions
                or any(n in self.local for n in content.starts)
                or any(q in self.part.requests for q in content.requests)
                or any(m in self.managers for m in content.managers)
                or any(r.registered == block for r in self.reactions.values())
                or any(self.listens(e, event) for e in content.actions
                       for event in ("process_start", "process_exit", "execution_complete")))

    # ------------------------------------------------------------------ driver

    def run(self, result: Exploration) -> None:
        effects: list[Effect] = []
        start = self.happen(self.empty(), LAUNCH, effects)
        seen: dict[State, int] = {start: 0}
        self.parents.append((-1, Move("start"), ()))
        for effect in effects:
            self.record(effect, Where(self.number, 0), result)
        queue = deque([start])
        while queue:
            state = queue.popleft()
            here = seen[state]
            self.note(state, result)
            successors = self.reduce(list(self.successors(state)), seen)
            if not successors:
                self.terminal(state, here, result)
            for move, after, done in successors:
                where = Where(self.number, here, move, tuple(done))
                for effect in done:
                    self.record(effect, where, result)
                if after in seen:
                    continue
                if len(seen) >= MAX_STATES:
                    result.complete = False
                    queue.clear()
                    break
                seen[after] = len(self.parents)
                self.parents.append((here, move, tuple(done)))
                queue.append(after)
        result.states += len(seen)
        if self.part.incomplete:
            result.incomplete_nodes.update(self.nodes)

    @staticmethod
    def record(effect: Effect, where: Where, result: Exploration) -> None:
        if effect.kind == "fired":
            result.fired.setdefault(effect.key, where)
        elif effect.kind == "refused" and effect.source is not None:
            result.refused.setdefault((effect.source, effect.key, effect.label), where)
        elif effect.kind == "state":
            result.reached.setdefault(effect.key, {}).setdefault(effect.label, where)

    def note(self, state: State, result: Exploration) -> None:
        result.happened.update(state.happened)
        for index, pc in zip(self.managers, state.pcs, strict=True):
            if pc == self.manager_end(index):
                result.managers_done.add(index)

    def terminal(self, state: State, here: int, result: Exploration) -> None:
        for index, pc in zip(self.managers, state.pcs, strict=True):
            manager = self.system.managers[index]
            if manager.spec.autostart and 0 <= pc != self.manager_end(index):
                result.manager_stuck.setdefault(index, Where(self.number, here))

    def manager_end(self, index: int) -> int:
        return 2 * len(self.system.managers[index].nodes) + 1

    # ------------------------------------------------------------------ reduction

    def reduce(self, successors: list[tuple[Move, State, list[Effect]]],
               seen: dict[State, int]) -> list[tuple[Move, State, list[Effect]]]:
        """Keep one move when it cannot interact with any other (partial-order reduction).

        A move whose reach (every node, handler, manager and process it can ever
        influence) is disjoint from every other enabled move's reach commutes with all
        that they and their consequences do, so exploring it alone loses no node state,
        refusal or firing. Timers wait for quiescence, so none fires in between. A move
        back to a state already seen is not taken alone (a cycle could defer the others
        for ever).
        """
        if (not REDUCE or len(successors) < 2
                or any(m.kind == "timer" for m, _, _ in successors)):
            return successors
        reaches = [self.reach(self.atom(move)) for move, _, _ in successors]
        for position, (reach, successor) in enumerate(zip(reaches, successors, strict=True)):
            if successor[1] in seen:
                continue
            if all(reach.isdisjoint(other) for i, other in enumerate(reaches)
                   if i != position):
                return [successor]
        return successors

    def atom(self, move: Move) -> tuple[str, int]:
        """Return what a move acts on first."""
        if move.kind == "manager":
            return ("m", move.manager)
        assert move.item is not None
        return ("q" if move.item.kind == "request" else "e", move.item.ref)

    def reach(self, atom: tuple[str, int]) -> frozenset[tuple[str, int]]:
        """Return everything a move on ``atom`` can influence, directly or through others."""
        found = self.reaches.get(atom)
        if found is None:
            seen = {atom}
            stack = [atom]
            while stack:
                for successor in self.influences(stack.pop()):
                    if successor not in seen:
                        seen.add(successor)
                        stack.append(successor)
            found = self.reaches[atom] = frozenset(seen)
        return found

    def influences(self, atom: tuple[str, int]) -> Iterator[tuple[str, int]]:
        """Return what one element acts on directly."""
        kind, ref = atom
        system = self.system
        if kind == "q":
            request = system.requests[ref]
            yield ("n", request.node)
            if request.command is not None:
                yield ("e", request.command)
        elif kind == "n":
            for key, reaction in self.reactions.items():
                if reaction.event == "state_transition" and (
                        reaction.nodes is None or ref in reaction.nodes):
                    yield ("r", key)
            for request in self.sequences.get(ref, ()):
                yield ("q", request.index)
            for index in self.managers:
                if ref in system.managers[index].nodes:
                    yield ("m", index)
        elif kind == "m":
            for node in system.managers[ref].nodes:
                if node is not None:
                    yield ("n", node)
        elif kind == "e":
            for key, reaction in self.reactions.items():
                if reaction.event != "state_transition" and (
                        reaction.targets is None or ref in reaction.targets):
                    yield ("r", key)
        elif kind == "r":
            for block, content in system.blocks.items():
                if block[0] != ref:
                    continue
                yield from (("n", n) for n in content.starts if n in self.local)
                yield from (("q", q) for q in content.requests if q in self.part.requests)
                yield from (("m", m) for m in content.managers if m in self.managers)
                yield from (("e", e) for e in content.actions)
                for key, reaction in self.reactions.items():
                    if reaction.registered == block:
                        yield ("r", key)

    # ------------------------------------------------------------------ moves

    def empty(self) -> State:
        return State(tuple("" for _ in self.nodes), frozenset(), frozenset(), (), frozenset(),
                     tuple(0 for _ in self.managers))

    def successors(self, state: State) -> Iterator[tuple[Move, State, list[Effect]]]:
        for item in dict.fromkeys(state.pending):
            rest = list(state.pending)
            rest.remove(item)
            effects: list[Effect] = []
            after = self.take(item, state._replace(pending=tuple(rest)), effects)
            yield Move("item", item=item), after, effects
        stepped = False
        for position, index in enumerate(self.managers):
            effects = []
            moved = self.manager_step(state, position, index, effects)
            if moved is not None:
                stepped = True
                yield moved[0], moved[1], effects
        if state.pending or stepped or not state.timers:
            return
        soonest = min(block[1] or 0.0 for block in state.timers)
        for block in sorted(state.timers, key=repr):
            if (block[1] or 0.0) == soonest:
                effects = []
                after = self.happen(state._replace(timers=state.timers - {block}), block,
                                    effects)
                yield Move("timer", block=block), after, effects

    def take(self, item: Item, state: State, effects: list[Effect]) -> State:
        """Handle one pending event."""
        if item.kind == "request":
            request = self.system.requests[item.ref]
            step = int(item.detail)
            state = self.apply(state, request.node, request.transitions[step],
                               Source("request", item.ref, step), effects)
            if request.command is not None:  # the command ends once answered
                state = self.process_event(state, request.command, "exit", effects)
            return state
        return self.process_event(state, item.ref, item.detail, effects)

    def apply(self, state: State, node: int, transition: int | str, source: Source,
              effects: list[Effect]) -> State:
        """A request reaches a node: rcl accepts or refuses it; handlers see the events."""
        local = self.local[node]
        current = state.nodes[local]
        if not current:
            effects.append(Effect("refused", node, "", source))
            return state
        outcome = lc.request(current, transition)
        if outcome is None:
            effects.append(Effect("refused", node, current, source))
            return state
        goal, events = outcome
        effects.extend(Effect("state", node, event.goal, source) for event in events)
        state = state._replace(nodes=(*state.nodes[:local], goal, *state.nodes[local + 1:]))
        return self.transition_events(state, node, events, effects)

    def transition_events(self, state: State, node: int,
                          events: tuple[lc.TransitionEvent, ...],
                          effects: list[Effect]) -> State:
        """Fire what waits for a node's transition events."""
        if self.system.nodes[node].record.kind not in EMITTING:
            return state  # launch sees no StateTransition of a plain Node
        for event in events:
            for key, reaction in self.reactions.items():
                if (reaction.event == "state_transition"
                        and reaction.registered in state.happened
                        and ("r", key, 0) not in state.spent
                        and (reaction.nodes is None or node in reaction.nodes)
                        and reaction.matches(event)):
                    state = self.fire(state, key, effects)
            for request in self.sequences.get(node, ()):
                if request.block not in state.happened:
                    continue
                for step in range(1, len(request.transitions)):
                    spent = ("s", request.index, step)
                    if spent not in state.spent and lc.completes(request.transitions[step - 1],
                                                                 event):
                        item = Item("request", request.index, str(step))
                        state = state._replace(
                            spent=state.spent | {spent},
                            pending=tuple(sorted((*state.pending, item))))
        return state

    def process_event(self, state: State, execution: int, what: str,
                      effects: list[Effect]) -> State:
        """A process starts or exits, or an action completes: fire who waits for it."""
        events = EVENT_HANDLERS[what]
        for key, reaction in self.reactions.items():
            if (reaction.event in events and reaction.registered in state.happened
                    and ("r", key, 0) not in state.spent
                    and (reaction.targets is None or execution in reaction.targets)):
                state = self.fire(state, key, effects)
        return state

    def fire(self, state: State, key: int, effects: list[Effect]) -> State:
        """A handler fires: its block executes (again, for a handler not handled once)."""
        effects.append(Effect("fired", key))
        if self.reactions[key].once:
            state = state._replace(spent=state.spent | {("r", key, 0)})
        return self.happen(state, (key, None), effects)

    def happen(self, state: State, block: Block, effects: list[Effect]) -> State:
        """A block executes: nodes start, requests and process events are queued."""
        again = block in state.happened
        content = self.system.blocks.get(block)
        nodes = state.nodes
        queued = list(state.pending)
        if content is not None:
            if not again:
                started = list(nodes)
                for node in content.starts:
                    local = self.local.get(node)
                    if local is not None and not started[local]:
                        started[local] = "unconfigured"
                        effects.append(Effect("state", node, "unconfigured"))
                nodes = tuple(started)
            queued.extend(Item("request", i, "0") for i in content.requests
                          if i in self.part.requests)
            for execution in content.processes:
                if self.listens(execution, "process_start"):
                    queued.append(Item("event", execution, "start"))
                if execution in self.system.ending and execution not in self.commands and (
                        self.listens(execution, "process_exit")
                        or self.listens(execution, "execution_complete")):
                    queued.append(Item("event", execution, "exit"))
            queued.extend(Item("event", e, "done") for e in content.actions
                          if e not in content.processes
                          and self.listens(e, "execution_complete"))
        timers = state.timers
        if block[1] is None and not again:
            timers = timers | {b for b in self.timer_blocks if b[0] == block[0]}
        return state._replace(nodes=nodes, happened=state.happened | {block},
                              pending=tuple(sorted(queued)), timers=timers)

    def listens(self, execution: int, event: str) -> bool:
        return any(r.event == event and (r.targets is None or execution in r.targets)
                   for r in self.reactions.values())

    def manager_step(self, state: State, position: int, index: int,
                     effects: list[Effect]) -> tuple[Move, State] | None:
        """One step of a nav2 lifecycle manager's bring-up program."""
        manager = self.system.managers[index]
        pc = state.pcs[position]
        if (pc < 0 or pc == self.manager_end(index) or manager.block not in state.happened
                or not manager.spec.autostart):
            return None
        if pc == 0:
            if any(n is None or not state.nodes[self.local[n]] for n in manager.nodes):
                return None  # still waiting for a node's services
            return Move("manager", manager=index, action="ready"), self.set_pc(state, position, 1)
        count = len(manager.nodes)
        configure = pc <= count
        node = manager.nodes[(pc - 1) % count]
        assert node is not None
        before = len(effects)
        state = self.apply(state, node, lc.CONFIGURE if configure else lc.ACTIVATE,
                           Source("manager", index, node), effects)
        refused = any(e.kind == "refused" for e in effects[before:])
        move = Move("manager", manager=index, action="configure" if configure else "activate",
                    node=node)
        return move, self.set_pc(state, position, -1 if refused else pc + 1)

    @staticmethod
    def set_pc(state: State, position: int, pc: int) -> State:
        return state._replace(pcs=(*state.pcs[:position], pc, *state.pcs[position + 1:]))

    # ------------------------------------------------------------------ traces

    def trace(self, where: Where) -> tuple[Step, ...]:
        links: list[tuple[Move, tuple[Effect, ...]]] = []
        state_id = where.state
        while state_id > 0:
            parent, move, effects = self.parents[state_id]
            links.append((move, effects))
            state_id = parent
        if where.move is not None:
            links.insert(0, (where.move, where.effects))
        steps = [Step("the launch starts")]
        for move, effects in reversed(links):
            steps.extend(self.describe(move, effects))
        return tuple(steps)

    def describe(self, move: Move, effects: tuple[Effect, ...]) -> list[Step]:
        step = self.describe_move(move)
        source = move_source(move)
        text = step.text
        for effect in effects:
            if source is None or effect.source != source:
                continue
            if effect.kind == "state" and effect.label in lc.PRIMARY_STATES:
                text += f": it becomes {effect.label}"
            elif effect.kind == "refused":
                text += (": the node is not started yet, launch drops the request"
                         if not effect.label else f": refused, the node is {effect.label}")
        steps = [Step(text, step.span)]
        for effect in effects:
            if effect.kind == "fired":
                reaction = self.system.reactions[effect.key]
                steps.append(Step(f"the {reaction.event.replace('_', ' ')} handler fires",
                                  reaction.origin.span))
        return steps

    def describe_move(self, move: Move) -> Step:
        system = self.system
        if move.kind == "item" and move.item is not None and move.item.kind == "request":
            request = system.requests[move.item.ref]
            transition = request.transitions[int(move.item.detail)]
            return Step(f"{request.label} asks {system.nodes[request.node].fqn} to "
                        f"{verb(transition)}", request.origin.span)
        if move.kind == "item" and move.item is not None:
            from launchverify.events import describe_action

            record = system.executions[move.item.ref]
            what = {"start": "starts", "exit": "exits", "done": "completes"}[move.item.detail]
            return Step(f"{describe_action(record.action)} {what}", record.origin.span)
        if move.kind == "manager":
            manager = system.managers[move.manager]
            name = manager.spec.fqn or "the lifecycle manager"
            if move.action == "ready":
                return Step(f"{name} finds the services of all its nodes",
                            manager.spec.record.origin.span)
            return Step(f"{name} asks {system.nodes[move.node].fqn} to {move.action}",
                        manager.spec.record.origin.span)
        if move.kind == "timer" and move.block is not None:
            return Step(f"a timer fires after {move.block[1] or 0.0:g} s")
        return Step("the launch starts")


def move_source(move: Move) -> Source | None:
    """Return what a move asks a transition for, if it does."""
    if move.kind == "item" and move.item is not None and move.item.kind == "request":
        return Source("request", move.item.ref, int(move.item.detail))
    if move.kind == "manager" and move.action != "ready":
        return Source("manager", move.manager, move.node)
    return None


def verb(transition: int | str) -> str:
    """Return a transition as a verb for messages (``configure``, ``shutdown``)."""
    if isinstance(transition, str):
        return transition
    known = lc.TRANSITIONS.get(transition)
    return known.label if known else lc.transition_name(transition)
