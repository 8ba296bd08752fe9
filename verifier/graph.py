"""The launch graph: everything one evaluation found, ready for rules and reporters.

Every record carries an ``Origin``: where it is written, the include chain that reached it
(root first) and its path condition (the guards that must hold for it to run). Values are
residual expressions (``Text`` when concrete). ``LaunchGraph.base`` gives the view under
the arguments as given (command line, then defaults): what ``ros2 launch`` would do.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable, Iterator
from dataclasses import dataclass, field
from pathlib import Path

from launchverify.evaluate.values import BaseReducer, describe_value, text_of
from launchverify.frontends import LoadedFile
from launchverify.frontends.param_file import ParamFile
from launchverify.ir import actions as a
from launchverify.ir.conditions import Condition
from launchverify.ir.subst import Sub, Text, walk
from launchverify.ir.symbolic import (
    Guard,
    PackageFolder,
    PathCondition,
    StrEquals,
    Truthy,
    describe_path,
)
from launchverify.ir.walk import configuration_names
from launchverify.problems import NotFollowed, Problem, ProblemKind
from launchverify.span import Span


@dataclass(frozen=True, slots=True)
class Origin:
    """Where a record comes from: span, include chain (root first), path condition.

    ``call``: the action written around ``span`` when ``span`` is a piece of it (the
    ``LaunchConfiguration(...)`` inside a ``Node(...)``); findings show it as related.
    """

    span: Span
    chain: tuple[Span, ...] = ()
    path: PathCondition = ()
    call: Span | None = field(default=None, compare=False)

    def condition_text(self) -> str | None:
        """Return the path condition as text, or ``None`` when unconditional."""
        return describe_path(self.path)


@dataclass(frozen=True, slots=True)
class RemapRecord:
    """One remap rule applying to a node, in the order ROS 2 applies them."""

    src: Sub
    dst: Sub
    origin: Origin
    scope: bool = False


@dataclass(frozen=True, slots=True)
class ParamRecord:
    """One parameter source of a node: a file, or one named value."""

    origin: Origin
    file: Sub | None = None
    name: Sub | None = None
    value: object = None
    scope: bool = False
    value_type: str | None = None  # forced type (frontend ``type=``, ``ParameterValue``)
    source: Path | None = None  # the parameter file read (in ``LaunchGraph.param_files``)


@dataclass(frozen=True, slots=True)
class NodeRecord:
    """A ROS node that the launch starts (process, lifecycle, container or component)."""

    kind: str
    origin: Origin
    package: Sub | None
    executable: Sub | None
    name: Sub | None
    namespace: Sub | None
    fqn: Sub | None
    remappings: tuple[RemapRecord, ...] = ()
    parameters: tuple[ParamRecord, ...] = ()
    container: Sub | None = None
    deferred: bool = False
    execution: int | None = None  # index in ``LaunchGraph.executed`` of what started it
    autostart: Sub | None = None  # lifecycle nodes: configure and activate at start
    executable_written: Span | None = None  # where the executable is written verbatim

    def executable_label(self) -> str:
        """Return ``package/executable`` as written, for messages."""
        parts = [p.describe() for p in (self.package, self.executable) if p is not None]
        return "/".join(parts) or "node"

    @property
    def lifecycle(self) -> bool:
        """Return whether the node is a managed (lifecycle) node."""
        return self.kind in ("lifecycle_node", "composable_lifecycle_node")

    @property
    def composable(self) -> bool:
        """Return whether the node is a component loaded into a container."""
        return self.kind in ("composable_node", "composable_lifecycle_node")


@dataclass(frozen=True, slots=True)
class LoadRecord:
    """A ``LoadComposableNodes`` / ``<load_composable_node>``: components sent to a container.

    ``target`` is the container's name as launch_ros takes it: the name given, or a
    container action's full name once it ran; ``None`` when not known.
    """

    origin: Origin
    target: Sub | None
    components: int


@dataclass(frozen=True, slots=True)
class EnvRecord:
    """An environment variable the launch sets, and where.

    ``SetEnvironmentVariable`` / ``<set_env>``, or a process's own ``additional_env`` /
    ``<env>``.
    """

    name: str
    value: Sub | None  # None: unset
    origin: Origin


@dataclass(frozen=True, slots=True)
class ArgumentRecord:
    """A launch argument declaration as it executed."""

    name: str
    origin: Origin
    default: Sub | None
    description: str | None
    choices: tuple[str, ...] | None
    value: Sub
    action: a.DeclareArgument


@dataclass(frozen=True, slots=True)
class StaticArgument:
    """An argument found by launch's static discovery of an included file."""

    name: str
    has_default: bool
    conditional: bool
    span: Span
    description: str | None
    via_includes: tuple[frozenset[str], ...] = ()


