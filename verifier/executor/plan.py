"""What a run does, read off an evaluated graph: blocks of actions, handlers, processes.

The evaluator recorded every action that executes with the handler it runs in
(``within``; ``None``: at launch) and the timers around it (``delay``). A *block* is what
one firing of a handler (or the launch itself) executes, in order, each action after its
delay. Actions whose condition is false under the arguments are left out; a condition
that cannot be decided before run time stops the plan (nothing is guessed).
"""

from __future__ import annotations

import shutil
from collections import defaultdict
from dataclasses import dataclass, field
from pathlib import Path

from launchverify.executor.command import Command, CommandBuilder, CommandError, yaml_value
from launchverify.graph import HandlerRecord, LaunchGraph, LaunchRecord, TransitionRequest
from launchverify.ir import actions as a
from launchverify.models import lifecycle as lc
from launchverify.render.inert import inert

OUTPUTS = ("screen", "log", "both")


class PlanError(Exception):
    """A launch that cannot be run as evaluated.

    Its message is lines of launchverify's own, each made inert where it quotes the
    checked files (names, paths): shown as it is, line breaks and all.
    """

    def lines(self) -> list[str]:
        """Return the message's lines."""
        return str(self).split("\n")


@dataclass
class Process:
    """A process the plan starts: its command and how launch supervises it."""

    execution: int
    launch: LaunchRecord
    command: Command
    name: str  # launch's process name before the ``-N`` suffix
    output: str = "log"
    respawn: bool = False
    respawn_delay: float = 0.0
    respawn_max_retries: int = -1  # -1: for ever
    sigterm_timeout: float = 5.0
    sigkill_timeout: float = 5.0
    lifecycle_fqn: str | None = None  # a lifecycle node's name (autostart, transitions)
    autostart: bool = False


@dataclass
class Plan:
    """Everything ``run`` executes, keyed by execution index (``graph.executed``)."""

    graph: LaunchGraph
    blocks: dict[int | None, list[tuple[float | None, int]]]
    processes: dict[int, Process]
    registers: dict[int, list[int]]  # execution of a RegisterEventHandler: handler indices
    requests: dict[int, list[TransitionRequest]]
    components: dict[int, list[list[str]]] = field(default_factory=dict)  # load commands
    notes: list[str] = field(default_factory=list)  # what will not be done, said up front

    @property
    def handlers(self) -> list[HandlerRecord]:
        """Return the graph's handlers (indices are what ``within`` refers to)."""
        return self.graph.handlers

    def action(self, execution: int) -> object:
        """Return the IR action of an execution."""
        return self.graph.executed[execution].action

    def log(self, execution: int) -> tuple[str, str] | None:
        """Return the level and text of a log action (``None``: not a log)."""
        if execution not in self.graph.logs:
            return None
        level, message = self.graph.logs[execution]
        return level, self.graph.display(message) or ""

    def shutdown_reason(self, execution: int) -> str | None:
        """Return why an action shuts the launch down (``None``: it does not)."""
        action = self.action(execution)
        if isinstance(action, a.Shutdown):
            reason = self.graph.base(action.reason) if action.reason is not None else None
        elif isinstance(action, a.EmitEvent) and action.event == "Shutdown":
            reason = str(action.details.get("reason", "")) or None
        else:
            return None
        return reason or "Shutdown action"


def build_plan(graph: LaunchGraph, prefixes: list[Path], params_dir: Path, *,
               strict: bool = True) -> Plan:
    """Return the plan of a graph under its arguments (``strict``: every executable found)."""
    blocks: dict[int | None, list[tuple[float | None, int]]] = defaultdict(list)
    undecided = []
    for index, record in enumerate(graph.executed):
        runs = graph.runs(record.origin)
        if runs is False:
            continue
        if runs is None:
            undecided.append(record.origin.span.short())
            continue
        blocks[record.within].append((record.delay, index))
    if undecided:
        raise PlanError("conditions not known before run time (pin the arguments they "
                        f"read with name:=value): {inert(', '.join(undecided[:5]))}")
    builder = CommandBuilder(graph, prefixes, params_dir, strict=strict)
    processes: dict[int, Process] = {}
    errors = []
    for launch in graph.launches:
        if launch.execution is None or not graph.runs(launch.origin):
            continue
        try:
            processes[launch.execution] = _process(graph, builder, launch)
        except CommandError as error:
            errors.append(f"{launch.origin.span.short()}: {error}")
    if errors:
        raise PlanError("cannot start:\n  " + "\n  ".join(inert(error) for error in errors))
    registers: dict[int, list[int]] = defaultdict(list)
    for number, handler in enumerate(graph.handlers):
        if handler.execution is not None:
            registers[handler.execution].append(number)
    requests: dict[int, list[TransitionRequest]] = defaultdict(list)
    for request in graph.requests:
        if request.execution is not None and graph.runs(request.origin):
            requests[request.execution].append(request)
    plan = Plan(graph, dict(blocks), processes, dict(registers), dict(requests),
                components=_components(graph, builder))
    plan.notes.extend(_notes(plan))
    plan.notes.extend(builder.missing)
    return plan


