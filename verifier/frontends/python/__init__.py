"""The Python frontend: run a launch file's ``generate_launch_description()`` against models.

The file runs in the sandbox (no side effects, time and memory limits) with the launch API
served by ``launchverify.models.launch_api``; the objects it builds record the user's
lines and become the same IR as the XML and YAML frontends produce. What goes wrong is
recorded as a problem at the user's line, never raised.
"""

from __future__ import annotations

import builtins
import dataclasses
import errno
import inspect
import io
import re
import sys
import traceback
from collections.abc import Iterable, Iterator, Mapping
from contextlib import contextmanager
from pathlib import Path
from types import CodeType
from typing import Any

from launchverify.frontends.python.assumptions import checked
from launchverify.frontends.python.concrete import SubstitutionFailure
from launchverify.frontends.python.convert import BLAMED, Converted, PythonConverter
from launchverify.frontends.python.importer import absent_import, import_context
from launchverify.frontends.python.machine import robot_machine
from launchverify.frontends.python.mentions import mentioned_strings
from launchverify.frontends.python.rewrite import compile_launch_file
from launchverify.frontends.python.sandbox import (
    SCRATCH_NAME,
    SandboxViolation,
    TimeLimitExceeded,
    in_other_scratch,
    in_scratch,
    removing,
    sandbox,
    take_refusals,
)
from launchverify.ir import actions as a
from launchverify.models.launch_api import runtime
from launchverify.models.launch_api.base import in_characters
from launchverify.models.launch_api.context import LaunchContext, MissingConfiguration
from launchverify.models.launch_api.launch_actions import LaunchDescription
from launchverify.models.launch_api.placeholders import (
    UnknownMapping,
    has_placeholder,
    placeholder,
    read,
)
from launchverify.models.launch_api.runtime import blamable
from launchverify.models.launch_api.unknown import Opaque, handed, launch_builtins
from launchverify.own_code import for_launchverify, is_own_file
from launchverify.problems import Problem, ProblemSink
from launchverify.span import Span
from launchverify.workspace.packages import PackageIndex
from launchverify.workspace.paths import resolved
from launchverify.workspace.reading import read_file

ENTRY_POINTS = ("generate_launch_description", "generate_test_description")
_REAL_OPEN = builtins.open  # (robot_machine gives code other than ours another while it runs)


class UnknownInput(Exception):
    """The launch file needs something only the robot has (a file outside the workspace)."""


class PythonFrontend:
    """Loads Python launch files for one run (one package index, one workspace)."""

    def __init__(self, index: PackageIndex, workspace: Path,
                 arguments: Mapping[str, str] | None = None, *,
                 absent_modules: bool = False) -> None:
        self.index = index
        self.workspace = workspace
        self.arguments = dict(arguments or {})  # name:=value given on the command line
        self.absent_modules = absent_modules  # ablation: only launch and Python's own exist

    def argv(self, path: Path) -> list[str]:
        """Return ``sys.argv`` as ``ros2 launch`` leaves it for a launch file.

        ``ros2 launch PACKAGE FILE name:=value``, or ``ros2 launch PATH name:=value`` for a
        file outside any package; launchverify's own command line is never shown.
        """
        owner = self.index.owner(path)
        where = [owner.name, path.name] if owner is not None else [str(path)]
        return ["ros2", "launch", *where, *(f"{k}:={v}" for k, v in self.arguments.items())]

    def prefetch(self, paths: Iterable[Path]) -> None:
        """Nothing to start ahead: a file is run in this process when it is loaded."""

    def load(self, path: Path, sink: ProblemSink) -> a.LaunchFile | None:
        """Run a Python launch file and return its IR, recording problems in ``sink``."""
        try:
            data = read_file(path)
        except OSError as error:
            sink.cannot_read(error, Span.of_file(path))
            return None
        try:
            code = compile_launch_file(data, str(path))
        except SyntaxError as error:
            sink.parse(f"invalid Python: {error.msg}",
                       Span(path, error.lineno or 1, (error.offset or 1)))
            return None
        except (ValueError, MemoryError, RecursionError) as error:
            sink.parse(f"invalid Python: {error}", Span.of_file(path))
            return None
        def evaluate() -> tuple[a.LaunchFile | None, list[Problem]]:
            into = ProblemSink()
            session = _Session(self, path, into)
            description = session.run_module(code)
            if description is None:
                return None, into.problems
            with session.environment():  # models may call back into the file's code
                return session.convert(description), into.problems

        done = checked(evaluate, lambda launch: None if launch is None else launch.actions)
        sink.problems.extend(done.problems)
        launch = done.result
        if launch is not None and done.depends:
            launch = dataclasses.replace(launch, actions=(*launch.actions, _assumed(launch.span)))
        return launch