@dataclass
class IncludeRecord:
    """An include as it executed, and what its subtree declared and read."""

    origin: Origin
    action: a.Include
    location: Sub
    target: Path | None
    status: str
    arguments: tuple[tuple[str | None, Sub, Span], ...] = ()
    static_arguments: tuple[StaticArgument, ...] = ()
    declared: set[str] = field(default_factory=set)
    reads: set[str] = field(default_factory=set)
    mentioned: set[str] = field(default_factory=set)  # by OpaqueFunctions (see LaunchGraph)
    files: set[Path] = field(default_factory=set)
    complete: bool = True
    note: str = ""
    relative: bool = False
    # an argument's name comes from what launchverify cannot know (code it does not see):
    # it may be any name
    unknown_names: bool = False
    # a path computed from an argument: its name, and the values tried (each one an
    # include of its own under the guard ``argument == value``)
    computed_from: str | None = None
    candidates: tuple[str, ...] = ()

    def missing_required(self) -> list[StaticArgument]:
        """Return the required arguments this include does not pass (launch raises).

        An argument whose name launchverify cannot know may be any of them: then none is
        missing. (A name from a launch argument is the user's value, an IP address say.)
        """
        if self.unknown_names:
            return []
        given = {name for name, _value, _span in self.arguments if name is not None}
        return [
            argument for argument in self.static_arguments
            if not argument.has_default and not argument.conditional
            and argument.name not in given.union(*argument.via_includes)
        ]


@dataclass(frozen=True, slots=True)
class ConfigRead:
    """A read of a launch configuration (``$(var name)``)."""

    name: str
    origin: Origin
    found: bool
    has_default: bool
    written: Span | None = None  # where the name is written verbatim (for a fix)
    # what it reads where that is set on some paths only (a ``Select`` with an unset
    # branch): whether the arguments as given take one of them is LV201's to ask
    value: Sub | None = None


@dataclass(frozen=True, slots=True)
class PackageRef:
    """A reference to a package by name (``pkg=``, ``$(find-pkg-share)``...)."""

    name: str
    origin: Origin
    found: bool
    what: str
    written: Span | None = None  # where the name is written verbatim (for a fix)


@dataclass(frozen=True, slots=True)
class FileRef:
    """A file the launch needs (parameter file, ``$(file-content)``)."""

    location: str
    origin: Origin
    exists: bool
    what: str
    note: str = ""
    written: Span | None = None  # where the file's name is written verbatim (for a fix)


@dataclass(frozen=True, slots=True)
class NameRecord:
    """A ROS name launch validates or passes on (node name, namespace, remap side)."""

    kind: str
    value: str
    origin: Origin


@dataclass(frozen=True, slots=True)
class ProblemRecord:
    """A frontend or evaluation problem, with how the file was reached."""

    problem: Problem
    chain: tuple[Span, ...] = ()
    path: PathCondition = ()
    # a CONDITIONAL problem that only some argument values cause: the value that fails
    # with them (an ``$(eval)`` over arguments), for LV002 to look for them
    value: Sub | None = None

    @property
    def origin(self) -> Origin:
        """Return where the problem is, with the include chain that reached it."""
        return Origin(self.problem.span, self.chain, self.path)


