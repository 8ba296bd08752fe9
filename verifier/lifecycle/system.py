"""The lifecycle bring-up of one launch graph, as a transition system to explore.

Built from the evaluator's records, under the arguments as given (``graph.base``):

- managed nodes: ``LifecycleNode`` actions, lifecycle composable nodes, the nodes a nav2
  lifecycle manager lists and the nodes a ``ros2 lifecycle set`` command addresses;
- blocks: what executes together: at launch (``LAUNCH``), when a handler fires
  (``(handler, None)``), when a timer inside either fires (``(handler or None, delay)``);
- requests: ``ChangeState``, ``LifecycleTransition``, ``autostart`` and ``ros2 lifecycle
  set`` commands, each made by the block its action executes in;
- reactions: the handlers whose entities matter to the bring-up and that fire on a
  lifecycle event (``OnStateTransition``; one whose labels no event carries never fires,
  see ``labels.py``), a process start or exit, or an action's end;
- managers: nav2 lifecycle managers with the nodes they wait for.

What the launch asks but can never deliver is found here, before any search: a
``ChangeState`` aimed at a node launched as a plain ``Node`` (launch_ros delivers it only to
``LifecycleNode`` actions), at a name no lifecycle node has, or with CREATE/DESTROY.
"""

from __future__ import annotations

import shlex
from dataclasses import dataclass, field

from launchverify.graph import ExecutedRecord, LaunchGraph, NodeRecord, Origin
from launchverify.ir import actions as a
from launchverify.lifecycle.labels import never_fires
from launchverify.lifecycle.managers import ManagerSpec, is_manager, manager_spec
from launchverify.models import lifecycle as lc
from launchverify.suggest import typo_of

Block = tuple[int | None, float | None]
LAUNCH: Block = (None, None)
REACTION_EVENTS = ("state_transition", "process_start", "process_exit", "execution_complete")
PROCESS_ACTIONS = (a.ExecuteProcess, a.Node)


@dataclass(frozen=True)
class ManagedNode:
    """A node whose lifecycle state the bring-up follows.

    ``drivable``: launched as a ``LifecycleNode`` action, so launch delivers ``ChangeState``
    to it and turns its transitions into ``StateTransition`` events.
    """

    fqn: str
    record: NodeRecord
    block: Block
    drivable: bool


@dataclass(frozen=True)
class Request:
    """Transitions asked of one managed node, one after the other once each completes."""

    index: int
    node: int
    transitions: tuple[int | str, ...]
    label: str  # how messages name the request
    origin: Origin
    block: Block
    command: int | None = None  # a ``ros2 lifecycle set`` process (its execution)


@dataclass(frozen=True)
class Reaction:
    """A handler whose entities matter to the bring-up (its block is ``(key, None)``)."""

    key: int  # index in ``graph.handlers``
    event: str
    nodes: frozenset[int] | None  # state_transition: whose events (None: any drivable)
    targets: frozenset[int] | None  # process events: target executions (None: any)
    filters: tuple[tuple[str, str], ...]
    once: bool
    registered: Block
    origin: Origin
    never: lc.NeverMatches | None = None  # labels no event carries: it never fires

    def matches(self, event: lc.TransitionEvent) -> bool:
        """Return whether a transition event passes the handler's label filters."""
        if self.never is not None:
            return False  # e.g. transition labels, which events carry only since rolling
        values = {"transition": event.transition, "start_state": event.start,
                  "goal_state": event.goal}
        return all(values[name] == label for name, label in self.filters)


@dataclass
class BlockContent:
    """What happens when a block executes."""

    starts: list[int] = field(default_factory=list)  # managed nodes
    requests: list[int] = field(default_factory=list)
    processes: list[int] = field(default_factory=list)  # executions that start a process
    actions: list[int] = field(default_factory=list)  # every execution (completion events)
    managers: list[int] = field(default_factory=list)


@dataclass(frozen=True)
class Refusal:
    """A request the launch makes that can never reach a lifecycle node."""

    origin: Origin
    label: str
    reason: str