class _Session:
    """One launch file's run: its module, its problems, its OpaqueFunctions."""

    def __init__(self, frontend: PythonFrontend, path: Path, sink: ProblemSink) -> None:
        self.frontend = frontend
        self.path = path
        self.sink = sink
        self.reported: set[str] = set()
        self.in_opaque = False
        self.namespace: dict[str, Any] = {}
        self.lookups: list[tuple[str, Span]] = []
        self.handed_names: set[str] = set()  # configurations handed to unknown code
        self.failed_read: tuple[str, Span] | None = None  # OpaqueFunction read of nothing
        self.fallback: Span | None = None  # the running OpaqueFunction's line
        # one object, one record, whichever conversion meets it: an OpaqueFunction's
        # handler may target a node made before it ran (``RegisterEventHandler(
        # OnProcessExit(target_action=jsb))``, jsb in the description)
        self.converted = Converted()

    # ------------------------------------------------------------------ reporting

    def unmodeled(self, what: str, span: Span) -> None:
        """Record LV003 once per message."""
        if what not in self.reported:
            self.reported.add(what)
            self.sink.unmodeled(what, span)

    def module_unmodeled(self, name: str) -> None:
        """Record an import nothing provides."""
        self.unmodeled(f"module {name!r} is not modelled and not installed; values from it "
                       "are unknown", self._user_span())

    def name_unmodeled(self, name: str) -> None:
        """Record a name of the launch API that has no model."""
        self.unmodeled(f"{name} is not modelled; values from it are unknown",
                       self._user_span())

    def _user_span(self) -> Span:
        import sys

        frame = sys._getframe(1)
        while frame is not None and (not blamable(frame.f_code.co_filename, self.path)
                                     or "importlib" in frame.f_code.co_filename):
            frame = frame.f_back  # type: ignore[assignment]
        if frame is None:
            return self.fallback or Span.of_file(self.path)
        return Span(Path(frame.f_code.co_filename), frame.f_lineno or 1)

    def failure(self, error: BaseException) -> None:
        """Record an exception raised while running the launch file."""
        span = self._error_span(error)
        if isinstance(error, UnknownInput):
            self.sink.unmodeled(str(error), span)
        elif isinstance(error, SandboxViolation):
            pass  # reported with every other refusal when the run ends
        elif isinstance(error, PermissionError) and error.errno == errno.EPERM:
            # the operating system's confinement refused what the audit hook did not see
            self.unmodeled(f"launch files are evaluated without side effects: the sandbox "
                           f"refused an operation ({_shown(str(error))}); the evaluation of "
                           "this file may be incomplete", span)
        elif isinstance(error, FileNotFoundError) and removing(error.filename):
            pass  # removing a file that a process of the launch writes: nothing is missed
        elif isinstance(error, FileNotFoundError) and in_scratch(error.filename):
            # A temporary file that a process of the launch writes at run time (xacro, a
            # generated world): launchverify starts no process, so it never exists here.
            self.unmodeled("the launch file's code needs a temporary file that only exists "
                           f"at run time ({type(error).__name__} on a file in its temporary "
                           "folder); what follows is not evaluated", span)
        elif isinstance(error, TimeLimitExceeded):
            self.sink.evaluation(f"{error} (an endless loop?)", span)
        elif isinstance(error, MemoryError):
            self.sink.evaluation("evaluation ran out of memory", span)
        elif (library := _failing_library(error)) is not None:
            # Installed libraries here are launchverify's, not the robot's: their versions
            # differ (pydantic 1 on humble, 2 here), so their failures are no verdict.
            self.unmodeled(f"the library {library} fails here ({type(error).__name__}: "
                           f"{_shown(str(error))[:160]}); the robot's copy may differ, what "
                           "follows is not evaluated", span)
        elif has_placeholder(str(error)):
            # It failed on a value only the robot or an includer knows: not evaluated.
            self.unmodeled(f"the launch file's code fails on a value unknown here "
                           f"({type(error).__name__}: {_shown(str(error))}); what follows "
                           "is not evaluated", span)
        else:
            text = str(error)
            message = f"{type(error).__name__}: {text}" if text else type(error).__name__
            # A configuration nobody set: an includer may set it (LV201's policy decides).
            # An OpaqueFunction runs with what the includers set: without them (a file
            # checked on its own) its failures may come from what only they provide.
            contextual = self.in_opaque or isinstance(
                error, (SubstitutionFailure, MissingConfiguration))
            if contextual and getattr(error, "configuration", None) and self.in_opaque:
                self.failed_read = (str(getattr(error, "configuration", "")), span)
                return
            self.sink.evaluation(f"the launch file raises {message}", span,
                                 contextual=contextual)

    def _error_span(self, error: BaseException) -> Span:
        frames = traceback.extract_tb(error.__traceback__)
        user = [f for f in frames if blamable(f.filename, self.path)
                and not f.filename.startswith(_STDLIB)]
        if not user:
            blamed = getattr(error, BLAMED, None)  # an action launch rejects, built here
            return blamed if isinstance(blamed, Span) else (
                self.fallback or Span.of_file(self.path))
        frame = user[-1]
        column = (frame.colno or 0) + 1 if getattr(frame, "colno", None) is not None else 1
        return in_characters(Span(Path(frame.filename), frame.lineno or 1, column))

    # ------------------------------------------------------------------ running

    @contextmanager
    def environment(self) -> Iterator[None]:
        """Run a block as this file's code runs: models, workspace imports, sandbox."""
        frontend = self.frontend
        runtime.current = runtime.Runtime(frontend.index, frontend.workspace, self.unmodeled,
                                          self.path, context_tools=self._context_tools,
                                          lookups=self.lookups, fallback=self.fallback,
                                          handed_names=self.handed_names)
        take_refusals()
        saved_argv, sys.argv = sys.argv, frontend.argv(self.path)
        try:
            with import_context([self.path.parent], frontend.index, self.module_unmodeled,
                                self.name_unmodeled), sandbox(), _libraries_know_unknowns(), \
                    robot_machine(self._seen, self._open):
                yield
        finally:
            sys.argv = saved_argv
            runtime.current = None
            for message, where in take_refusals():
                span = Span(Path(where[0]), where[1]) if where else Span.of_file(self.path)
                self.unmodeled(f"{message}; launchverify did not do it (the evaluation of "
                               "this file may be incomplete)", span)

    def _seen(self, path: str) -> bool:
        """Return whether an absolute path is where launchverify sees the files."""
        where = Path(path)
        return (resolved(where).is_relative_to(self.frontend.workspace)
                or self.frontend.index.owner(where) is not None)

    def run_module(self, code: CodeType) -> Any:
        """Execute the module and call its entry point; ``None`` after a problem."""
        self.namespace = {
            "__name__": "__launchverify_launch_file__",
            "__file__": str(self.path),
        }
        try:
            with self.environment():
                # taken here: the machine's stand-ins (``input``) are in place
                self.namespace["__builtins__"] = self._builtins()
                exec(code, self.namespace)
                entry = next((self.namespace[n] for n in ENTRY_POINTS if n in self.namespace),
                             None)
                if entry is None:
                    self.sink.parse(
                        "launch file does not contain the required function "
                        "'generate_launch_description()'", Span.of_file(self.path))
                    return None
                required = _required_parameters(entry)
                if required:
                    # A test script's helper, called by its own main(): not a launch file.
                    body = getattr(entry, "__code__", None)
                    self.sink.unmodeled(
                        f"{entry.__name__}() takes parameters ({', '.join(required)}): not "
                        "a launch file ros2 launch can start; not checked",
                        Span(self.path, body.co_firstlineno if body is not None else 1))
                    return None
                result = entry()
        except BaseException as error:  # the user's code: anything may come out
            self.failure(error)
            return None
        self._finalizers()
        if isinstance(result, tuple) and result:
            result = result[0]  # generate_test_description returns (description, context)
        if isinstance(result, Opaque):  # a vendor's helper built it: what it holds is unknown
            return LaunchDescription([result])
        if not isinstance(result, LaunchDescription):
            self.sink.evaluation(
                "generate_launch_description() must return a LaunchDescription, got "
                f"{type(result).__name__}", Span.of_file(self.path))
            return None
        return result

    def _finalizers(self) -> None:
        """Note classes of the launch file whose ``__del__`` launchverify never runs."""
        for value in list(self.namespace.values()):
            finalizer = vars(value).get("__del__") if isinstance(value, type) else None
            code = getattr(finalizer, "__code__", None)
            if code is not None and value.__module__ == self.namespace["__name__"]:
                self.unmodeled(f"{value.__name__}.__del__ is a finalizer: ros2 launch runs "
                               "it when the object is collected, launchverify never does",
                               Span(self.path, code.co_firstlineno))

    def convert(self, description: LaunchDescription) -> a.LaunchFile | None:
        """Turn the description into IR."""
        converter = self.converter()
        try:
            actions = converter.actions(description.entities)
        except Exception as error:  # a model rejecting a value the user passed
            self.failure(error)
            return None
        if handed(description):  # code launchverify cannot see may have added to it
            actions = (*actions, a.OpaqueAction(span=description._span,
                                                description="what code launchverify cannot "
                                                            "see adds to the description"))
        return a.LaunchFile(path=self.path, format="python", actions=actions,
                            span=Span.of_file(self.path),
                            deprecated=description.deprecated_reason,
                            lookups=tuple(self.lookups), handed=tuple(converter.handed),
                            mentions=tuple(sorted(self.handed_names)))

    def converter(self, context: Any = None) -> PythonConverter:
        """Return a converter reporting into this session (``context``: an OpaqueFunction's)."""
        return PythonConverter(self.unmodeled, self.opaque_function, Span.of_file(self.path),
                               fail=lambda message, span: self.sink.evaluation(  # noqa: PLW0108
                                   message, span), context=context, converted=self.converted)

    def _builtins(self) -> dict[str, Any]:
        namespace = launch_builtins()
        namespace["open"] = self._open
        if self.frontend.absent_modules:
            namespace["__import__"] = absent_import(self.module_unmodeled)
        return namespace

    def _open(self, file: Any, mode: str = "r", *args: Any, **kwargs: Any) -> Any:
        """``open`` for launch files: files only the robot has are unknown inputs."""
        name = str(file)
        path = Path(name)
        reading = not any(c in mode for c in "wax+")
        if reading and path.is_absolute() and not path.exists() and not has_placeholder(name):
            located = self.frontend.index.locate(path)  # install layout -> sources
            if located is not None:
                file = located
        unknown = has_placeholder(name) or isinstance(file, Opaque) or (
            path.is_absolute() and not Path(file).exists()
            and not resolved(path).is_relative_to(self.frontend.workspace))
        if reading and (unknown or in_other_scratch(name)):
            # A file of the robot (a package not in the workspace), or one another launch
            # file's code writes at run time: an input, not an error.
            return _unknown_content(path, mode)
        try:
            return _REAL_OPEN(file, mode, *args, **kwargs)
        except PermissionError as error:
            if not reading or error.errno != errno.EACCES:
                raise
            # Outside what a launch file may read (the workspace, packages, Python): a
            # file of this machine, not of the launch tree; its content is not read.
            self.unmodeled(f"{_shown(name)} is outside the workspace and its packages: "
                           "launchverify does not read it, its content is unknown",
                           self._user_span())
            return _unknown_content(path, mode)

    # ------------------------------------------------------------------ OpaqueFunction

    def opaque_function(self, model: Any) -> a.Action:
        """Return the IR of an OpaqueFunction whose body runs when the walk reaches it."""
        def run(configurations: Mapping[str, str], current: Path) -> a.OpaqueResult:
            return self.run_opaque(model, configurations, current)

        return a.OpaqueFunction(span=model._span, condition=self.converter().condition(
            model.condition), description=model.label, run=run)

    def _context_tools(self, configurations: dict[str, str]) -> tuple[Any, Any]:
        performer = _Performer(self.frontend, configurations, self.path)
        return performer.perform, performer.evaluate

    def run_opaque(self, model: Any, configurations: Mapping[str, str],
                   current: Path) -> a.OpaqueResult:
        """Run an OpaqueFunction's body with a concrete context."""
        def run() -> tuple[a.OpaqueResult, list[Problem]]:
            result = self._run_opaque(model, configurations, current)
            return result, _problems(result)

        done = checked(run, lambda result: result.actions)
        result = dataclasses.replace(done.result, problems=tuple(done.problems))
        if done.depends:
            result = dataclasses.replace(result, actions=(*result.actions,
                                                          _assumed(model._span)))
        return result

    def _run_opaque(self, model: Any, configurations: Mapping[str, str],
                    current: Path) -> a.OpaqueResult:
        sink = ProblemSink()
        saved, saved_lookups, saved_reported = self.sink, self.lookups, self.reported
        # each run says what it met, whatever earlier runs (other roots) said: its result
        # is then the same for the same inputs
        self.sink, self.lookups, self.reported = sink, [], set()
        self.in_opaque, self.failed_read = True, None
        self.fallback = model._span
        performer = _Performer(self.frontend, configurations, current)
        context = LaunchContext(configurations=dict(configurations), performer=performer.perform,
                                condition_evaluator=performer.evaluate,
                                launch_file=str(current))
        actions: tuple[a.Action, ...] = ()
        try:
            with self.environment():  # conversion may call the user's code (__fspath__)
                entities = model.call(context)
                actions = self.converter(context).actions(entities or [])
        except BaseException as error:  # the user's code
            self.failure(error)
        finally:
            lookups = tuple(self.lookups)
            self.sink, self.lookups, self.reported = saved, saved_lookups, saved_reported
            self.in_opaque, self.fallback = False, None
        reads: tuple[tuple[str, bool, bool] | tuple[str, bool, bool, Span], ...] = (
            *performer.reducer.reads, *context.launch_configurations.read)
        if self.failed_read is not None:
            name, span = self.failed_read
            reads = (*reads, (name, False, False, span))
        return a.OpaqueResult(actions=actions, problems=tuple(sink.problems), reads=reads,
                              lookups=lookups,
                              mentions=tuple(sorted(mentioned_strings(model.function))),
                              reads_all=context.launch_configurations.whole)