@dataclass(frozen=True, slots=True)
class ConditionRecord:
    """A condition (``if``/``unless``/``LaunchConfigurationEquals``) as it was evaluated.

    ``origin.span`` is the condition, ``origin.path`` the path condition around it.
    ``guard`` is what must hold for the action to run; ``verdict`` is ``True``/``False``
    when evaluation decided it (a constant, or a value the path condition fixes), else
    ``None``. ``literal`` marks a condition written without any input (``if="true"``,
    ``$(eval '1 < 2')``). ``override``: the verdict comes from a ``<let>`` (or
    ``SetLaunchConfiguration``) that replaced, after its declaration, an argument the
    condition reads, so the user's value no longer counts.
    """

    origin: Origin
    condition: Condition
    guard: Guard
    verdict: bool | None
    literal: bool
    # decided by a <let>/SetLaunchConfiguration that replaced the argument it reads: where
    override: Origin | None = None

    @property
    def text(self) -> str:
        """Return the condition as written (built when a rule reports it, not before)."""
        return self.condition.describe()

    @property
    def symbolic(self) -> bool:
        """Return whether the condition depends on inputs (arguments, environment...)."""
        guard = self.guard
        if isinstance(guard, Truthy):
            return not isinstance(guard.expression, Text)
        if isinstance(guard, StrEquals):
            return not (isinstance(guard.left, Text)
                        and (guard.right is None or isinstance(guard.right, Text)))
        return False


@dataclass(frozen=True, slots=True)
class HandlerRecord:
    """An event handler as registered: what it waits for and where.

    ``target`` is the IR action it listens to (``None``: any action); ``within`` the
    index of the handler whose entities registered it (``None``: registered at launch).
    A process's ``on_exit`` is recorded as a ``process_exit`` handler on the process.
    ``execution`` is the action that registered it (index in ``LaunchGraph.executed``);
    ``filters`` the labels an ``OnStateTransition`` compares; ``custom`` marks a matcher
    function launchverify cannot read.
    """

    origin: Origin
    event: str
    target: object | None
    once: bool
    within: int | None
    execution: int | None = None
    filters: tuple[tuple[str, str], ...] = ()
    custom: bool = False
    filter_spans: tuple[tuple[str, Span], ...] = ()  # where each label is written


@dataclass(frozen=True, slots=True)
class ExecutedRecord:
    """An action that executes: at launch, or when the handler ``within`` fires.

    ``instance`` and ``loop`` tell evaluations of one file apart (each include and each
    loop iteration runs the actions anew, with new action objects, while launchverify
    reuses what it read). ``delay`` is the period of the timers around the action
    (seconds from the launch or from the handler; ``None``: no timer; unknown periods
    count as 0).
    """

    origin: Origin
    action: object
    within: int | None
    instance: int = 0
    loop: tuple[object, ...] = ()
    delay: float | None = None

    def same_run(self, other: ExecutedRecord) -> bool:
        """Return whether two executions come from one evaluation of their file."""
        return self.instance == other.instance and self.loop == other.loop


@dataclass(frozen=True, slots=True)
class RerunRecord:
    """A process object that the handler ``within`` runs again, which launch refuses.

    ``problem`` indexes the ``executed more than once`` failure in ``LaunchGraph.problems``:
    when the rerun closes a loop of handlers, LV501 names it instead of LV002.
    """

    origin: Origin
    action: object
    within: int
    problem: int


@dataclass(frozen=True, slots=True)
class TransitionRequest:
    """A request that lifecycle nodes change state, as the launch makes it.

    ``via``: ``change_state`` (``EmitEvent(ChangeState)``), ``lifecycle_transition``
    (``LifecycleTransition``, one transition after the other) or ``autostart``.
    ``matcher`` says whom it addresses: ``action`` (``target``, by identity), ``name``
    (``names``, node FQNs as written) or ``custom`` (a function).
    """

    origin: Origin
    via: str
    transitions: tuple[Sub, ...]
    matcher: str
    execution: int | None
    target: object | None = None
    names: tuple[Sub, ...] = ()


