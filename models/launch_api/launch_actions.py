"""Models of ``launch``'s actions, descriptions, description sources and event handlers.

Each model accepts the arguments of the real class (humble to rolling) and raises
``TypeError`` for arguments the real class does not take, as launch would; ``to_ir``
produces the IR the XML and YAML frontends produce for the same action.
"""

from __future__ import annotations

import inspect
import os
from collections.abc import Callable, Iterable, Iterator
from typing import Any

from launchverify.ir import actions as a
from launchverify.ir import subst as s
from launchverify.models.launch_api.base import (
    Action,
    Converter,
    LaunchDescriptionEntity,
    Modelled,
    _unknown,
    check_substitutions,
    flatten,
    launch_getter,
    normalized,
    typed,
)
from launchverify.models.launch_api.placeholders import has_placeholder, read
from launchverify.models.launch_api.unknown import Opaque
from launchverify.span import Span


def entities_of(value: Iterable[Any] | None) -> list[Any]:
    """Return the entities a launch file gives as a collection.

    An unknown collection (a vendor's ``make_actions()``) holds unknown actions: it is one
    unknown entity, not an empty list.
    """
    if value is None:
        return []
    return [value] if isinstance(value, Opaque) else list(value)


class LaunchDescription(LaunchDescriptionEntity):
    """``LaunchDescription(initial_entities=None, *, deprecated_reason=None)``."""

    def __init__(self, initial_entities: Iterable[Any] | None = None, *,
                 deprecated_reason: str | None = None) -> None:
        super().__init__()
        self._entities: list[Any] = entities_of(initial_entities)
        self._deprecated_reason = deprecated_reason

    @property
    def entities(self) -> list[Any]:
        """Return the entities: the list itself, as launch does (appending to it adds)."""
        return self._entities

    @property
    def deprecated(self) -> bool:
        """Return whether the description is deprecated (launch's API)."""
        return self._deprecated_reason is not None

    @property
    def deprecated_reason(self) -> str | None:
        """Return why the description is deprecated, or ``None`` (launch's API)."""
        return self._deprecated_reason

    def add_action(self, action: Any) -> None:
        """Append an action."""
        self._entities.append(action)

    def add_entity(self, entity: Any) -> None:
        """Append an entity."""
        self._entities.append(entity)

    def get_sub_entities(self) -> list[Any]:
        return list(self._entities)

    def describe_sub_entities(self) -> list[Any]:
        return self._entities

    def visit(self, context: Any) -> list[Any]:
        """Return the entities to visit (launch's API)."""
        return self._entities

    def get_launch_arguments(self, conditional_inclusion: bool = False) -> list[Any]:
        """Return the argument declarations of this description, nested ones included."""
        return [item[0] for item in
                self.get_launch_arguments_with_include_launch_description_actions(
                    conditional_inclusion)]

    def get_launch_arguments_with_include_launch_description_actions(
            self, conditional_inclusion: bool = False) -> list[tuple[Any, Any]]:
        """Return ``(declaration, includes it is nested in)`` pairs, as launch walks them.

        Descriptions of files an include would load are not loaded: their declarations are
        not listed.
        """
        declared: list[tuple[Any, Any]] = []

        def walk(entities: Any, conditional: bool, includes: list[Any] | None) -> None:
            for entity in flatten(entities):
                if isinstance(entity, DeclareLaunchArgument):
                    if entity.name in (known.name for known, _ in declared):
                        continue
                    entity._conditionally_included = conditional or entity.condition is not None
                    declared.append((entity, includes))
                if isinstance(entity, ResetLaunchConfigurations):
                    return
                nested = includes
                if isinstance(entity, IncludeLaunchDescription):
                    nested = [*(includes or []), entity]
                if isinstance(entity, LaunchDescriptionEntity):
                    walk(entity.describe_sub_entities(), False, nested)
                    for _, sub_entities in entity.describe_conditional_sub_entities():
                        walk(sub_entities, True, nested)

        walk(self._entities, conditional_inclusion, None)
        return declared

    def to_ir(self, cv: Converter) -> a.Action:
        # A description inside another visits its entities in place, without a scope.
        return a.Group(span=self._span, actions=cv.actions(self._entities), scoped=False)


class NoGraphEffect(Action):
    """Actions that change nothing the graph models (logging set-up, unregistering...)."""

    def __init__(self, *args: Any, condition: Any = None, **kwargs: Any) -> None:
        super().__init__(condition=condition)

    def to_ir(self, cv: Converter) -> a.Action | None:
        return None