def _assumed(span: Span) -> a.Action:
    """Return what a description holds once its code branched on an unknown value.

    A loop over a vendor's list, an ``if`` on its flag: another answer may have built more
    or less, so no rule may claim what the description lacks.
    """
    return a.OpaqueAction(span=span, description="what the code builds with other answers "
                                                 "about values launchverify cannot know",
                          anywhere=True)


def _problems(result: a.OpaqueResult) -> list[Problem]:
    return [p for p in result.problems if isinstance(p, Problem)]


class _Performer:
    """Performs substitutions for an OpaqueFunction's context."""

    def __init__(self, frontend: PythonFrontend, configurations: Mapping[str, str],
                 current: Path) -> None:
        from launchverify.frontends.python.concrete import ConcreteReducer

        self.reducer = ConcreteReducer(frontend.index, configurations, current)
        self.converter = PythonConverter(lambda what, span: None, _no_opaque,
                                         Span.of_file(current))

    def perform(self, substitution: Any) -> str:
        return self.reducer.perform(self.converter.sub(substitution))

    def evaluate(self, condition: Any) -> bool:
        ir = self.converter.condition(condition)
        return self.reducer.holds(ir)


class OpaqueText(io.StringIO):
    """The content of a file only the robot has."""


@contextmanager
def _libraries_know_unknowns() -> Iterator[None]:
    """Make ``yaml.safe_load(open(robot_file))`` an unknown mapping rather than a string.

    ``json.loads`` of a text that holds an unknown (a vendor's value, an environment
    variable) and does not parse is an unknown value too; dumping an unknown to YAML
    writes its text (a string's), as a safe dumper writes a string.
    """
    import json

    import yaml

    originals = {name: getattr(yaml, name) for name in ("safe_load", "load", "full_load")}
    json_loads = json.loads

    def loads(text: Any, *args: Any, **kwargs: Any) -> Any:
        try:
            return json_loads(text, *args, **kwargs)
        except ValueError:  # a text that holds an unknown is no JSON here, on the robot any
            if isinstance(text, str) and has_placeholder(text):
                return Opaque(f"the JSON in {read(text)}")
            raise

    json.loads = loads  # type: ignore[assignment]
    searches = {name: getattr(re, name) for name in _RE_SEARCHES}
    for name, search in searches.items():
        setattr(re, name, _searching_unknowns(name, search))
    for dumper in (yaml.SafeDumper, yaml.Dumper):
        if Opaque not in dumper.yaml_representers:
            dumper.add_representer(Opaque, _represent_unknown)

    def wrap(original: Any) -> Any:
        def load(stream: Any, *args: Any, **kwargs: Any) -> Any:
            if isinstance(stream, OpaqueText) or (
                    isinstance(stream, str) and has_placeholder(stream) and "\n" not in stream):
                return UnknownMapping()
            return original(stream, *args, **kwargs)

        return load

    for name, original in originals.items():
        setattr(yaml, name, wrap(original))
    try:
        yield
    finally:
        for name, original in originals.items():
            setattr(yaml, name, original)
        json.loads = json_loads
        for name, search in searches.items():
            setattr(re, name, search)