@dataclass(frozen=True, slots=True)
class ProcessSettings:
    """What every process takes besides its command, reduced where it executes.

    ``env`` holds the launch's environment changes in scope (``None``: unset) followed by
    the process's ``additional_env``; ``replace_env`` is ``ExecuteProcess(env=...)``,
    which replaces the whole environment.
    """

    name: Sub | None = None
    cwd: Sub | None = None
    prefix: Sub | None = None
    output: Sub | None = None
    env: tuple[tuple[str, Sub | None], ...] = ()
    replace_env: tuple[tuple[Sub, Sub], ...] | None = None
    shell: bool = False
    emulate_tty: bool | None = None
    respawn: Sub | bool = False
    respawn_delay: float | None = None
    respawn_max_retries: int | None = None
    sigterm_timeout: Sub | float | None = None
    sigkill_timeout: Sub | float | None = None


@dataclass(frozen=True, slots=True)
class LaunchRecord:
    """A process the launch starts, with everything needed to start it for real.

    For a node (``node`` set) the command is built as launch_ros builds it from the node's
    record, ``arguments`` and ``ros_arguments``; for ``ExecuteProcess`` it is ``cmd``.
    ``execution`` is the action's index in ``LaunchGraph.executed``.
    """

    origin: Origin
    execution: int | None
    settings: ProcessSettings
    cmd: tuple[Sub, ...] = ()
    node: NodeRecord | None = None
    arguments: tuple[Sub, ...] = ()
    ros_arguments: tuple[Sub, ...] = ()


@dataclass(frozen=True, slots=True)
class SkippedAction:
    """An action whose condition is constant false: it never runs."""

    action: a.Action
    origin: Origin


