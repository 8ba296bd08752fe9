"""Walk the IR of a launch tree the way ``ros2 launch`` executes it, building the graph.

Actions are visited in launch's order (depth first, an include's actions before the next
sibling), with launch's scoping. Conditions that the launch files decide are applied;
conditions that depend on arguments or the machine extend the path condition and both
outcomes are explored. What launch runs later (a timer's actions, an event handler's
entities) is visited after the whole launch file, as launch runs it (``PendingRun``): a
timer's actions with a copy of the scope it was executed in, as jazzy hands them their
configurations; a handler's entities in the scope launch has when it handles an event, the
top level as the file left it, every group popped.
"""

from __future__ import annotations

import dataclasses
import itertools
import os
from collections import deque
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import yaml

from launchverify.evaluate.budget import BoundReached, ExpansionBudget
from launchverify.evaluate.files import FileCache
from launchverify.evaluate.nodes import NodeBuilder
from launchverify.evaluate.reducers import Ctx, DefaultsReducer, ScopeReducer, fill_unset
from launchverify.evaluate.scope import (
    GLOBAL_PARAMS,
    ROS_NAMESPACE,
    ROS_REMAPS,
    ScopedParam,
    ScopedRemap,
    Scopes,
    ScopeState,
    guarded,
)
from launchverify.evaluate.static_args import include_argument_names, static_arguments
from launchverify.evaluate.values import (
    argument_names,
    file_source,
    is_literal,
    is_unset,
    machine_dependent,
    ns_prefix,
    text_of,
    unset_read,
)
from launchverify.events import loop_closing_reruns
from launchverify.frontends import LoadedFile
from launchverify.graph import (
    ArgumentRecord,
    ConditionRecord,
    ConfigRead,
    EnvRecord,
    ExecutedRecord,
    FileRef,
    HandlerRecord,
    IncludeRecord,
    LaunchGraph,
    LaunchRecord,
    LoadRecord,
    NameRecord,
    Origin,
    PackageRef,
    ProblemRecord,
    ProcessSettings,
    RerunRecord,
    SkippedAction,
    StaticArgument,
    TransitionRequest,
)
from launchverify.ir import actions as a
from launchverify.ir import conditions as c
from launchverify.ir import subst as s
from launchverify.ir.symbolic import (
    Arg,
    Guard,
    StrEquals,
    Truthy,
    Unknown,
    Unset,
    depends_on_unknowns,
)
from launchverify.models.launch_api.placeholders import placeholder
from launchverify.models.parameter_values import typed_parameter
from launchverify.problems import Problem, ProblemKind
from launchverify.span import Span
from launchverify.workspace.packages import PackageIndex
from launchverify.workspace.paths import resolved
from launchverify.workspace.reading import read_file

MAX_INCLUDE_DEPTH = 40
MAX_LOOP = 256
MAX_FILE_CONTENT = 1024 * 1024


@dataclass(frozen=True, slots=True)
class PendingRun:
    """What launch runs later, to visit once the launch file has been visited.

    launch visits a launch file's actions in one go; timers fire and events are handled
    only afterwards. For an event it pushes ``context.locals`` around the handler's
    entities, never the launch configurations (``LaunchService.__process_event``), so they
    run in the scope current then: the top level, every group popped. Nothing in
    ``OnActionEventBase``/``EventHandler`` captures the scope at registration, in humble,
    jazzy and rolling alike. A ``TimerAction`` captures the configurations when it is
    executed and runs its actions in them (jazzy 3.4.5, rolling): ``state``.
    Kept for both is where they were written (include chain, path condition, and the
    stacks that name their records).
    """

    handler: int | None  # in ``graph.handlers``; ``None``: a timer's actions
    state: ScopeState | None  # the scope a timer captured (a handler's: when it runs)
    entities: tuple[a.Action, ...]
    ctx: Ctx
    handler_stack: tuple[int, ...]
    include_stack: tuple[IncludeRecord, ...]
    file_stack: tuple[tuple[Path, tuple[tuple[str | None, str], ...]], ...]
    current_file: Path
    calls: tuple[Span, ...]
    executing: tuple[int, ...]
    delays: tuple[float, ...]  # the timers' periods (since the launch or the handler)
    built_otherwise: int
    at_shutdown: bool