# ``re``'s functions and where each takes the text it searches
_RE_SEARCHES = {"findall": 1, "finditer": 1, "search": 1, "match": 1, "fullmatch": 1,
                "split": 1, "sub": 2, "subn": 2}


def _searching_unknowns(name: str, search: Any) -> Any:
    r"""Wrap a ``re`` function: what it finds in a text that holds an unknown is unknown.

    (``re.findall(r'R(\d+)', version_file.read())[0]`` finds nothing in a placeholder;
    on the robot the file holds a version.)
    """
    at = _RE_SEARCHES[name]

    def searching(*args: Any, **kwargs: Any) -> Any:
        text = args[at] if len(args) > at else kwargs.get("string")
        if isinstance(text, str) and has_placeholder(text) and not for_launchverify(1):
            return Opaque(f"what re.{name} finds in {read(text)}")
        return search(*args, **kwargs)

    searching.__name__ = name
    return searching


def _represent_unknown(dumper: Any, value: Opaque) -> Any:
    """Write an unknown value to YAML as its placeholder's text (a plain string)."""
    return dumper.represent_str(str.__str__(value))


def _unknown_content(path: Path, mode: str) -> Any:
    content = placeholder("opaque", f"content of {path.name}")
    return OpaqueText(content) if "b" not in mode else io.BytesIO(content.encode())