@dataclass
class LaunchGraph:
    """Everything one evaluation of a root launch file found."""

    root: Path
    pinned: dict[str, str]
    included_elsewhere: bool = False
    environment: dict[str, str] = field(default_factory=dict)  # --env NAME=VALUE
    files: dict[Path, LoadedFile] = field(default_factory=dict)
    nodes: list[NodeRecord] = field(default_factory=list)
    includes: list[IncludeRecord] = field(default_factory=list)
    arguments: list[ArgumentRecord] = field(default_factory=list)
    reads: list[ConfigRead] = field(default_factory=list)
    packages: list[PackageRef] = field(default_factory=list)
    file_refs: list[FileRef] = field(default_factory=list)
    names: list[NameRecord] = field(default_factory=list)
    problems: list[ProblemRecord] = field(default_factory=list)
    skipped: list[SkippedAction] = field(default_factory=list)
    conditions: list[ConditionRecord] = field(default_factory=list)
    param_files: dict[Path, ParamFile] = field(default_factory=dict)
    handlers: list[HandlerRecord] = field(default_factory=list)
    executed: list[ExecutedRecord] = field(default_factory=list)
    reruns: list[RerunRecord] = field(default_factory=list)
    requests: list[TransitionRequest] = field(default_factory=list)
    launches: list[LaunchRecord] = field(default_factory=list)  # what ``run`` starts
    loads: list[LoadRecord] = field(default_factory=list)  # components sent to containers
    environment_sets: list[EnvRecord] = field(default_factory=list)  # what the launch sets
    logs: dict[int, tuple[str, Sub]] = field(default_factory=dict)  # execution: level, text
    root_arguments: tuple[StaticArgument, ...] = ()
    opaque_files: set[Path] = field(default_factory=set)
    complete: bool = True  # False when part of the launch could not be seen into
    # ... and that part may be where the arguments as given go (not known off their path):
    # without it, what runs with them is all seen
    unseen_as_given: bool = False
    # OpaqueFunctions stopped at a configuration nobody set (name, where): their reads before
    # that point are known (LV201 judges them), what they would read or start after is not.
    stops: list[tuple[str, Origin]] = field(default_factory=list)
    # The walk stopped at a bound on what one root may expand (``evaluate/budget.py``):
    # the records hold what came before, nothing after.
    cut_short: bool = False
    # Strings OpaqueFunctions' code holds: configurations they may read on paths not taken.
    mentioned: set[str] = field(default_factory=set)
    # Reads a workspace file for values that depend on file content (set by the evaluator).
    file_reader: Callable[[str], str | None] | None = field(default=None, repr=False)
    # What is computed from the records once and asked for again (effective parameters).
    derived: dict[str, dict[Hashable, object]] = field(default_factory=dict, repr=False)
    queries_elsewhere: int = 0  # z3 queries its rules asked in forked processes (fanout)

    def __post_init__(self) -> None:
        self._base = BaseReducer(self.inputs(), read=self.read_file)
        self._facts: BaseReducer | None = None
        self._verdicts: dict[Guard, bool | None] = {}
        # the same guard objects, by identity: hashing a guard walks its whole expression
        self._verdicts_by_id: dict[int, tuple[Guard, bool | None]] = {}
        # base texts by identity: rules ask again for the same names (the fleet: 270 000)
        self._texts_by_id: dict[int, tuple[Sub, str | None]] = {}

    def read_file(self, path: str) -> str | None:
        """Return a workspace file's text for the base view (``None``: not readable)."""
        return self.file_reader(path) if self.file_reader is not None else None

    def inputs(self) -> dict[str, str]:
        """Return the fixed inputs: arguments by name, environment variables as ``env:NAME``."""
        return {**self.pinned, **{f"env:{k}": v for k, v in self.environment.items()}}

    # ------------------------------------------------------------------ base view

    def base(self, sub: Sub | None) -> str | None:
        """Return a value under the given arguments and defaults, or ``None`` if unknown.

        Examples:
            >>> from launchverify.ir.symbolic import Arg
            >>> from launchverify.ir.subst import Text
            >>> LaunchGraph(Path("x"), {}).base(Arg("robot", Text("r1")))
            'r1'
        """
        if sub is None:
            return None
        if type(sub) is Text:
            return sub.text
        known = self._texts_by_id.get(id(sub))
        if known is not None and known[0] is sub:
            return known[1]
        text = text_of(self._base.reduce(sub))
        self._texts_by_id[id(sub)] = (sub, text)
        return text

    def launch_of(self, node: NodeRecord) -> LaunchRecord | None:
        """Return the process record that starts a node (its command line), if any.

        A component has none of its own: it runs in its container's process.
        """
        launches = self.derived.get("launch_of_node")
        if launches is None:  # built once per graph: a fleet has many nodes
            launches = {id(launch.node): launch for launch in self.launches
                        if launch.node is not None}
            self.derived["launch_of_node"] = launches
        found = launches.get(id(node))
        return found if isinstance(found, LaunchRecord) else None

    @property
    def processes(self) -> list[LaunchRecord]:
        """Return the plain processes (``ExecuteProcess``, ``<executable>``) it starts."""
        return [launch for launch in self.launches if launch.node is None]

    def reduced(self, sub: Sub) -> Sub:
        """Return a value reduced under the given arguments, as far as it goes."""
        return self._base.reduce(sub)

    def as_facts(self, sub: Sub) -> Sub:
        """Return a value reduced under the given arguments, the machine's variables kept.

        (``reduced`` reads an unset variable as its default; whether the robot sets it is
        not a fact an error may rest on.)
        """
        if self._facts is None:
            self._facts = BaseReducer(self.inputs(), read=self.read_file,
                                      environment_defaults=False)
        return self._facts.reduce(sub)

    def runs(self, origin: Origin) -> bool | None:
        """Return whether a record runs under the given arguments (``None``: unknown)."""
        result: bool | None = True
        for guard in origin.path:  # many records share guards, most as the same objects
            known = self._verdicts_by_id.get(id(guard))
            if known is not None and known[0] is guard:
                verdict = known[1]
            else:
                if guard not in self._verdicts:
                    self._verdicts[guard] = self._base.guard(guard)
                verdict = self._verdicts[guard]
                self._verdicts_by_id[id(guard)] = (guard, verdict)
            if verdict is False:
                return False
            if verdict is None:
                result = None
        return result

    @property
    def stopped_early(self) -> bool:
        """Return whether the evaluation stopped before its end (absence is unknown).

        An OpaqueFunction stopped at a configuration nothing sets, or the walk at a bound.
        """
        return bool(self.stops) or self.cut_short

    def handed(self) -> set[int]:
        """Return the actions (by ``id``) given to code launchverify cannot see.

        That code may run them: that launchverify sees no one run them is no fact.
        """
        return {id(action) for loaded in self.files.values() if loaded.launch is not None
                for action in loaded.launch.handed}

    def unseen(self) -> list[tuple[str, Span]]:
        """Return what the evaluation could not see into, and where: why it is incomplete.

        Claims that something is absent (an argument unused, a parameter block for no
        node) are not made on an incomplete evaluation; ``check --explain`` lists this.
        """
        out = [(f"include {include.status} ({self.display(include.location)})",
                include.origin.span)
               for include in self.includes if include.status not in ("loaded", "cycle")]
        out += [(record.problem.message, record.problem.span) for record in self.problems
                if record.problem.kind is ProblemKind.UNMODELED]
        out += [(f"an OpaqueFunction stopped at configuration {name!r}, which nothing sets "
                 "here", origin.span) for name, origin in self.stops]
        return list(dict.fromkeys(out))

    def not_followed(self) -> list[NotFollowed]:
        """Return the includes and package references the workspace and underlays lack.

        Each once, as met. An include counts when its path names a package found nowhere
        (``$(find-pkg-share nav2_bringup)/launch/...``); one whose path rests on an argument
        or the environment is only in ``unseen``.
        """
        out = [NotFollowed("package", ref.name, ref.origin.span)
               for ref in self.packages if not ref.found]
        for include in self.includes:
            if include.status not in ("unresolved", "external"):
                continue
            named = next((leaf.package for leaf in walk(include.location)
                          if isinstance(leaf, PackageFolder)), None)
            if named is not None:
                out.append(NotFollowed("include", named, include.origin.span))
        return list(dict.fromkeys(out))

    def complete_as_given(self) -> bool:
        """Return whether everything that runs under the given arguments was understood.

        ``complete`` is false as soon as anything was not, even in a branch that these
        arguments never take (an include of a package that is not there, behind
        ``slam:=true``); this asks only about what runs.
        """
        if self.complete:
            return True
        unseen = [i.origin for i in self.includes if i.status not in ("loaded", "cycle")]
        unseen += [r.origin for r in self.problems if r.problem.kind is ProblemKind.UNMODELED]
        return all(self.runs(origin) is False for origin in unseen)

    def display(self, sub: Sub | None) -> str | None:
        """Return the base value if known, else the expression."""
        if sub is None:
            return None
        return self.base(sub) or describe_value(self._base.reduce(sub))

    # ------------------------------------------------------------------ queries

    def running_nodes(self) -> Iterator[NodeRecord]:
        """Yield the nodes that run under the given arguments."""
        for node in self.nodes:
            if self.runs(node.origin):
                yield node

    def launchable_alone(self) -> bool:
        """Return whether the root is meant to be launched by itself, not only included.

        A root that another launch file of the workspace names (``included_elsewhere``)
        expects its includers to provide values: what they would fix is not reported there.
        One that no file names is an entry point, launched directly, and what ``ros2
        launch`` would fail on is reported there, reads of configurations it never
        declares included; but arguments without defaults are the user's to give, and
        what they would fix is not reported. One that declares no argument at all yet
        itself reads configurations nothing sets is a building block (nav2's old
        fragments): its reads are its interface, which only an includer (or the command
        line) gives. (One that only includes files reading them is an entry point that
        forgot to pass them.)
        """
        if self.included_elsewhere:
            return False
        if not self.root_arguments and any(
                not r.found and not r.has_default and r.origin.span.file == self.root
                for r in self.reads):
            return False
        return not any(not a.has_default and not a.conditional and a.name not in self.pinned
                       for a in self.root_arguments)

    def declared_names(self) -> set[str]:
        """Return every argument name declared anywhere in the evaluation."""
        return {arg.name for arg in self.arguments}

    def read_names(self) -> set[str]:
        """Return every configuration name read anywhere in the evaluation."""
        return {read.name for read in self.reads}

    def mentioned_names(self) -> set[str]:
        """Return every configuration name the loaded files mention, on any branch.

        (Reads on branches this evaluation did not take, and OpaqueFunctions' strings.)
        """
        names = set(self.mentioned)
        for loaded in self.files.values():
            if loaded.launch is not None:
                names |= configuration_names(loaded.launch)
        return names