def _process(graph: LaunchGraph, builder: CommandBuilder, launch: LaunchRecord) -> Process:
    settings = launch.settings
    command = builder.build(launch)
    output = graph.base(settings.output) if settings.output is not None else "log"
    if output not in OUTPUTS:
        output = "log"  # launch also accepts a dict of per-stream settings; logged
    name = graph.base(settings.name) if settings.name is not None else None
    if not name:
        node = launch.node
        executable = graph.base(node.executable) if node is not None else None
        name = Path(executable or command.argv[0]).name
    respawn = settings.respawn
    if not isinstance(respawn, bool):
        respawn = (graph.base(respawn) or "").strip().lower() in ("true", "1")
    node = launch.node
    fqn = graph.base(node.fqn) if node is not None and node.lifecycle else None
    return Process(
        execution=launch.execution or 0, launch=launch, command=command, name=name,
        output=output, respawn=respawn, respawn_delay=settings.respawn_delay or 0.0,
        respawn_max_retries=(-1 if settings.respawn_max_retries is None
                             else settings.respawn_max_retries),
        sigterm_timeout=_seconds(graph, settings.sigterm_timeout, "sigterm_timeout"),
        sigkill_timeout=_seconds(graph, settings.sigkill_timeout, "sigkill_timeout"),
        lifecycle_fqn=fqn,
        autostart=node is not None and node.autostart is not None
        and (graph.base(node.autostart) or "").lower() == "true",
    )


def _seconds(graph: LaunchGraph, value: object, configuration: str) -> float:
    """Return a timeout: the process's own, else the launch configuration, else 5 s."""
    text: str | None
    if isinstance(value, (int, float)):
        return float(value)
    if value is not None:
        text = graph.base(value)  # type: ignore[arg-type]
    else:  # launch reads LaunchConfiguration(configuration, default=5)
        text = graph.pinned.get(configuration) or next(
            (graph.base(arg.value) for arg in graph.arguments if arg.name == configuration),
            None)
    try:
        return float(text) if text else 5.0
    except ValueError:
        return 5.0


def _components(graph: LaunchGraph, builder: CommandBuilder) -> dict[int, list[list[str]]]:
    """Return, per executing action, the ``ros2 component load`` argv of each component.

    launch_ros calls the container's ``_container/load_node`` service with the node's
    name, namespace, remaps, parameters (files already read: the effective values) and
    extra arguments; ``ros2 component load`` makes the same request.
    """
    from launchverify.parameters import effective_parameters

    out: dict[int, list[list[str]]] = defaultdict(list)
    for node in graph.nodes:
        if (not node.composable
                or node.execution is None or node.container is None
                or not graph.runs(node.origin)):
            continue
        try:
            argv = ["component", "load", builder.text(node.container, "the container"),
                    builder.text(node.package, "the package"),
                    builder.text(node.executable, "the plugin")]
            if node.name is not None:
                argv += ["--node-name", builder.text(node.name, "the node name")]
            if node.namespace is not None:
                argv += ["--node-namespace", builder.text(node.namespace, "the namespace")]
            for remap in node.remappings:
                argv += ["--remap-rule", f"{builder.text(remap.src, 'a remap')}:="
                         f"{builder.text(remap.dst, 'a remap')}"]
            effective = effective_parameters(graph, node)
            for name in effective.values:
                winner = effective.winner(name)
                if winner is not None:
                    argv += ["--parameter", f"{name}:={yaml_value(winner.value)}"]
        except CommandError:
            continue  # said by the notes: its values are not known before run time
        out[node.execution].append(argv)
    return dict(out)


def _notes(plan: Plan) -> list[str]:
    """Return what the embedded executor will not do, so it is said before starting."""
    notes = [f"{h.origin.span.short()}: OnProcessIO callbacks are Python functions the "
             "embedded executor does not call" for h in plan.handlers
             if h.event == "process_io"]
    for execution in (i for block in plan.blocks.values() for _, i in block):
        action = plan.action(execution)
        if isinstance(action, (a.LoadComposableNodes, a.ComposableNodeContainer)) and (
                isinstance(action, a.LoadComposableNodes) or action.composable_nodes) and \
                shutil.which("ros2") is None:
            notes.append(f"{plan.graph.executed[execution].origin.span.short()}: composable "
                         "nodes are loaded through the container's ROS service (ros2 "
                         "component load); without the ros2 command line only the container "
                         "starts")
        if isinstance(action, (a.OpaqueAction,)):
            notes.append(f"{plan.graph.executed[execution].origin.span.short()}: "
                         f"{action.description} is not run")
    return notes


def transition_label(transition: object) -> str:
    """Return ``ros2 lifecycle set``'s word for a transition id (``configure``)."""
    text = str(transition)
    try:
        known = lc.TRANSITIONS.get(int(text))
    except ValueError:
        known = None
    return known.label if known is not None else text.lower()