def _no_opaque(model: Any) -> a.Action:
    raise TypeError("an OpaqueFunction cannot be performed as a substitution")


def _shown(text: str) -> str:
    """Show placeholders the way users write the values they stand for."""
    from launchverify.models.launch_api.placeholders import PATTERN, parsed, read

    spelled = {"env": "$(env {})", "arg": "$(var {})", "pkg": "$(find-pkg-share {})",
               "prefix": "$(find-pkg-prefix {})", "opaque": "<{}>"}

    def shown(match: re.Match[str]) -> str:
        found = parsed(match)
        return match.group(0) if found is None else spelled[found[0]].format(found[1])

    text = read(PATTERN.sub(shown, text))
    return _SCRATCH_PATH.sub("<a temporary file>", text)[:200]


# A path in an evaluation's scratch folder: random, so never part of a message.
_SCRATCH_PATH = re.compile(r"[^\s'\"]*/" + SCRATCH_NAME.pattern + r"(?:/[^\s'\"]*)?")


def _required_parameters(function: Any) -> list[str]:
    """Return the names of the parameters a call without arguments would lack."""
    try:
        signature = inspect.signature(function)
    except (TypeError, ValueError):
        return []
    return [name for name, parameter in signature.parameters.items()
            if parameter.default is inspect.Parameter.empty
            and parameter.kind not in (inspect.Parameter.VAR_POSITIONAL,
                                       inspect.Parameter.VAR_KEYWORD)]


_INSTALLED = ("site-packages", "dist-packages")


def _failing_library(error: BaseException) -> str | None:
    """Return the installed library an exception was raised in (``None``: anywhere else)."""
    frames = traceback.extract_tb(error.__traceback__)
    if not frames:
        return None
    parts = Path(frames[-1].filename).parts
    for index, part in enumerate(parts[:-1]):
        if part in _INSTALLED and not is_own_file(frames[-1].filename):
            return parts[index + 1].removesuffix(".py")
    return None


def _is_file(name: str) -> bool:
    return not name.startswith("<")


_STDLIB = str(Path(traceback.__file__).parent)


def load_python(path: Path, sink: ProblemSink, index: PackageIndex | None,
                workspace: Path | None) -> a.LaunchFile | None:
    """Load a Python launch file (used by ``frontends.load_launch_file``)."""
    frontend = PythonFrontend(index or PackageIndex(), workspace or path.parent)
    return frontend.load(path, sink)