@dataclass(frozen=True)
class ManagerRun:
    """A lifecycle manager: the managed node behind each name (``None``: none launched)."""

    spec: ManagerSpec
    block: Block
    nodes: tuple[int | None, ...]


@dataclass
class System:
    """The bring-up of one graph: what the explorer searches."""

    nodes: list[ManagedNode] = field(default_factory=list)
    requests: list[Request] = field(default_factory=list)
    reactions: dict[int, Reaction] = field(default_factory=dict)
    blocks: dict[Block, BlockContent] = field(default_factory=dict)
    managers: list[ManagerRun] = field(default_factory=list)
    refusals: list[Refusal] = field(default_factory=list)
    unmodelled: set[Block] = field(default_factory=set)  # triggers launchverify cannot follow
    ending: set[int] = field(default_factory=set)  # executions of processes that end
    executions: list[ExecutedRecord] = field(default_factory=list)  # graph.executed
    complete: bool = True

    def content(self, block: Block) -> BlockContent:
        """Return what a block holds (empty when nothing in it matters)."""
        return self.blocks.setdefault(block, BlockContent())

    @property
    def empty(self) -> bool:
        """Return whether there is nothing to explore or report."""
        return not self.nodes and not self.managers and not self.refusals


def build_system(graph: LaunchGraph) -> System:
    """Return the bring-up of a graph under the arguments as given."""
    return _Builder(graph).build()