class Walker:
    """Evaluates one root launch file into a ``LaunchGraph``."""

    def __init__(self, graph: LaunchGraph, index: PackageIndex,
                 loader: FileCache, workspace: Path) -> None:
        self.graph = graph
        graph.file_reader = self.workspace_text
        self.index = index
        self.loader = loader
        self.workspace = workspace
        self.scopes = Scopes({k: s.Text(v) for k, v in graph.pinned.items()})
        self.reducer = ScopeReducer(self)
        self.nodes = NodeBuilder(self)
        self.base_check = DefaultsReducer(self)
        self.current_file = graph.root
        self.anon_counter = itertools.count(1)
        self.include_stack: list[IncludeRecord] = []
        self.handler_stack: list[int] = []  # the handlers whose entities are being run
        self.executing: list[int] = []  # graph.executed indices of the actions being run
        self.delays: list[float] = []  # periods of the timers around (since launch/handler)
        self.at_shutdown = False  # walking an OnShutdown handler: no process starts
        # what must hold for the launch to get past a failure met so far (a value outside
        # an argument's choices stops it): every later action runs only if it held
        self.goes_on: list[Guard] = []
        self.calls: list[Span] = []  # the actions being visited, innermost last
        # (action, file, loop) -> the handler its first execution ran in (None: at launch)
        self.executed_processes: dict[tuple[object, ...], int | None] = {}
        self.file_stack: list[tuple[Path, tuple[tuple[str | None, str], ...]]] = []
        self.incomplete = False  # something before this point was not understood
        # action lists being visited whose code other answers would have built otherwise
        self.built_otherwise = 0
        # the container actions that ran, by id, with their full names (LoadComposableNodes)
        self.container_names: dict[int, tuple[a.Action, s.Sub | None]] = {}
        self.budget = ExpansionBudget()  # what this root may expand (``budget.py``)
        self.maybe_failing: set[tuple[object, ...]] = set()  # ``may_fail``'s, once each
        self.pending: deque[PendingRun] = deque()  # what launch runs later: ``run_pending``

    # ------------------------------------------------------------------ recording

    def problem(self, kind: ProblemKind, message: str, span: Span, ctx: Ctx | None,
                *, contextual: bool = False, rule: str | None = None,
                harmless: bool = False, with_defaults: bool = False) -> None:
        """Record an evaluation problem (``contextual``: an includer might prevent it).

        Launch evaluates an action's fields only once its condition held. A failure met on
        a path the arguments as given do not take (an include's argument, a node's name
        under a condition false by default), or may not take (a condition on the machine),
        happens only with arguments that take it: it is ``CONDITIONAL``, for LV002 to
        report with such arguments (or not at all).
        ``with_defaults``: the failure was computed with the values as given, whatever the
        path (an OpaqueFunction's body): off the path it says nothing about what launch
        does, so that part is not judged (LV003), and the evaluation is incomplete.
        ``harmless``: what was not understood could start nothing (code run at shutdown),
        so the evaluation stays complete.
        """
        chain = ctx.chain if ctx else ()
        runs = (self.graph.runs(ctx.origin(span))
                if kind is ProblemKind.EVALUATION and ctx is not None and ctx.path else True)
        if runs is False and with_defaults:
            kind = ProblemKind.UNMODELED
            message = (f"{message}, in a part evaluated with argument values under which "
                       "it does not run: not judged (give the arguments that switch it "
                       "on to check it)")
        elif runs is not True and not with_defaults:  # off the path, or not known to be on it
            kind = ProblemKind.CONDITIONAL
        self.graph.problems.append(ProblemRecord(Problem(kind, message, span, contextual, rule),
                                                 chain, ctx.path if ctx else ()))
        if kind is ProblemKind.UNMODELED and not harmless:
            self.mark_incomplete(None if ctx is None else ctx.origin(span))

    def may_fail(self, value: s.Sub, span: Span, ctx: Ctx) -> None:
        """Keep a value over arguments evaluated off the default path (see ``probe``).

        Once per place, value and path: a value read again asks the same question.
        """
        key = (span, value, ctx.chain, ctx.path)
        if key in self.maybe_failing:
            return
        self.maybe_failing.add(key)
        self.graph.problems.append(ProblemRecord(
            Problem(ProblemKind.CONDITIONAL, f"{value.describe()} may raise", span),
            ctx.chain, ctx.path, value))

    def mark_incomplete(self, where: Origin | None = None) -> None:
        """Note that the includes being walked contain something not understood (``where``).

        Not understood where the arguments as given do not go, what it hides is not there
        with them either.
        """
        self.incomplete = True
        if not self.graph.unseen_as_given:
            self.graph.unseen_as_given = (where is None or not where.path
                                          or self.graph.runs(where) is not False)
        self.graph.complete = False
        for record in self.include_stack:
            record.complete = False

    def record_read(self, name: str, origin: Origin, found: bool, has_default: bool,
                    written: Span | None = None, value: s.Sub | None = None) -> None:
        """Record a configuration read (its name written verbatim at ``written``).

        ``value``: what it reads, when that is set on some paths only.
        """
        self.graph.reads.append(ConfigRead(name, origin, found, has_default, written, value))
        for record in self.include_stack:
            record.reads.add(name)

    def record_package(self, name: str, origin: Origin, found: bool, what: str,
                       written: Span | None = None) -> None:
        """Record a package reference (its name written verbatim at ``written``)."""
        self.graph.packages.append(PackageRef(name, origin, found, what, written))

    def record_lookups(self, lookups: tuple[tuple[str, Span], ...], ctx: Ctx) -> None:
        """Record the packages Python code looked up (get_package_share_directory...)."""
        for name, span in lookups:
            found = self.index.find(name) is not None
            self.record_package(name, Origin(span, ctx.chain, ctx.path), found, "lookup")

    def workspace_text(self, path: str) -> str | None:
        """Return a workspace file's text (``None`` outside it, missing or too large)."""
        located = self.index.locate(Path(path))
        if located is None or not self.loader.within(located, self.workspace):
            return None
        try:
            data = read_file(located, prefix=MAX_FILE_CONTENT + 1)
        except OSError:
            return None
        return None if len(data) > MAX_FILE_CONTENT else data.decode("utf-8", "replace")

    def read_file_content(self, path: str, origin: Origin) -> s.Sub:
        """Return ``$(file-content)`` of a workspace file, never reading outside it."""
        located = self.index.locate(Path(path))
        if located is None:
            inside = Path(path).is_absolute() and resolved(Path(path)).is_relative_to(
                self.workspace)
            if inside or self.index.owner(Path(path)) is not None:
                self.graph.file_refs.append(FileRef(path, origin, False, "file-content"))
            return Unknown(f"content of {path}")
        if not self.loader.within(located, self.workspace):
            return Unknown(f"content of {path}")
        self.graph.file_refs.append(FileRef(path, origin, True, "file-content"))
        text = self.workspace_text(path)
        return Unknown(f"content of {path}") if text is None else s.Text(text)

    # ------------------------------------------------------------------ entry

    def run(self) -> None:
        """Evaluate the root file as ``ros2 launch ROOT args...`` does."""
        ctx = Ctx(file=self.graph.root, chain=(), path=())
        loaded = self.load(self.graph.root, ctx, root=True)
        if loaded.launch is None:
            return
        self.graph.root_arguments = self.static_args(loaded)
        pinned = tuple(sorted((k, v) for k, v in self.graph.pinned.items()))
        self.file_stack.append((self.graph.root, pinned))
        self.record_lookups(loaded.launch.lookups, ctx)
        self.graph.mentioned.update(loaded.launch.mentions)
        try:
            try:
                self.visit_all(loaded.launch.actions, ctx)
            finally:
                self.file_stack.pop()
            self.run_pending()  # the events launch handles once the file is visited
        except BoundReached as reached:
            self.cut_short(reached)
        self.name_rerun_loops()

    def cut_short(self, reached: BoundReached) -> None:
        """Keep what the walk found before a bound stopped it, and say so on the root.

        The graph is incomplete and stopped early: rules claim nothing absent from it.
        """
        where = f", stopped at {reached.where.short()}" if reached.where else ""
        self.graph.cut_short = True
        self.graph.problems.append(ProblemRecord(Problem(
            ProblemKind.UNMODELED,
            f"not checked past {reached.message} (the most launchverify evaluates of one "
            f"launch file with all it includes{where}): the rest of this launch is not "
            "evaluated", Span.of_file(self.graph.root))))
        self.mark_incomplete()

    def stopping(self, reached: BoundReached) -> None:
        """Note where a bound was reached; every include being walked is incomplete."""
        reached.where = self.calls[-1] if self.calls else None
        self.mark_incomplete()

    def name_rerun_loops(self) -> None:
        """Give LV501 the reruns that close a loop of handlers (it explains the loop)."""
        for rerun in loop_closing_reruns(self.graph):
            record = self.graph.problems[rerun.problem]
            self.graph.problems[rerun.problem] = dataclasses.replace(
                record, problem=dataclasses.replace(record.problem, rule="LV501"))

    def load(self, path: Path, ctx: Ctx, *, root: bool = False) -> LoadedFile:
        """Load a file (cached by the loader) and record its problems once.

        A ROS 1 file checked on its own (``root``) gives its one info and is not walked;
        included, it gives its parse errors like any file ros2 launch cannot load.
        """
        loaded: LoadedFile = self.loader(path)
        if root and loaded.ros1 is not None:
            loaded = dataclasses.replace(loaded, launch=None, problems=[loaded.ros1])
        for record in self.include_stack:
            record.files.add(path)
        if path not in self.graph.files:
            self.graph.files[path] = loaded
            for problem in loaded.problems:
                self.graph.problems.append(ProblemRecord(problem, ctx.chain, ctx.path))
            if loaded.launch is None:
                self.mark_incomplete()
        return loaded

    def static_args(self, loaded: LoadedFile) -> tuple[StaticArgument, ...]:
        """Return the statically discovered arguments of a loaded file (cached per run)."""
        if loaded.launch is None:
            return ()
        cache = self.loader.static_arguments
        if loaded.path in cache:
            return cache[loaded.path]
        out = []
        for declaration, includes, conditional in static_arguments(
            loaded.launch, self.loader, self.index, self.loader.static_subtrees
        ):
            via = tuple(self.include_names(i) for i in includes)
            out.append(StaticArgument(
                declaration.name, declaration.default is not None, conditional,
                declaration.span, declaration.description, via,
            ))
        cache[loaded.path] = tuple(out)
        return cache[loaded.path]

    def include_names(self, include: a.Include) -> frozenset[str]:
        """Return the argument names an include passes, without context (cached per run)."""
        cache = self.loader.include_names
        found = cache.get(id(include))
        if found is None:
            found = cache[id(include)] = frozenset(include_argument_names(include, self.index))
        return found

    # ------------------------------------------------------------------ visiting

    def visit_all(self, actions: tuple[a.Action, ...], ctx: Ctx) -> None:
        """Visit actions in order."""
        # code that built them branched on unknowns: other answers may have built more,
        # before any of them (a declaration, say)
        others = any(isinstance(x, a.OpaqueAction) and x.anywhere for x in actions)
        self.built_otherwise += others
        try:
            for action in actions:
                self.visit(action, ctx)
        finally:
            self.built_otherwise -= others

    def visit(self, action: a.Action, ctx: Ctx) -> None:
        """Visit one action: evaluate its condition, then execute it (within the budget)."""
        try:
            self.budget.action(len(self.graph.nodes))
        except BoundReached as reached:
            self.stopping(reached)
            raise
        self.calls.append(action.span)
        try:
            self._visit(action, ctx)
        finally:
            self.calls.pop()

    def _visit(self, action: a.Action, ctx: Ctx) -> None:
        where = action.attr_spans.get("if") or action.attr_spans.get("unless") or action.span
        for guard in self.goes_on:
            if guard not in ctx.path:
                ctx = ctx.guarded(guard)
        inner = self.apply_condition(action.condition, where, ctx)
        if inner is None:
            self.graph.skipped.append(SkippedAction(action, ctx.origin(action.span)))
            return
        if self.at_shutdown and isinstance(action, (a.ExecuteProcess, a.Node)):
            return  # launch starts no process once shutdown has begun
        handler = getattr(self, "do_" + type(action).__name__, None)
        if handler is None:
            self.problem(ProblemKind.UNMODELED,
                         f"action {type(action).__name__} is not modelled", action.span, inner)
            return
        if self.record_execution(action, inner):
            self.executing.append(len(self.graph.executed) - 1)
            try:
                handler(action, inner)
            finally:
                self.executing.pop()

    @property
    def execution(self) -> int | None:
        """Return the index in ``graph.executed`` of the action being executed."""
        return self.executing[-1] if self.executing else None

    def apply_condition(self, condition: c.Condition | None, span: Span, ctx: Ctx) -> Ctx | None:
        """Return the context inside a condition, or ``None`` when it is surely false."""
        if condition is None:
            return ctx
        reducer = self.reducer.at(ctx, span)
        guard: Guard
        literal = False
        if isinstance(condition, (c.IfCondition, c.UnlessCondition)):
            negate = isinstance(condition, c.UnlessCondition)
            value = reducer.reduce(condition.expression)
            guard = Truthy(value, negate, where=span)
            literal = is_literal(condition.expression)
        elif isinstance(condition, c.ConfigEquals):
            name = reducer.text(condition.name)
            current = (Unknown("configuration") if name is None
                       else self.scopes.get(name) or Unset(name))
            if name is not None:
                self.record_read(name, ctx.origin(span), not isinstance(current, Unset), True,
                                 s.written_at(condition.name))
            expected = None if condition.expected is None else reducer.reduce(condition.expected)
            guard = StrEquals(current, expected, condition.negate, where=span)
        else:
            self.problem(ProblemKind.UNMODELED, f"condition {condition.describe()} is not "
                         "modelled", span, ctx)
            return ctx.guarded(_opaque(condition.describe(), span))
        verdict = reducer.guard(guard)
        if isinstance(guard, Truthy) and verdict is None and text_of(guard.expression) is not None:
            verdict = False  # an invalid constant condition: launch raises (recorded)
        override = None
        if verdict is not None and not literal:  # the same file: in others, includers decide
            override = next((found for name in read_names(condition)
                             if (found := self.scopes.overrides.get(name)) is not None
                             and found.span.file == span.file), None)
        self.graph.conditions.append(ConditionRecord(
            ctx.origin(span), condition, guard, verdict, literal, override))
        if verdict is True:
            return ctx
        if verdict is False:
            return None
        if self.graph.runs(ctx.origin(span)) is not False:
            self.base_check.at(ctx, span).guard(guard)
        return ctx.guarded(guard)

    @contextmanager
    def scope(self, configs: bool = True, env: bool = True) -> Iterator[None]:
        """Run a block in a pushed scope."""
        if configs:
            self.scopes.push_configs()
        if env:
            self.scopes.push_env()
        try:
            yield
        finally:
            if env:
                self.scopes.pop_env()
            if configs:
                self.scopes.pop_configs()

    # ------------------------------------------------------------------ launch actions

    def do_DeclareArgument(self, action: a.DeclareArgument, ctx: Ctx) -> None:
        reducer = self.reducer.at(ctx, action.span)
        default = None if action.default is None else reducer.reduce(action.default)
        existing = self.scopes.get(action.name)
        if existing is None or is_unset(existing):
            value: s.Sub = Arg(action.name, default)
            if existing is not None:
                value = fill_unset(existing, value)
            self.scopes.set(action.name, value, ctx.path)
            self.scopes.overrides.pop(action.name, None)
        current = self.scopes.get(action.name) or Unset(action.name)
        given = text_of(current)
        if action.choices is not None and given is not None and given not in action.choices:
            self.problem(
                ProblemKind.EVALUATION,
                f"argument {action.name!r} gets value {given!r}, which is not one of its "
                f"choices {list(action.choices)} (ros2 launch fails)",
                action.span, ctx,
            )
            self.stops_unless(current, action.choices, action.span)
        elif action.choices is not None and given is None and existing is not None \
                and not is_unset(existing) and self.graph.runs(ctx.origin(action.span)):
            # An includer passes a value that depends on its arguments: with their
            # defaults it must still be a choice (its own default is LV203's to judge).
            # Reported where the includer passes it, when it does so by name.
            chosen = self.base_check.at(ctx, action.span).text(current)
            if chosen is not None and chosen not in action.choices:
                where, at = self.passed_at(action.name, ctx, action.span)
                self.base_check.at(at, where).fail(
                    f"argument {action.name!r} of {action.span.short()} gets value "
                    f"{chosen!r}, which is not one of its choices {list(action.choices)} "
                    "(ros2 launch fails)")
                self.stops_unless(current, action.choices, action.span)
        self.graph.arguments.append(ArgumentRecord(
            action.name, ctx.origin(action.span), default, action.description,
            action.choices, current, action,
        ))
        for record in self.include_stack:
            record.declared.add(action.name)

    def stops_unless(self, value: s.Sub, choices: tuple[str, ...], where: Span) -> None:
        """Note that launch stops here unless ``value`` is one of ``choices``.

        What comes after runs only if it is: a finding there (a parameter file named by
        the bad value) is about code the launch never reaches.
        """
        self.goes_on.append(Truthy(
            s.AnySub(tuple(s.EqualsSub(value, s.Text(c)) for c in choices)), where=where))

    def passed_at(self, name: str, ctx: Ctx, declared: Span) -> tuple[Span, Ctx]:
        """Return where the innermost include passes argument ``name`` (and its context).

        Falls back to the declaration when the value came another way (an XML include
        passes every configuration of its scope).
        """
        if self.include_stack:
            record = self.include_stack[-1]
            for passed, _value, span in record.arguments:
                if passed == name:
                    origin = record.origin
                    return span, Ctx(span.file, origin.chain, origin.path)
        return declared, ctx

    def do_SetConfig(self, action: a.SetConfig, ctx: Ctx) -> None:
        reducer = self.reducer.at(ctx, action.span)
        name = reducer.text(action.name)
        value = reducer.reduce(action.value)
        if name is None:
            self.problem(ProblemKind.UNMODELED, "a configuration whose name is computed is "
                         "not modelled", action.span, ctx)
            return
        previous = self.scopes.get(name)
        self.scopes.set(name, value, ctx.path)
        current = self.scopes.get(name)
        if (previous is not None and depends_on_argument(previous, name)
                and current is not None and not depends_on_argument(current, name)):
            self.scopes.overrides[name] = ctx.origin(action.span)
        else:
            self.scopes.overrides.pop(name, None)
        for record in self.include_stack:
            record.declared.add(name)

    def do_UnsetConfig(self, action: a.UnsetConfig, ctx: Ctx) -> None:
        name = self.reducer.at(ctx, action.span).text(action.name)
        if name is not None:
            self.scopes.set(name, Unset(name), ctx.path)

    def do_ResetConfigs(self, action: a.ResetConfigs, ctx: Ctx) -> None:
        reducer = self.reducer.at(ctx, action.span)
        keep = {}
        for name_sub, value_sub in action.keep or ():
            name = reducer.text(name_sub)
            if name is not None:
                keep[name] = reducer.reduce(value_sub)
        self.scopes.configs.clear()
        self.scopes.configs.update(keep)

    def do_PushConfigs(self, action: a.PushConfigs, ctx: Ctx) -> None:
        self.scopes.push_configs()

    def do_PopConfigs(self, action: a.PopConfigs, ctx: Ctx) -> None:
        if not self.scopes.pop_configs():
            self.problem(ProblemKind.EVALUATION,
                         "launch_configurations stack unexpectedly empty", action.span, ctx)

    def do_Group(self, action: a.Group, ctx: Ctx) -> None:
        reducer = self.reducer.at(ctx, action.span)
        keep = [(reducer.text(n), reducer.reduce(v)) for n, v in action.keep]
        if not action.scoped:
            for name, value in keep:
                if name is not None:
                    self.scopes.set(name, value, ctx.path)
            self.visit_all(action.actions, ctx)
            return
        with self.scope():
            if not action.forwarding:
                self.scopes.reset_env()
                self.scopes.configs.clear()
            for name, value in keep:
                if name is not None:
                    self.scopes.set(name, value, () if not action.forwarding else ctx.path)
            self.visit_all(action.actions, ctx)

    def do_Include(self, action: a.Include, ctx: Ctx) -> None:
        reducer = self.reducer.at(ctx, action.span)
        location = reducer.reduce(action.path)
        origin = ctx.origin(action.span)
        record = IncludeRecord(origin=origin, action=action, location=location, target=None,
                               status="loaded")
        self.graph.includes.append(record)
        written = text_of(location)
        as_given = None if written is not None else self.graph.base(location)
        if written is None and self.include_candidates(action, ctx, record, as_given is None):
            return
        path_text = written or as_given
        if path_text is None:
            record.status = "unresolved"
            record.arguments = self.passed_arguments(action, ctx)
            self.mark_incomplete()
            return
        self.include_path(action, ctx, record, path_text)

    def passed_arguments(self, action: a.Include, ctx: Ctx
                         ) -> tuple[tuple[str | None, s.Sub, Span], ...]:
        """Return what an include passes to a file launchverify does not read.

        For ``graph`` and the models of known files (a domain_bridge's ``config``).
        """
        passed = []
        for argument in action.arguments:
            reducer = self.reducer.at(ctx, argument.span)
            passed.append((text_of(reducer.reduce(argument.name)),
                           reducer.reduce(argument.value), argument.span))
        return tuple(passed)

    def include_candidates(self, action: a.Include, ctx: Ctx, record: IncludeRecord,
                           patterns: bool) -> bool:
        """Follow an include whose path an argument computes, once per value it may take.

        Each value is an include of its own under the guard ``argument == value``, so a
        finding in one sensor's file names the value that reaches it. ``False`` when the
        path is not computed from one argument with known candidates. ``patterns``: the
        workspace may give them (the arguments as given name no file); otherwise only the
        argument's choices do.
        """
        from launchverify.evaluate.candidates import candidates_of

        found = candidates_of(action.path, self.scopes, self.graph, self.index,
                              self.reducer.at(ctx, action.span), patterns)
        if found is None:
            return False
        record.status = "computed"
        record.computed_from = found.name
        record.candidates = found.values
        if not found.complete:
            self.mark_incomplete()  # the value as given names no file tried
        current = self.current_file  # each branch starts where the include is written
        for value in found.values:
            self.current_file = current
            guard = StrEquals(found.input, s.Text(value), where=action.span)
            if self.reducer.at(ctx, action.span).guard(guard) is False:
                continue
            inner = ctx.guarded(guard)
            with self.scope(env=False):
                self.scopes.set(found.name, s.Text(value), ())
                location = self.reducer.at(inner, action.span).reduce(action.path)
                path_text = text_of(location)
                branch = IncludeRecord(origin=inner.origin(action.span), action=action,
                                       location=location, target=None, status="loaded",
                                       computed_from=found.name, candidates=(value,))
                self.graph.includes.append(branch)
                if path_text is None:
                    branch.status = "unresolved"
                    self.mark_incomplete()
                    continue
                self.include_path(action, inner, branch, path_text)
        return True

    def include_path(self, action: a.Include, ctx: Ctx, record: IncludeRecord,
                     path_text: str) -> None:
        """Follow an include to the file ``path_text`` names (the rest of ``do_Include``)."""
        written_in = ctx.file
        location = record.location
        target, note = self.resolve_path(path_text, written_in, action.path)
        record.note = note
        if target is None:
            absent = self.in_workspace(Path(path_text)) and not machine_dependent(location)
            record.status = "missing" if absent else "external"
            record.arguments = self.passed_arguments(action, ctx)
            self.mark_incomplete()
            return
        record.target = target
        record.relative = not Path(path_text).is_absolute()
        inner = dataclasses.replace(ctx, file=target, chain=(*ctx.chain, action.span))
        loaded = self.load(target, inner)
        if loaded.launch is None:
            record.status = "unreadable" if loaded.format != "python" else "unmodeled"
            self.mark_incomplete()
            return
        record.files.add(target)
        record.static_arguments = self.static_args(loaded)
        # launch sets the current file before the arguments are evaluated: $(dirname) in an
        # include argument is the included file's folder.
        self.current_file = target  # and never restores it (before rolling 3.9.6)
        # Whether a configuration nothing set here is unset when launch gets here: not when
        # what launchverify does not see may have set it.
        seen_all = not self.graph.unseen_as_given and not self.built_otherwise
        arguments = []
        for argument in action.arguments:  # one after another: later ones see earlier ones
            arg_reducer = self.reducer.at(ctx, argument.span)
            name_value = arg_reducer.reduce(argument.name)
            name = text_of(name_value)
            record.unknown_names |= name is None and depends_on_unknowns(name_value)
            value = arg_reducer.reduce(argument.value)
            if not seen_all and is_unset(value):
                value = set_elsewhere(value)
            arguments.append((name, value, argument.span))
            if name is not None:
                self.scopes.set(name, value, ctx.path)
                self.scopes.overrides.pop(name, None)  # what the includer passes counts
        record.arguments = tuple(arguments)
        # launch sets the arguments as configurations (SetLaunchConfiguration) before the
        # file's actions run: a value that reads a configuration nothing set raises there,
        # at this include (LV201 reports the read), and the file runs only where every value
        # is set: with a value given for that configuration (ros2 launch's name:=value sets
        # any), as a condition false with the arguments as given. Its code never runs on a
        # value it would not get.
        for _name, value, span in arguments:
            if is_unset(value):
                inner = inner.guarded(StrEquals(value, None, negate=True, where=span))
        # Re-entering a file with the same arguments can only recurse forever; with other
        # arguments it may terminate (a recursion guarded by a condition), up to a depth.
        key = (target, tuple(sorted(((name, value.describe()) for name, value, _ in arguments),
                                    key=lambda pair: (pair[0] or "", pair[1]))))
        if key in self.file_stack or len(self.file_stack) >= MAX_INCLUDE_DEPTH:
            record.status = "cycle"
            return
        missing = record.missing_required()
        if missing:  # launch raises here: what the file would start is not certain to run
            inner = inner.guarded(_opaque(f"{target.name} misses required argument "
                                          f"{missing[0].name!r}", action.span))
        try:
            self.budget.include()
        except BoundReached as reached:
            record.complete = False
            self.stopping(reached)
            raise
        self.include_stack.append(record)
        self.file_stack.append(key)
        self.record_lookups(loaded.launch.lookups, inner)
        self.graph.mentioned.update(loaded.launch.mentions)
        for each in self.include_stack:
            each.mentioned.update(loaded.launch.mentions)
        try:
            self.visit_all(loaded.launch.actions, inner)
        finally:
            self.file_stack.pop()
            self.include_stack.pop()

    def in_workspace(self, path: Path) -> bool:
        """Return whether a missing file would belong to the checked tree."""
        if not path.is_absolute():
            return True
        return path.is_relative_to(self.workspace) or self.index.owner(path) is not None

    def resolve_path(self, text: str, written_in: Path, written: s.Sub) -> tuple[Path | None, str]:
        """Find an included or referenced file; explain launch's quirks in a note."""
        path = Path(text)
        note = ""
        uses_dirname = any(isinstance(x, (s.ThisLaunchFileDir, s.ThisLaunchFile))
                           for x in s.walk(written))
        if uses_dirname and self.current_file != written_in:
            note = (f"$(dirname) here is the folder of {self.current_file.name}: ros2 launch "
                    "does not restore it after an include (fixed only in rolling)")
        if not path.is_absolute():
            beside = written_in.parent / path
            note = ("relative paths are resolved against the folder ros2 launch is started "
                    "from, not the including file; use $(dirname)/" + text)
            return (self.index.canonical(beside) if beside.is_file() else None), note
        return self.index.locate(path), note

    def do_Timer(self, action: a.Timer, ctx: Ctx) -> None:
        period = self.reducer.at(ctx, action.span).text(action.period)
        try:
            seconds = max(float(period), 0.0) if period is not None else 0.0
        except ValueError:
            seconds = 0.0
        self.defer(None, self.scopes.state(), action.actions, ctx, (*self.delays, seconds))

    def do_ForLoop(self, action: a.ForLoop, ctx: Ctx) -> None:
        reducer = self.reducer.at(ctx, action.span)
        length_text = reducer.text(action.length)
        try:
            length = int(length_text) if length_text is not None else None
        except ValueError:
            self.problem(ProblemKind.EVALUATION,
                         f"for loop length {length_text!r} is not an integer", action.span, ctx)
            return
        if length is None:
            self.problem(ProblemKind.UNMODELED, "a for loop whose length depends on arguments "
                         "is walked once", action.span, ctx)
            iterations: list[s.Sub] = [Unknown("loop index")]
        else:
            iterations = [s.Text(str(i)) for i in range(min(length, MAX_LOOP))]
        for value in iterations:
            inner = dataclasses.replace(ctx, loop=(*ctx.loop, (action.name, value, True)))
            self.visit_all(action.actions, inner)

    def do_ForEach(self, action: a.ForEach, ctx: Ctx) -> None:
        reducer = self.reducer.at(ctx, action.span)
        text = reducer.text(action.values)
        if text is None:
            self.problem(ProblemKind.UNMODELED, "for_each over values that depend on "
                         "arguments is not modelled", action.span, ctx)
            return
        for chunk in [part for part in text.split(";") if part.strip()][:MAX_LOOP]:
            try:
                mapping = yaml.safe_load(chunk)
            except yaml.YAMLError as error:
                self.problem(ProblemKind.EVALUATION, f"for_each value {chunk!r} is not YAML: "
                             f"{error}", action.span, ctx)
                return
            if not isinstance(mapping, dict):
                self.problem(ProblemKind.EVALUATION, f"for_each value {chunk!r} is not a "
                             "mapping", action.span, ctx)
                return
            loop = tuple((str(k), s.Text(str(v)), False) for k, v in mapping.items())
            self.visit_all(action.actions, dataclasses.replace(ctx, loop=(*ctx.loop, *loop)))

    # ------------------------------------------------------------------ environment

    def do_SetEnv(self, action: a.SetEnv, ctx: Ctx) -> None:
        reducer = self.reducer.at(ctx, action.span)
        name = reducer.text(action.name)
        if name is not None:
            value = reducer.reduce(action.value)
            self.graph.environment_sets.append(EnvRecord(name, value, ctx.origin(action.span)))
            self.scopes.env[name] = _guard_env(ctx, value, self.scopes.env.get(name), name)

    def do_UnsetEnv(self, action: a.UnsetEnv, ctx: Ctx) -> None:
        name = self.reducer.at(ctx, action.span).text(action.name)
        if name is not None:
            self.scopes.env[name] = None if not ctx.path else Unknown(f"environment {name}")

    def do_AppendEnv(self, action: a.AppendEnv, ctx: Ctx) -> None:
        reducer = self.reducer.at(ctx, action.span)
        name = reducer.text(action.name)
        if name is None:
            return
        value = reducer.reduce(action.value)
        separator = s.Text(os.pathsep) if action.separator is None else reducer.reduce(
            action.separator)
        previous = self.scopes.env.get(name) or reducer.environment(name, None)
        prepend = action.prepend if isinstance(action.prepend, bool) else (
            reducer.text(s.NotSub(s.NotSub(action.prepend))) == "true")
        parts = [value, separator, previous] if prepend else [previous, separator, value]
        joined = s.concat(parts)
        self.scopes.env[name] = _guard_env(ctx, joined, self.scopes.env.get(name), name)

    def do_ResetEnv(self, action: a.ResetEnv, ctx: Ctx) -> None:
        self.scopes.reset_env()

    def do_PushEnv(self, action: a.PushEnv, ctx: Ctx) -> None:
        self.scopes.push_env()

    def do_PopEnv(self, action: a.PopEnv, ctx: Ctx) -> None:
        if not self.scopes.pop_env():
            self.problem(ProblemKind.EVALUATION, "environment stack unexpectedly empty",
                         action.span, ctx)

    # ------------------------------------------------------------------ ROS scope

    def do_PushNamespace(self, action: a.PushNamespace, ctx: Ctx) -> None:
        reducer = self.reducer.at(ctx, action.span)
        pushed = reducer.reduce(action.namespace)
        previous = self.scopes.get(ROS_NAMESPACE)
        combined = ns_prefix(None if previous is None else reducer.decided(previous), pushed)
        assert combined is not None
        origin = ctx.origin(action.at("namespace"))
        self.record_name("namespace", combined, origin)
        # Without a pushed namespace launch_ros uses none, which names nodes like "/".
        self.scopes.set(ROS_NAMESPACE, combined, ctx.path, unset=s.Text("/"))

    def do_SetRemap(self, action: a.SetRemap, ctx: Ctx) -> None:
        reducer = self.reducer.at(ctx, action.span)
        origin = ctx.origin(action.span)
        src, dst = reducer.reduce(action.src), reducer.reduce(action.dst)
        self.record_name("remap", src, ctx.origin(action.at("from")))
        self.record_name("remap", dst, ctx.origin(action.at("to")))
        self.scopes.append_shared(ROS_REMAPS, ScopedRemap(src, dst, origin, ctx.path))

    def do_SetParameter(self, action: a.SetParameter, ctx: Ctx) -> None:
        reducer = self.reducer.at(ctx, action.span)
        value = action.value.value
        reduced = reducer.reduce(value) if isinstance(value, s.Sub) else value
        self.scopes.append_shared(GLOBAL_PARAMS, ScopedParam(
            ctx.origin(action.span), ctx.path, name=reducer.reduce(action.name), value=reduced,
            value_type=action.value.value_type))

    def do_SetParametersFromFile(self, action: a.SetParametersFromFile, ctx: Ctx) -> None:
        reducer = self.reducer.at(ctx, action.span)
        location = reducer.reduce(action.filename)
        self.nodes.check_file(file_source(location), ctx.origin(action.at("filename")),
                              "parameter file", ctx, action.filename)
        self.scopes.append_shared(GLOBAL_PARAMS, ScopedParam(
            ctx.origin(action.span), ctx.path, file=location,
            source=self.nodes.read_param_file(location)))

    def do_SetUseSimTime(self, action: a.SetUseSimTime, ctx: Ctx) -> None:
        """Only the launch process's own node: nothing reaches launched nodes."""

    def do_SetRosLogDir(self, action: a.SetRosLogDir, ctx: Ctx) -> None:
        """Changes where logs go; nothing the graph models."""

    def do_Log(self, action: a.Log, ctx: Ctx) -> None:
        message = self.reducer.at(ctx, action.span).reduce(action.message)
        if self.execution is not None:
            self.graph.logs[self.execution] = (action.level, message)

    def do_Shutdown(self, action: a.Shutdown, ctx: Ctx) -> None:
        """Ends the launch at run time; statically nothing to record."""

    def do_RegisterEventHandler(self, action: a.RegisterEventHandler, ctx: Ctx) -> None:
        handler = action.handler
        if isinstance(handler.target, a.OpaqueAction):  # when unknown code's process acts
            ctx = ctx.guarded(_opaque(f"{handler.event} of {handler.target.description}",
                                      action.span))
        index = self.record_handler(ctx.origin(action.span), handler.event, handler.target,
                                    handler.handle_once, handler.filters,
                                    handler.custom_matcher, handler.filter_spans)
        # OnShutdown runs when the launch ends: logs, cleanup
        self.run_handler(index, handler.entities, ctx, at_shutdown=handler.event == "shutdown")

    def record_execution(self, action: a.Action, ctx: Ctx) -> bool:
        """Record that an action executes; return ``False`` when launch refuses to.

        launch refuses to execute an ``ExecuteProcess``/``Node`` object a second time
        (``executed more than once``): in Python one object added twice, or run again by
        an event handler. Each include and each loop iteration makes new objects.
        """
        within = self.handler_stack[-1] if self.handler_stack else None
        instance = id(self.include_stack[-1]) if self.include_stack else 0
        if isinstance(action, (a.ExecuteProcess, a.Node)):
            key = (id(action), instance, ctx.loop)
            if key in self.executed_processes:
                if within is None:  # what launch runs first; a handler's run comes later
                    within = self.executed_processes[key]
                when = "" if within is None else (
                    f" when the {self.graph.handlers[within].event.replace('_', ' ')} "
                    f"handler at {self.graph.handlers[within].origin.span.short()} runs it")
                self.problem(ProblemKind.EVALUATION, "this process is executed a second "
                             f"time{when}: ros2 launch raises ('executed more than once')",
                             action.span, ctx)
                if within is not None:
                    self.graph.reruns.append(RerunRecord(
                        ctx.origin(action.span), action, within, len(self.graph.problems) - 1))
                return False
            self.executed_processes[key] = within
        self.graph.executed.append(ExecutedRecord(
            ctx.origin(action.span), action, within, instance, ctx.loop,
            sum(self.delays) if self.delays else None))
        return True

    def record_handler(self, origin: Origin, event: str, target: object | None,
                       once: bool, filters: tuple[tuple[str, str], ...] = (),
                       custom: bool = False,
                       filter_spans: tuple[tuple[str, Span], ...] = ()) -> int:
        """Record an event handler; return its index in ``graph.handlers``."""
        self.graph.handlers.append(HandlerRecord(
            origin, event, target, once, self.handler_stack[-1] if self.handler_stack else None,
            self.execution, filters, custom, filter_spans))
        return len(self.graph.handlers) - 1

    def run_handler(self, index: int, entities: tuple[a.Action, ...], ctx: Ctx, *,
                    at_shutdown: bool = False) -> None:
        """Visit what a handler runs when its event happens: later, in the scope of then."""
        # timers in the handler start when it fires
        self.defer(index, None, entities, ctx, (), at_shutdown=at_shutdown)

    def defer(self, handler: int | None, state: ScopeState | None,
              entities: tuple[a.Action, ...], ctx: Ctx, delays: tuple[float, ...], *,
              at_shutdown: bool = False) -> None:
        """Queue what launch runs later for ``run_pending``, with where it is written."""
        self.pending.append(PendingRun(
            handler, state, entities, dataclasses.replace(ctx, deferred=True),
            tuple(self.handler_stack), tuple(self.include_stack), tuple(self.file_stack),
            self.current_file, tuple(self.calls), tuple(self.executing), delays,
            self.built_otherwise, self.at_shutdown or at_shutdown))

    def run_pending(self) -> None:
        """Visit timers' actions and handlers' entities as launch does, in the order queued.

        A handler's entities start from the scope the launch file left at its top level,
        after its last action (a configuration set there later than the handler's group
        counts); one registered by another handler's entities starts from the scope that
        one left (it ran, unscoped, at the top level before this event could come). What
        unrelated handlers leave set depends on which event comes first, which is not
        modelled: each starts from the launch file's top level.
        """
        top = self.scopes.state()
        left: dict[int | None, ScopeState] = {}  # what each handler's entities left
        saved = (self.handler_stack, self.include_stack, self.file_stack, self.current_file,
                 self.calls, self.executing, self.built_otherwise, self.at_shutdown)
        try:
            while self.pending:
                run = self.pending.popleft()
                if run.state is not None:
                    self.scopes.restore(run.state)
                else:
                    assert run.handler is not None
                    self.scopes.restore(left.get(self.graph.handlers[run.handler].within, top))
                self.visit_pending(run)
                if run.handler is not None:
                    left[run.handler] = self.scopes.state()
        finally:
            (self.handler_stack, self.include_stack, self.file_stack, self.current_file,
             self.calls, self.executing, self.built_otherwise, self.at_shutdown) = saved
            self.scopes.restore(top)
            self.delays = []

    def visit_pending(self, run: PendingRun) -> None:
        """Visit one deferred list of actions where it was written (its stacks), unscoped."""
        within = [] if run.handler is None else [run.handler]
        self.handler_stack = [*run.handler_stack, *within]
        self.include_stack = list(run.include_stack)
        self.file_stack = list(run.file_stack)
        self.current_file = run.current_file
        self.calls = list(run.calls)
        self.executing = list(run.executing)
        self.built_otherwise = run.built_otherwise
        self.at_shutdown = run.at_shutdown
        self.delays = list(run.delays)
        self.visit_all(run.entities, run.ctx)

    def do_EmitEvent(self, action: a.EmitEvent, ctx: Ctx) -> None:
        """Record lifecycle requests; other events are left to the event analysis."""
        if action.event not in ("ChangeState", "LifecycleTransition"):
            return
        reducer = self.reducer.at(ctx, action.span)
        self.graph.requests.append(TransitionRequest(
            ctx.origin(action.span),
            "change_state" if action.event == "ChangeState" else "lifecycle_transition",
            tuple(reducer.reduce(t) for t in action.transition_ids), action.matcher,
            self.execution, action.target, tuple(reducer.reduce(n) for n in action.target_names),
        ))

    def do_OpaqueFunction(self, action: a.OpaqueFunction, ctx: Ctx) -> None:
        """Run the function's body with the configurations as they are here."""
        result = self.loader.opaque_result(action, self.concrete_configurations(),
                                           self.current_file, id(self.graph))
        failed = {read[0]: read[3] for read in result.reads if len(read) == 4}
        for name, found, has_default, *_ in dict.fromkeys(result.reads):
            if name in failed and not found:
                continue
            self.record_read(name, ctx.origin(action.span), found, has_default)
        for name, span in failed.items():
            self.record_read(name, ctx.origin(span), False, False)
        if failed:
            self.graph.stops += [(name, ctx.origin(span)) for name, span in failed.items()]
            for record in self.include_stack:
                record.complete = False
        self.record_lookups(result.lookups, ctx)
        self.graph.mentioned.update(result.mentions)
        for record in self.include_stack:
            record.mentioned.update(result.mentions)
        for problem in result.problems:
            assert isinstance(problem, Problem)
            # At shutdown launch starts nothing more: what a failing body would have given
            # (a temporary file removed, say) leaves the evaluation complete.
            self.problem(problem.kind, problem.message, problem.span, ctx,
                         contextual=problem.contextual, harmless=self.at_shutdown,
                         with_defaults=True)
            if problem.kind is ProblemKind.EVALUATION and not self.at_shutdown:
                # the body stopped at an exception: what it would have read and started
                # is unknown, so absence rules (unused arguments...) must not judge
                self.mark_incomplete(ctx.origin(action.span))
        self.visit_all(result.actions, ctx)

    def concrete_configurations(self) -> dict[str, Any]:
        """Return the configurations in scope as strings.

        An argument without a value takes its first choice when it has choices, else a
        placeholder (Python code then sees an unknown value, not an arbitrary one).
        """
        choices = {arg.name: arg.choices for arg in self.graph.arguments if arg.choices}
        out: dict[str, Any] = {}
        for name, value in self.scopes.configs.items():
            if name == GLOBAL_PARAMS:  # launch_ros keeps (name, value) pairs and file paths
                out[name] = [self.concrete_param(p) for p in value]
                continue
            if not isinstance(value, s.Sub) or isinstance(value, Unset):
                continue  # launch_ros's other lists; one nothing sets here (launch has none)
            text = self.graph.base(value)
            if text is None and choices.get(name):
                text = choices[name][0]
            out[name] = text if text is not None else placeholder("arg", name)
        return out

    def concrete_param(self, param: ScopedParam) -> object:
        """Return a SetParameter/SetParametersFromFile entry as launch_ros stores it."""
        if param.file is not None:
            return self.graph.base(param.file) or placeholder("opaque", "parameter file")
        name = self.graph.base(param.name) if param.name is not None else None
        value = param.value
        if isinstance(value, s.Sub):
            text = self.graph.base(value)
            value = (typed_parameter(text, param.value_type) if text is not None
                     else placeholder("opaque", "value"))
        return (name or placeholder("opaque", "name"), value)

    def do_OpaqueAction(self, action: a.OpaqueAction, ctx: Ctx) -> None:
        """Something the frontend could not see into (it already said so)."""
        self.mark_incomplete(ctx.origin(action.span))
        self.graph.opaque_files.add(ctx.file)

    # ------------------------------------------------------------------ processes and nodes

    def do_ExecuteProcess(self, action: a.ExecuteProcess, ctx: Ctx) -> None:
        reducer = self.reducer.at(ctx, action.span)
        cmd = tuple(reducer.reduce(part) for part in action.cmd)
        origin = ctx.origin(action.span)
        settings = self.visit_process_options(action.process, action.span, ctx, action)
        self.graph.launches.append(LaunchRecord(origin, self.execution, settings, cmd=cmd))

    def visit_process_options(self, options: a.ProcessOptions, span: Span, ctx: Ctx,
                              process: a.Action | None = None) -> ProcessSettings:
        """Evaluate what every process takes (reads of configurations count as uses)."""
        reducer = self.reducer.at(ctx, span)

        def reduce(value: s.Sub | None) -> s.Sub | None:
            return None if value is None else reducer.reduce(value)

        env: list[tuple[str, s.Sub | None]] = list(self.scopes.env.items())
        for name, value in options.additional_env:
            key = text_of(reducer.reduce(name))
            reduced = reducer.reduce(value)
            if key is not None:
                env.append((key, reduced))
                self.graph.environment_sets.append(EnvRecord(key, reduced, ctx.origin(span)))

        def timeout(value: s.Sub | float | None) -> s.Sub | float | None:
            return reducer.reduce(value) if isinstance(value, s.Sub) else value

        settings = ProcessSettings(
            name=reduce(options.name), cwd=reduce(options.cwd), prefix=reduce(options.prefix),
            output=reduce(options.output), env=tuple(env),
            replace_env=None if options.env is None else tuple(
                (reducer.reduce(k), reducer.reduce(v)) for k, v in options.env),
            shell=options.shell, emulate_tty=options.emulate_tty,
            respawn=(reducer.reduce(options.respawn) if isinstance(options.respawn, s.Sub)
                     else options.respawn),
            respawn_delay=options.respawn_delay,
            respawn_max_retries=options.respawn_max_retries,
            sigterm_timeout=timeout(options.sigterm_timeout),
            sigkill_timeout=timeout(options.sigkill_timeout),
        )
        if options.on_exit:  # an OnProcessExit handler on this very process
            index = self.record_handler(ctx.origin(span), "process_exit", process, False)
            self.run_handler(index, options.on_exit, ctx)
        return settings

    def do_Node(self, action: a.Node, ctx: Ctx) -> None:
        self.nodes.run_node(action, ctx)

    def do_LifecycleNode(self, action: a.LifecycleNode, ctx: Ctx) -> None:
        self.nodes.run_node(action, ctx)

    def do_ComposableNodeContainer(self, action: a.ComposableNodeContainer, ctx: Ctx) -> None:
        container = self.nodes.run_node(action, ctx)
        self.container_names[id(action)] = (action, container.fqn)
        for description in action.composable_nodes:
            self.nodes.run_composable(description, container.fqn, ctx)

    def do_LoadComposableNodes(self, action: a.LoadComposableNodes, ctx: Ctx) -> None:
        """Load into the container as launch_ros names it (``LoadComposableNodes.execute``).

        A container action given as the target stands for its ``node_name``: its full name,
        pushed namespace included, once it has run (before, launch_ros raises: unknown).
        """
        target: s.Sub | None = None
        if isinstance(action.target, s.Sub):
            target = self.reducer.at(ctx, action.span).reduce(action.target)
        else:
            ran = self.container_names.get(id(action.target))
            target = ran[1] if ran is not None and ran[0] is action.target else None
        for description in action.composable_nodes:
            self.nodes.run_composable(description, target, ctx)
        self.graph.loads.append(LoadRecord(ctx.origin(action.span), target,
                                           len(action.composable_nodes)))

    def record_name(self, kind: str, value: s.Sub, origin: Origin) -> None:
        """Record a ROS name for validation when its value is concrete."""
        text = text_of(value)
        if text is not None:
            self.graph.names.append(NameRecord(kind, text, origin))