# ----------------------------------------------------------------------------- arguments


class DeclareLaunchArgument(Action):
    """``DeclareLaunchArgument(name, *, default_value=None, description=None, choices=None)``."""

    def __init__(self, name: str, *, default_value: Any = None, description: str | None = None,
                 choices: Iterable[str] | None = None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        if not isinstance(name, str):
            raise TypeError(f"DeclareLaunchArgument name must be a str, got {type(name)}")
        if _unknown(choices):
            choices = None  # a vendor's list: which values it allows is unknown, no claim
        elif choices is not None and not list(choices):
            raise RuntimeError(
                "Provided choices arg is empty. Use None to ignore the choice list.")
        self._name = name
        self._default_value = None if default_value is None else check_substitutions(
            default_value)
        self._description = description
        self._choices = None if choices is None else list(choices)
        self._conditionally_included = False

    @property
    def name(self) -> str:
        """Return the argument's name (launch's API)."""
        return self._name

    default_value = launch_getter(
        "_default_value", "Return the default as substitutions, or ``None`` (launch's API).")

    @property
    def description(self) -> str:
        """Return the description as launch completes it (choices, 'no description given')."""
        choices = self._choices
        if self._description is None:
            return "no description given" if choices is None else f"One of: {choices}"
        if choices is None:
            return self._description
        text = self._description if self._description.endswith(".") else (
            self._description + ".")
        return f"{text} Valid choices are: {choices}"

    @property
    def choices(self) -> list[Any] | None:
        """Return the allowed values, or ``None`` (launch's API)."""
        return self._choices

    def to_ir(self, cv: Converter) -> a.Action:
        if has_placeholder(self._name):  # named by code launchverify cannot see: any name
            cv.unmodeled(f"an argument named by code launchverify cannot see "
                         f"({read(self._name)}) is declared here", self._span)
            return a.OpaqueAction(span=self._span, description="an argument of unknown name")
        choices = None if self._choices is None else tuple(str(c) for c in self._choices)
        if choices is not None and any(has_placeholder(c) for c in choices):
            choices = None  # one of them is a vendor's value: which values it allows is unknown
        return a.DeclareArgument(**cv_common(self, cv), name=self._name,
                                 default=cv.opt_sub(self._default_value),
                                 description=self._description, choices=choices)


class SetLaunchConfiguration(Action):
    """``SetLaunchConfiguration(name, value)``."""

    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._name, self._value = check_substitutions(name), check_substitutions(value)

    name = launch_getter("_name",
                         "Return the configuration's name as substitutions (launch's API).")

    value = launch_getter("_value", "Return the value as substitutions (launch's API).")

    def to_ir(self, cv: Converter) -> a.Action:
        return a.SetConfig(**cv_common(self, cv), name=cv.sub(self._name),
                           value=cv.sub(self._value))


class UnsetLaunchConfiguration(Action):
    """``UnsetLaunchConfiguration(name)``."""

    def __init__(self, name: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._name = name

    name = launch_getter("_name",
                         "Return the configuration's name as substitutions (launch's API).")

    def to_ir(self, cv: Converter) -> a.Action:
        return a.UnsetConfig(**cv_common(self, cv), name=cv.sub(self._name))


class ResetLaunchConfigurations(Action):
    """``ResetLaunchConfigurations(launch_configurations=None)``."""

    def __init__(self, launch_configurations: Any = None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.launch_configurations = launch_configurations

    def to_ir(self, cv: Converter) -> a.Action:
        keep = None if self.launch_configurations is None else cv.pairs(
            self.launch_configurations)
        return a.ResetConfigs(**cv_common(self, cv), keep=keep)


class PushLaunchConfigurations(Action):
    """``PushLaunchConfigurations()``."""

    def to_ir(self, cv: Converter) -> a.Action:
        return a.PushConfigs(**cv_common(self, cv))


class PopLaunchConfigurations(Action):
    """``PopLaunchConfigurations()``."""

    def to_ir(self, cv: Converter) -> a.Action:
        return a.PopConfigs(**cv_common(self, cv))


# ----------------------------------------------------------------------------- structure


class LaunchDescriptionSource(Modelled):
    """``LaunchDescriptionSource(launch_description=None, location=..., method=...)``."""

    kind = "any"

    def __init__(self, launch_description: Any = None, location: Any = "<string>",
                 method: str = "unspecified mechanism from a script") -> None:
        self.launch_description = launch_description
        self._location = location
        self._method = method

    @property
    def location(self) -> str:
        """Return the location as launch shows it before loading: its substitutions joined.

        Launch joins ``str()`` of each substitution (object representations) until
        ``get_launch_description`` expanded it; statically it never is.
        """
        return " + ".join(str(sub) for sub in normalized(self._location))

    @property
    def method(self) -> str:
        """Return how the description is loaded (launch's API)."""
        return self._method


class PythonLaunchDescriptionSource(LaunchDescriptionSource):
    """``PythonLaunchDescriptionSource(launch_file_path)``."""

    kind = "python"

    def __init__(self, launch_file_path: Any) -> None:
        super().__init__(location=launch_file_path, method="interpreted python launch file")


class AnyLaunchDescriptionSource(LaunchDescriptionSource):
    """``AnyLaunchDescriptionSource(launch_file_path)``."""

    def __init__(self, launch_file_path: Any) -> None:
        super().__init__(location=launch_file_path, method="interpreted launch file")


class FrontendLaunchDescriptionSource(LaunchDescriptionSource):
    """``FrontendLaunchDescriptionSource(launch_file_path, *, method=..., parser=...)``."""

    kind = "frontend"

    def __init__(self, launch_file_path: Any, *, method: str = "interpreted frontend launch file",
                 parser: Any = None) -> None:
        super().__init__(location=launch_file_path, method=method)


class XMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    """``launch_xml...XMLLaunchDescriptionSource(launch_file_path)``."""

    kind = "xml"

    def __init__(self, launch_file_path: Any) -> None:
        super().__init__(launch_file_path, method="interpreted XML launch file")


class YAMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    """``launch_yaml...YAMLLaunchDescriptionSource(launch_file_path)``."""

    kind = "yaml"

    def __init__(self, launch_file_path: Any) -> None:
        super().__init__(launch_file_path, method="interpreted YAML launch file")


class IncludeLaunchDescription(Action):
    """``IncludeLaunchDescription(launch_description_source, *, launch_arguments=None)``."""

    def __init__(self, launch_description_source: Any, *, launch_arguments: Any = None,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._source = launch_description_source
        self._given_arguments = () if launch_arguments is None else tuple(launch_arguments)
        if isinstance(launch_arguments, Opaque):  # arguments of any name: unknown ones
            self._given_arguments = ((Opaque(f"name in {launch_arguments}"),
                                      Opaque(f"value in {launch_arguments}")),)
        # launch unpacks and normalizes the pairs only in ``execute``, once the condition
        # held: what it rejects (a dict's keys, a number) fails there, not in the file
        self._arguments = [_argument_pair(pair) for pair in self._given_arguments]

    @property
    def launch_description_source(self) -> Any:
        """Return the description source (launch's API)."""
        return self._source

    @property
    def launch_arguments(self) -> tuple[Any, ...]:
        """Return the ``(name, value)`` pairs as given (launch's API)."""
        return self._given_arguments

    def get_sub_entities(self) -> list[Any]:
        """Return the description when the source holds one (files are not loaded here)."""
        source = self._source
        description = getattr(source, "launch_description", None) if isinstance(
            source, LaunchDescriptionSource) else None
        return [description] if description is not None else []

    def to_ir(self, cv: Converter) -> a.Action:
        keys = cv.keyword_keys(self._span, "launch_arguments")
        arguments = tuple(
            a.IncludeArg(name=s.Raises(error), value=s.EMPTY,
                         span=keys.get(name, self._span) if isinstance(name, str) else self._span)
            if error is not None else
            a.IncludeArg(name=cv.written_key(self._span, "launch_arguments", name),
                         value=cv.sub(value),
                         span=keys.get(name, self._span) if isinstance(name, str) else self._span)
            for name, value, error in self._arguments
        )
        source = self._source
        if isinstance(source, LaunchDescriptionSource) and source.launch_description is not None:
            sets = tuple(a.SetConfig(span=self._span, name=arg.name, value=arg.value)
                         for arg in arguments)
            inner = cv.actions([source.launch_description])
            return a.Group(**cv_common(self, cv), actions=(*sets, *inner), scoped=False)
        if isinstance(source, LaunchDescriptionSource) and not cv.claim(source):
            cv.fail("this include reuses another include's description source: its actions "
                    "are the same objects, and ros2 launch fails executing them a second time "
                    "('executed more than once')", self._span)
        location = source._location if isinstance(source, LaunchDescriptionSource) else source
        kind = source.kind if isinstance(source, LaunchDescriptionSource) else "any"
        return a.Include(**cv_common(self, cv), path=cv.sub(location), arguments=arguments,
                         source_kind=kind)


def _argument_pair(pair: Any) -> tuple[Any, Any, str | None]:
    """Return one launch argument as ``(name, value, None)``, or what launch raises on it."""
    try:
        name, value = pair
    except (TypeError, ValueError) as error:
        return None, None, f"{type(error).__name__}: {error} (a launch argument is no pair)"
    try:
        return check_substitutions(name), check_substitutions(value), None
    except TypeError as error:
        where = f"launch argument {name!r}" if isinstance(name, str) else "a launch argument"
        return name, None, f"TypeError: {error} ({where})"


class GroupAction(Action):
    """``GroupAction(actions, *, scoped=True, forwarding=True, launch_configurations=None)``."""

    def __init__(self, actions: Iterable[Any], *, scoped: bool = True, forwarding: bool = True,
                 launch_configurations: Any = None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._actions = entities_of(actions)
        self._scoped, self._forwarding = bool(scoped), bool(forwarding)
        self._launch_configurations = launch_configurations

    def get_sub_entities(self) -> list[Any]:
        return list(self._actions)

    def to_ir(self, cv: Converter) -> a.Action:
        keep = () if self._launch_configurations is None else cv.pairs(
            self._launch_configurations)
        return a.Group(**cv_common(self, cv), actions=cv.actions(self._actions),
                       scoped=self._scoped, forwarding=self._forwarding, keep=keep)


class TimerAction(Action):
    """``TimerAction(*, period, actions, cancel_on_shutdown=True)``."""

    ros_time = False

    def __init__(self, *, period: Any, actions: Iterable[Any], cancel_on_shutdown: Any = True,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._period, self._actions = period, entities_of(actions)
        self._cancel_on_shutdown = cancel_on_shutdown
        self._canceled = False

    @property
    def period(self) -> Any:
        """Return the period: a number, or substitutions (launch's API)."""
        return typed(self._period)

    @property
    def actions(self) -> list[Any]:
        """Return the actions run when the timer fires (launch's API)."""
        return self._actions

    def describe(self) -> str:
        return f"TimerAction(period={self.period}, actions=<actions>)"

    def describe_conditional_sub_entities(self) -> list[tuple[str, Any]]:
        return [(f"{self.period} seconds pass without being canceled", self._actions)]

    def handle(self, context: Any) -> list[Any]:
        """Return what runs when the timer fires: its actions (launch's API)."""
        return list(self._actions)

    def cancel(self) -> None:
        """Cancel the timer (launch's API): statically nothing is pending."""
        self._canceled = True

    def to_ir(self, cv: Converter) -> a.Action:
        period = cv.sub(str(self._period) if isinstance(self._period, (int, float))
                        else self._period)
        cancel = self._cancel_on_shutdown
        return a.Timer(**cv_common(self, cv), period=period, actions=cv.actions(self._actions),
                       cancel_on_shutdown=cancel if isinstance(cancel, bool) else cv.sub(cancel),
                       ros_time=self.ros_time)


class OpaqueFunction(Action):
    """``OpaqueFunction(*, function, args=None, kwargs=None)``: run with a concrete context."""

    def __init__(self, *, function: Callable[..., Any], args: Iterable[Any] | None = None,
                 kwargs: dict[str, Any] | None = None, **other: Any) -> None:
        super().__init__(**other)
        if not callable(function):
            raise TypeError(f"OpaqueFunction expected a callable for 'function', got "
                            f"'{type(function)}'")
        self.function = function
        self.args = list(args or [])
        self.kwargs = dict(kwargs or {})

    def to_ir(self, cv: Converter) -> a.Action:
        return cv.opaque_function(self)  # type: ignore[attr-defined, no-any-return]

    def call(self, context: Any) -> Any:
        """Run the function with a concrete context; return what it yields."""
        return self.function(context, *self.args, **self.kwargs)

    def execute(self, context: Any) -> Any:
        """Run the function (launch's API), as the walk does when it reaches the action."""
        return self.call(context)

    @property
    def label(self) -> str:
        """Return how findings name this action."""
        return f"OpaqueFunction {getattr(self.function, '__name__', 'function')}()"


class ForEach(OpaqueFunction):
    """``ForEach(input_values, *, function)`` (kilted, rolling): one call per mapping."""

    SEPARATOR = ";"

    def __init__(self, input_values: Any, *, function: Callable[..., Any], **kwargs: Any) -> None:
        super().__init__(function=function, **kwargs)
        self._input_values = input_values

    input_values = launch_getter("_input_values",
                                 "Return the input values as substitutions (launch's API).")

    def call(self, context: Any) -> Any:
        import yaml

        values = self._input_values
        text = values if isinstance(values, str) else context.perform_substitution(values)
        entities: list[Any] = []
        for chunk in (part for part in text.split(self.SEPARATOR) if part.strip()):
            mapping = yaml.safe_load(chunk)
            if not isinstance(mapping, dict) and has_placeholder(chunk):
                entities.append(Opaque(f"what ForEach's function builds from {chunk}"))
                continue  # a value only the robot knows: what the call would build is unknown
            if not isinstance(mapping, dict):
                raise ValueError(f"ForEach value {chunk!r} is not a mapping")
            entities.extend(self.function(**mapping) or [])
        return entities

    @property
    def label(self) -> str:
        return "ForEach"


class ForLoop(OpaqueFunction):
    """``ForLoop(length, *, function, name=None)`` (kilted, rolling): one call per index."""

    def __init__(self, length: Any, *, function: Callable[..., Any], name: Any = None,
                 **kwargs: Any) -> None:
        super().__init__(function=function, **kwargs)
        self._length = length
        self._name = name

    length = launch_getter("_length",
                           "Return the number of iterations as substitutions (launch's API).")

    @property
    def name(self) -> Any:
        """Return the loop's name (launch's API)."""
        return self._name

    def call(self, context: Any) -> Any:
        length = self._length
        count = length if isinstance(length, int) else int(context.perform_substitution(length))
        entities: list[Any] = []
        for index in range(min(count, 256)):
            entities.extend(self.function(index) or [])
        return entities

    @property
    def label(self) -> str:
        return "ForLoop"


class OpaqueCoroutine(Action):
    """``OpaqueCoroutine(*, coroutine, ...)``: not modelled."""

    def __init__(self, *, coroutine: Any, args: Any = None, kwargs: Any = None,
                 ignore_context: bool = False, **other: Any) -> None:
        super().__init__(**other)
        self.coroutine = coroutine

    def to_ir(self, cv: Converter) -> a.Action:
        name = getattr(self.coroutine, "__name__", "a coroutine")
        cv.unmodeled(f"OpaqueCoroutine {name}() is not modelled", self._span)
        return a.OpaqueAction(**cv_common(self, cv), description=f"OpaqueCoroutine {name}")


# ----------------------------------------------------------------------------- processes


class ExecuteProcess(Action):
    """``ExecuteProcess(*, cmd, prefix, name, cwd, env, additional_env, **ExecuteLocal)``."""

    def __init__(self, *, cmd: Iterable[Any], prefix: Any = None, name: Any = None,
                 cwd: Any = None, env: Any = None, additional_env: Any = None,
                 shell: bool = False, sigterm_timeout: Any = None, sigkill_timeout: Any = None,
                 emulate_tty: bool = False, output: Any = "log", output_format: str = "",
                 cached_output: bool = False, log_cmd: bool = False, on_exit: Any = None,
                 respawn: Any = False, respawn_delay: float | None = None,
                 respawn_max_retries: int = -1, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._cmd = list(cmd)
        self.cached_output = cached_output
        self.options = {
            "prefix": prefix, "name": name, "cwd": cwd, "env": env,
            "additional_env": additional_env, "shell": shell,
            "sigterm_timeout": sigterm_timeout, "sigkill_timeout": sigkill_timeout,
            "emulate_tty": emulate_tty, "output": output, "log_cmd": log_cmd,
            "on_exit": on_exit, "respawn": respawn, "respawn_delay": respawn_delay,
            "respawn_max_retries": respawn_max_retries,
        }

    @property
    def cmd(self) -> list[list[Any]]:
        """Return the command line, each part a list of substitutions (launch's API)."""
        return [normalized(part) for part in self._cmd]

    @property
    def name(self) -> list[Any] | None:
        """Return the process's name as substitutions, or ``None`` (launch's API)."""
        return normalized(self.options["name"])  # type: ignore[no-any-return]

    @property
    def cwd(self) -> list[Any] | None:
        """Return the working folder as substitutions, or ``None`` (launch's API)."""
        return normalized(self.options["cwd"])  # type: ignore[no-any-return]

    @property
    def env(self) -> list[tuple[list[Any], list[Any]]] | None:
        """Return the environment as pairs of substitutions, or ``None`` (launch's API)."""
        return _env_pairs(self.options["env"])

    @property
    def additional_env(self) -> list[tuple[list[Any], list[Any]]] | None:
        """Return the added environment as pairs of substitutions (launch's API)."""
        return _env_pairs(self.options["additional_env"])

    @property
    def shell(self) -> Any:
        """Return whether the command runs in a shell (launch's API)."""
        return self.options["shell"]

    @property
    def emulate_tty(self) -> Any:
        """Return whether a tty is emulated (launch's API)."""
        return self.options["emulate_tty"]

    @property
    def output(self) -> Any:
        """Return where output goes: substitutions, or a dict as given (launch's API)."""
        output = self.options["output"]
        return output if isinstance(output, dict) else normalized(output)

    @property
    def sigterm_timeout(self) -> list[Any]:
        """Return the SIGTERM timeout as substitutions (launch's API)."""
        return _timeout(self.options["sigterm_timeout"], "sigterm_timeout")

    @property
    def sigkill_timeout(self) -> list[Any]:
        """Return the SIGKILL timeout as substitutions (launch's API)."""
        return _timeout(self.options["sigkill_timeout"], "sigkill_timeout")

    @property
    def process_details(self) -> None:
        """Return the running process's details: ``None`` until it runs, so always here."""
        return None

    @property
    def return_code(self) -> None:
        """Return the exit code: ``None`` until the process ends, so always here."""
        return None

    def get_stdout(self) -> str:
        """Return the cached output: nothing runs statically (launch raises without cache)."""
        return self._cached("stdout")

    def get_stderr(self) -> str:
        """Return the cached error output (see ``get_stdout``)."""
        return self._cached("stderr")

    def _cached(self, stream: str) -> str:
        if not self.cached_output and not _unknown(self.cached_output):
            raise RuntimeError(f"cached output must be true to be able to get {stream}, proc "
                               f"'{self.options['name']}'")
        return ""

    def get_sub_entities(self) -> list[Any]:
        on_exit = self.options["on_exit"]
        if on_exit is None or callable(on_exit):
            return []
        return list(on_exit) if isinstance(on_exit, (list, tuple)) else [on_exit]

    def process_options(self, cv: Converter, *, with_name: bool = True) -> a.ProcessOptions:
        """Return the IR process options."""
        o = self.options
        on_exit = o["on_exit"]
        exit_actions: tuple[a.Action, ...] = ()
        if callable(on_exit):
            cv.unmodeled("a callable on_exit is not modelled", self._span)
        elif on_exit is not None:
            exit_actions = cv.actions(on_exit if isinstance(on_exit, (list, tuple)) else
                                      [on_exit])
        respawn = o["respawn"]
        return a.ProcessOptions(
            name=cv.opt_sub(o["name"]) if with_name else None,
            cwd=cv.opt_sub(o["cwd"]),
            prefix=cv.opt_sub(o["prefix"]),
            env=None if o["env"] is None else cv.pairs(o["env"]),
            additional_env=() if o["additional_env"] is None else cv.pairs(o["additional_env"]),
            output=None if o["output"] is None else cv.sub(o["output"]),
            shell=bool(o["shell"]),
            emulate_tty=bool(o["emulate_tty"]),
            respawn=respawn if isinstance(respawn, bool) else cv.sub(respawn),
            respawn_delay=_number(o["respawn_delay"], float),
            respawn_max_retries=_number(o["respawn_max_retries"], int),
            sigterm_timeout=cv.opt_sub(_text(o["sigterm_timeout"])),
            sigkill_timeout=cv.opt_sub(_text(o["sigkill_timeout"])),
            on_exit=exit_actions,
            log_cmd=bool(o["log_cmd"]),
        )

    def to_ir(self, cv: Converter) -> a.Action:
        return a.ExecuteProcess(**cv_common(self, cv), cmd=tuple(cv.sub(p) for p in self._cmd),
                                process=self.process_options(cv))


ExecuteLocal = ExecuteProcess


def _env_pairs(value: Any) -> list[tuple[list[Any], list[Any]]] | None:
    if value is None:
        return None
    items = value.items() if isinstance(value, dict) else value
    return [(normalized(key), normalized(item)) for key, item in items]


def _timeout(value: Any, name: str) -> list[Any]:
    if value is None:  # launch's default: LaunchConfiguration(name, default=5)
        from launchverify.models.launch_api.launch_substitutions import LaunchConfiguration

        value = LaunchConfiguration(name, default=5)
    return normalized(_text(value))  # type: ignore[no-any-return]


def _number(value: Any, kind: type) -> Any:
    """Return a respawn setting as the IR holds it: launch reads it only when it respawns.

    Anything but a number of its kind (an unknown, a list, a substitution) is not known
    here (``None``); launch would fail on it at run time, not while loading the file.
    """
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    return kind(value) if kind is float or isinstance(value, int) else None


def _text(value: Any) -> Any:
    return str(value) if isinstance(value, (int, float)) and not isinstance(value, bool) else value


# ----------------------------------------------------------------------------- environment


class SetEnvironmentVariable(Action):
    """``SetEnvironmentVariable(name, value)``."""

    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._name, self._value = name, value

    name = launch_getter("_name", "Return the variable's name as substitutions (launch's API).")

    value = launch_getter("_value", "Return the value as substitutions (launch's API).")

    def to_ir(self, cv: Converter) -> a.Action:
        return a.SetEnv(**cv_common(self, cv), name=cv.sub(self._name),
                        value=cv.sub(self._value))


class UnsetEnvironmentVariable(Action):
    """``UnsetEnvironmentVariable(name)``."""

    def __init__(self, name: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._name = name

    name = launch_getter("_name", "Return the variable's name as substitutions (launch's API).")

    def to_ir(self, cv: Converter) -> a.Action:
        return a.UnsetEnv(**cv_common(self, cv), name=cv.sub(self._name))


class AppendEnvironmentVariable(Action):
    """``AppendEnvironmentVariable(name, value, prepend=False, separator=os.pathsep)``."""

    def __init__(self, name: Any, value: Any, prepend: Any = False,
                 separator: Any = os.pathsep, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._name, self._value, self._prepend, self._separator = name, value, prepend, separator

    name = launch_getter("_name", "Return the variable's name as substitutions (launch's API).")

    value = launch_getter("_value", "Return the value as substitutions (launch's API).")

    @property
    def prepend(self) -> Any:
        """Return whether to prepend: a bool, or substitutions (launch's API)."""
        return typed(self._prepend)

    separator = launch_getter("_separator",
                              "Return the separator as substitutions (launch's API).")

    def to_ir(self, cv: Converter) -> a.Action:
        prepend = self._prepend if isinstance(self._prepend, bool) else cv.sub(self._prepend)
        return a.AppendEnv(**cv_common(self, cv), name=cv.sub(self._name),
                           value=cv.sub(self._value), prepend=prepend,
                           separator=cv.sub(self._separator))


class ResetEnvironment(Action):
    """``ResetEnvironment()``."""

    def to_ir(self, cv: Converter) -> a.Action:
        return a.ResetEnv(**cv_common(self, cv))


class PushEnvironment(Action):
    """``PushEnvironment()``."""

    def to_ir(self, cv: Converter) -> a.Action:
        return a.PushEnv(**cv_common(self, cv))


class PopEnvironment(Action):
    """``PopEnvironment()``."""

    def to_ir(self, cv: Converter) -> a.Action:
        return a.PopEnv(**cv_common(self, cv))


# ----------------------------------------------------------------------------- misc


class LogInfo(Action):
    """``LogInfo(*, msg)``."""

    def __init__(self, *, msg: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._msg = msg
        self._level: Any = "INFO"

    msg = launch_getter("_msg", "Return the message as substitutions (launch's API).")

    level = launch_getter("_level", "Return the level as substitutions (launch's API).")

    def to_ir(self, cv: Converter) -> a.Action:
        return a.Log(**cv_common(self, cv), message=cv.sub(self._msg))


class Log(LogInfo):
    """``Log(*, msg, level)`` (rolling)."""

    def __init__(self, *, msg: Any, level: Any = "INFO", **kwargs: Any) -> None:
        super().__init__(msg=msg, **kwargs)
        self._level = level


class Shutdown(Action):
    """``Shutdown(*, reason='reason not given')``."""

    def __init__(self, *, reason: Any = "reason not given", **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.reason = reason
        from launchverify.models.launch_api.launch_events import Shutdown as ShutdownEvent

        self._event = ShutdownEvent(reason=reason)

    @property
    def event(self) -> Any:
        """Return the event this action emits: ``launch.events.Shutdown`` (launch's API)."""
        return self._event

    def to_ir(self, cv: Converter) -> a.Action:
        return a.Shutdown(**cv_common(self, cv), reason=cv.sub(self.reason))


class EmitEvent(Action):
    """``EmitEvent(*, event)``."""

    def __init__(self, *, event: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.event = event

    def to_ir(self, cv: Converter) -> a.Action:
        from launchverify.models.launch_api.launch_events import (
            ActionMatcher,
            ChangeState,
            NodeNameMatcher,
        )

        event = self.event
        fields: dict[str, Any] = {}
        if isinstance(event, ChangeState):
            matcher = event.lifecycle_node_matcher
            transition = str(event.transition_id)  # a vendor's: an unknown expression
            fields["transition_ids"] = (cv.sub(transition) if has_placeholder(transition)
                                        else s.Text(transition),)
            if isinstance(matcher, ActionMatcher):
                fields["matcher"] = "action"
                fields["target"] = (cv.action(matcher.target)
                                    if isinstance(matcher.target, LaunchDescriptionEntity)
                                    else None)
            elif isinstance(matcher, NodeNameMatcher):
                fields["matcher"] = "name"
                fields["target_names"] = (cv.sub(matcher.node_name),)
            else:
                fields["matcher"] = "custom"
        return a.EmitEvent(**cv_common(self, cv), event=type(event).__name__,
                           details=dict(getattr(event, "details", {})), **fields)


class RegisterEventHandler(Action):
    """``RegisterEventHandler(event_handler)``: its entities run when the event happens."""

    def __init__(self, event_handler: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.event_handler = event_handler

    def _called(self, function: Callable[..., Any], handler: str, cv: Converter) -> Any:
        """Return what a handler's function gives, called as launch calls it.

        Its event and context are only known when it fires: unknown values. What it
        returns is walked (what depends on them stays unknown); if it fails on them,
        what it would start is unknown.
        """
        arguments = [Opaque(f"the event {handler} handles"),
                     Opaque("the launch context when it fires")]
        try:  # OnProcessIO's on_stdout takes the event alone, the others the context too
            takes = len(inspect.signature(function).parameters)
        except (TypeError, ValueError):
            takes = 2
        try:
            return function(*arguments[:max(1, min(takes, 2))])
        except Exception as error:  # the launch file's code
            from launchverify.frontends.python.sandbox import TimeLimitExceeded

            if isinstance(error, TimeLimitExceeded):
                raise
            cv.unmodeled(f"a callable in {handler} fails here on what only the event "
                         "gives; what it starts is unknown", self._span)
            return None

    def to_ir(self, cv: Converter) -> a.Action:
        handler = self.event_handler
        entities = getattr(handler, "entities", None)
        if callable(entities):
            entities = self._called(entities, type(handler).__name__, cv)
        target = getattr(handler, "target_action", None)
        ir_target = cv.action(target) if isinstance(target, LaunchDescriptionEntity) else None
        if isinstance(target, Opaque):  # a process of code launchverify cannot see
            ir_target = a.OpaqueAction(span=self._span, description=read(str(target)))
        return a.RegisterEventHandler(**cv_common(self, cv), handler=a.EventHandler(
            event=getattr(handler, "event_name", type(handler).__name__),
            entities=cv.actions(entities if isinstance(entities, (list, tuple)) else
                                [entities] if entities is not None else []),
            span=self._span, target=ir_target,
            handle_once=bool(getattr(handler, "handle_once", False)),
            # a label given as a substitution is compared as an object: it never matches
            filters=tuple((field, value if isinstance(value, str) else "<substitution>")
                          for field, value in getattr(handler, "filters", ())),
            filter_spans=tuple(label_spans(handler, cv)),
            custom_matcher=getattr(handler, "matcher", None) is not None,
        ))


def label_spans(handler: Any, cv: Converter) -> Iterator[tuple[str, Span]]:
    """Yield where each label of an ``OnStateTransition`` is written (LV504 points there)."""
    call = getattr(handler, "_span", None)
    if not isinstance(call, Span):
        return
    written = cv.keyword_values(call)
    for field, _value in getattr(handler, "filters", ()):
        if field in written:
            yield field, written[field]


class UnregisterEventHandler(NoGraphEffect):
    """``UnregisterEventHandler(event_handler)``."""

    def __init__(self, event_handler: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.event_handler = event_handler


def cv_common(action: Action, cv: Converter) -> dict[str, Any]:
    """Return span and condition for an IR action."""
    return action.common(cv)