class _Builder:
    def __init__(self, graph: LaunchGraph) -> None:
        self.graph = graph
        self.system = System(complete=graph.complete_as_given(), executions=graph.executed)
        self.by_fqn: dict[str, int] = {}
        self.by_record: dict[int, int] = {}
        self.every_fqn: dict[str, NodeRecord] = {}  # any node that may run, by FQN

    # ------------------------------------------------------------------ helpers

    def block_of(self, execution: int | None) -> Block:
        if execution is None:
            return LAUNCH
        record = self.graph.executed[execution]
        return (record.within, record.delay)

    def runs(self, origin: Origin) -> bool:
        verdict = self.graph.runs(origin)
        if verdict is None:
            self.system.complete = False  # what may or may not run is not followed
        return verdict is not False

    def manage(self, record: NodeRecord) -> int | None:
        """Return the managed-node index of a node record, adding it on first sight."""
        if id(record) in self.by_record:
            return self.by_record[id(record)]
        fqn = self.graph.base(record.fqn)
        if fqn is None:
            self.system.complete = False
            return None
        index = len(self.system.nodes)
        self.system.nodes.append(ManagedNode(fqn, record, self.block_of(record.execution),
                                             record.kind == "lifecycle_node"))
        self.by_record[id(record)] = index
        self.by_fqn.setdefault(fqn, index)
        self.system.content(self.block_of(record.execution)).starts.append(index)
        return index

    def same_run_executions(self, target: object, execution: int | None) -> list[int]:
        """Return the executions of ``target`` from the same evaluation as ``execution``."""
        found = [i for i, r in enumerate(self.graph.executed) if r.action is target]
        if execution is None or len(found) < 2:
            return found
        here: ExecutedRecord = self.graph.executed[execution]
        return [i for i in found if self.graph.executed[i].same_run(here)] or found

    def add_request(self, node: int, transitions: tuple[int | str, ...], label: str,
                    origin: Origin, block: Block, command: int | None = None) -> None:
        index = len(self.system.requests)
        self.system.requests.append(Request(index, node, transitions, label, origin, block,
                                            command))
        self.system.content(block).requests.append(index)

    def refuse(self, origin: Origin, label: str, reason: str) -> None:
        self.system.refusals.append(Refusal(origin, label, reason))

    # ------------------------------------------------------------------ build

    def build(self) -> System:
        graph = self.graph
        for record in graph.nodes:
            if graph.runs(record.origin) is False:
                continue
            fqn = graph.base(record.fqn)
            if fqn is not None:
                self.every_fqn.setdefault(fqn, record)
            if record.lifecycle:
                self.manage(record)
        self.managers()
        self.commands()
        self.autostarts()
        self.launch_requests()
        if self.system.nodes or self.system.managers:  # else no handler can matter
            self.reactions()
            self.prune()
        return self.system

    def managers(self) -> None:
        for record in self.graph.nodes:
            if not is_manager(self.graph, record) or not self.runs(record.origin):
                continue
            spec = manager_spec(self.graph, record)
            if spec.resolved is None or spec.autostart is None:
                self.system.complete = False
            nodes: list[int | None] = []
            for fqn in spec.resolved or ():
                found = self.every_fqn.get(fqn)
                nodes.append(None if found is None else self.manage(found))
            index = len(self.system.managers)
            block = self.block_of(record.execution)
            self.system.managers.append(ManagerRun(spec, block, tuple(nodes)))
            self.system.content(block).managers.append(index)

    def commands(self) -> None:
        """``ros2 lifecycle set NODE TRANSITION`` run as a process by the launch."""
        for process in self.graph.processes:
            words = self.command_words(process.cmd)
            if words is None or not self.runs(process.origin):
                continue
            name, transition_text = words
            transition = lc.parse_transition(transition_text)
            label = f"`ros2 lifecycle set {name} {transition_text}`"
            fqn = name if name.startswith("/") else "/" + name
            found = self.every_fqn.get(fqn)
            if transition is None:
                self.refuse(process.origin, label, f"{transition_text!r} is not a transition")
                continue
            if found is None:
                self.refuse(process.origin, label, self.no_such_node(fqn))
                continue
            node = self.manage(found)
            if node is not None:
                self.add_request(node, (transition,), label, process.origin,
                                 self.block_of(process.execution), process.execution)

    def command_words(self, cmd: tuple[object, ...]) -> tuple[str, str] | None:
        texts = [self.graph.base(part) for part in cmd]  # type: ignore[arg-type]
        if any(t is None for t in texts):
            return None
        words: list[str] = []
        for text in texts:
            assert text is not None
            try:
                words.extend(shlex.split(text))
            except ValueError:
                return None
        for i in range(len(words) - 4):
            if (words[i].rsplit("/", 1)[-1] == "ros2" and words[i + 1] == "lifecycle"
                    and words[i + 2] == "set"):
                return words[i + 3], words[i + 4]
        return None

    def autostarts(self) -> None:
        for index, node in enumerate(list(self.system.nodes)):
            value = node.record.autostart
            if value is None:
                continue
            text = self.graph.base(value)
            if text is None:
                self.system.complete = False
                continue
            if text.strip().lower() in ("true", "1"):
                self.add_request(index, (lc.CONFIGURE, lc.ACTIVATE), "autostart",
                                 node.record.origin, node.block)

    def launch_requests(self) -> None:
        """``EmitEvent(ChangeState(...))`` and ``LifecycleTransition``."""
        for request in self.graph.requests:
            if not self.runs(request.origin):
                continue
            sequence = request.via == "lifecycle_transition"
            transitions: list[int] = []
            for sub in request.transitions:
                text = self.graph.base(sub)
                parsed = None if text is None else lc.parse_transition(text)
                if not isinstance(parsed, int):
                    self.system.complete = False
                    break
                transitions.append(parsed)
            else:
                label = ("LifecycleTransition" if sequence else
                         f"ChangeState({lc.transition_name(transitions[0])})")
                if not sequence and transitions[0] in lc.MESSAGE_ONLY:
                    self.refuse(request.origin, label, f"{lc.transition_name(transitions[0])}"
                                " is not a transition of the lifecycle state machine: rcl "
                                "refuses it whatever the state")
                    continue
                for node in self.request_targets(request, label):
                    self.add_request(node, tuple(transitions), label, request.origin,
                                     self.block_of(request.execution))

    def request_targets(self, request: object, label: str) -> list[int]:
        """Return the managed nodes a request reaches (refusing what it cannot reach)."""
        from launchverify.graph import TransitionRequest

        assert isinstance(request, TransitionRequest)
        if request.matcher == "action":
            if request.target is None:
                self.system.complete = False
                return []
            runs = self.same_run_executions(request.target, request.execution)
            nodes = [self.by_record[id(n)] for n in self.graph.nodes
                     if n.execution in runs and id(n) in self.by_record
                     and n.kind == "lifecycle_node"]
            if nodes:
                return nodes
            if isinstance(request.target, a.LifecycleNode):
                if not runs:
                    self.refuse(request.origin, label, "its target node is never launched")
                return []
            if isinstance(request.target, a.Node):
                self.refuse(request.origin, label, "its target is launched as a Node, not a "
                            "LifecycleNode: launch_ros delivers ChangeState only to "
                            "LifecycleNode actions")
            else:
                self.system.complete = False
            return []
        if request.matcher == "name":
            out = []
            for sub in request.names:
                name = self.graph.base(sub)
                if name is None:
                    self.system.complete = False
                    continue
                fqn = name if name.startswith("/") else "/" + name
                index = self.by_fqn.get(fqn)
                kind = None if index is None else self.system.nodes[index].record.kind
                if index is not None and kind == "lifecycle_node":
                    out.append(index)
                elif kind == "composable_lifecycle_node":
                    continue  # rolling's components have their own lifecycle event manager
                elif fqn in self.every_fqn:
                    self.refuse(request.origin, label, f"{fqn} is launched as a Node, not a "
                                "LifecycleNode: launch_ros delivers ChangeState only to "
                                "LifecycleNode actions")
                else:
                    self.refuse(request.origin, label, self.no_such_node(fqn))
            return out
        self.system.complete = False  # a matcher function: whom it reaches is not known
        return []

    def no_such_node(self, fqn: str) -> str:
        lifecycle = [f for f, r in self.every_fqn.items() if r.lifecycle] or list(self.every_fqn)
        near = typo_of(fqn, lifecycle)
        hint = f" (did you mean {near}?)" if near else ""
        return f"no node named {fqn} is launched{hint}"

    def reactions(self) -> None:
        for key, handler in enumerate(self.graph.handlers):
            if not self.runs(handler.origin):
                continue
            registered = self.block_of(handler.execution)
            if handler.event not in REACTION_EVENTS or handler.custom:
                if handler.event != "shutdown":
                    self.system.unmodelled.add((key, None))
                continue
            nodes: frozenset[int] | None = None
            targets: frozenset[int] | None = None
            if handler.target is not None:
                runs = self.same_run_executions(handler.target, handler.execution)
                if handler.event == "state_transition":
                    nodes = frozenset(self.by_record[id(n)] for n in self.graph.nodes
                                      if n.execution in runs and id(n) in self.by_record)
                else:
                    targets = frozenset(runs)
            self.system.reactions[key] = Reaction(
                key, handler.event, nodes, targets, handler.filters, handler.once, registered,
                handler.origin, never_fires(handler))
        for index, record in enumerate(self.graph.executed):
            block = (record.within, record.delay)
            if isinstance(record.action, PROCESS_ACTIONS):
                self.system.content(block).processes.append(index)
                if not isinstance(record.action, a.Node):
                    self.system.ending.add(index)
            self.system.content(block).actions.append(index)

    def prune(self) -> None:
        """Keep handlers of lifecycle events, and others whose blocks matter to the bring-up."""
        system = self.system
        owned: dict[int | None, list[Block]] = {}
        for block in system.blocks:
            owned.setdefault(block[0], []).append(block)
        relevant = {k for k, r in system.reactions.items() if r.event == "state_transition"}
        changed = True
        while changed:
            changed = False
            for key in system.reactions:
                if key in relevant:
                    continue
                for block in owned.get(key, []):
                    content = system.blocks[block]
                    if (content.starts or content.requests or content.managers
                            or any(r in relevant for r in self.registered_in(block))):
                        relevant.add(key)
                        changed = True
                        break
        system.reactions = {k: r for k, r in system.reactions.items() if k in relevant}

    def registered_in(self, block: Block) -> list[int]:
        return [k for k, r in self.system.reactions.items() if r.registered == block]