def set_elsewhere(value: s.Sub) -> s.Sub:
    """Return a value with what nothing set here as unknown: set where launchverify does not see.

    (By an includer of the file, or by code launchverify cannot see.) Never a text an
    included file's code or defaults would put in its place.
    """
    read = unset_read(value) or next(
        (part for part in s.walk(value) if isinstance(part, Unset)), None)
    unknown = Unknown(f"configuration {read.name if read else '?'}, set where launchverify "
                      "does not see")
    value = fill_unset(value, unknown)
    return unknown if is_unset(value) else value


def _guard_env(ctx: Ctx, value: s.Sub, old: s.Sub | None, name: str) -> s.Sub:
    previous = old if old is not None or not ctx.path else Unknown(f"environment {name}")
    return guarded(ctx.path, value, previous, name)


def _opaque(description: str, where: Span) -> Guard:
    from launchverify.ir.symbolic import Opaque

    return Opaque(description, where=where)


def depends_on_argument(value: s.Sub, name: str) -> bool:
    """Return whether a configuration's value is (or includes) the argument ``name``."""
    return name in argument_names(value)


def read_names(condition: c.Condition) -> list[str]:
    """Return the configurations a condition reads by a literal name."""
    if isinstance(condition, c.ConfigEquals):
        expression: s.Sub = s.LaunchConfig(condition.name)
    elif isinstance(condition, (c.IfCondition, c.UnlessCondition)):
        expression = condition.expression
    else:
        return []
    return [part.name.text for part in s.walk(expression)
            if isinstance(part, s.LaunchConfig) and isinstance(part.name, s.Text)]
