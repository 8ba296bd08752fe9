"""Models of ``launch``'s actions, descriptions, description sources and event handlers.

Each model accepts the arguments of the real class (humble to rolling) and raises
``TypeError`` for arguments the real class does not take, as launch would; ``to_ir``
produces the IR the XML and YAML frontends produce for the same action.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable
from typing import Any

from launchverify.ir import actions as a
from launchverify.ir import subst as s
from launchverify.models.launch_api.base import (
    Action,
    Converter,
    LaunchDescriptionEntity,
    check_substitutions,
    flatten,
)


class LaunchDescription(LaunchDescriptionEntity):
    """``LaunchDescription(initial_entities=None, *, deprecated_reason=None)``."""

    def __init__(self, initial_entities: Iterable[Any] | None = None, *,
                 deprecated_reason: str | None = None) -> None:
        super().__init__()
        self.entities: list[Any] = list(initial_entities or [])
        self.deprecated_reason = deprecated_reason

    def add_action(self, action: Any) -> None:
        """Append an action."""
        self.entities.append(action)

    def add_entity(self, entity: Any) -> None:
        """Append an entity."""
        self.entities.append(entity)

    def get_sub_entities(self) -> list[Any]:
        return list(self.entities)

    def get_launch_arguments(self, conditional_inclusion: bool = False) -> list[Any]:
        """Return the argument declarations directly in this description."""
        return [e for e in flatten(self.entities) if isinstance(e, DeclareLaunchArgument)]

    def to_ir(self, cv: Converter) -> a.Action:
        # A description inside another visits its entities in place, without a scope.
        return a.Group(span=self._span, actions=cv.actions(self.entities), scoped=False)


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
        if choices is not None and not list(choices):
            raise RuntimeError(
                "Provided choices arg is empty. Use None to ignore the choice list.")
        self.name = name
        self.default_value = None if default_value is None else check_substitutions(
            default_value)
        self.description = description
        self.choices = None if choices is None else tuple(choices)

    def to_ir(self, cv: Converter) -> a.Action:
        return a.DeclareArgument(**cv_common(self, cv), name=self.name,
                                 default=cv.opt_sub(self.default_value),
                                 description=self.description,
                                 choices=None if self.choices is None else tuple(
                                     str(c) for c in self.choices))


class SetLaunchConfiguration(Action):
    """``SetLaunchConfiguration(name, value)``."""

    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name, self.value = check_substitutions(name), check_substitutions(value)

    def to_ir(self, cv: Converter) -> a.Action:
        return a.SetConfig(**cv_common(self, cv), name=cv.sub(self.name),
                           value=cv.sub(self.value))


class UnsetLaunchConfiguration(Action):
    """``UnsetLaunchConfiguration(name)``."""

    def __init__(self, name: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = name

    def to_ir(self, cv: Converter) -> a.Action:
        return a.UnsetConfig(**cv_common(self, cv), name=cv.sub(self.name))


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


class LaunchDescriptionSource:
    """``LaunchDescriptionSource(launch_description=None, location=..., method=...)``."""

    kind = "any"

    def __init__(self, launch_description: Any = None, location: Any = "<script>",
                 method: str = "") -> None:
        self.launch_description = launch_description
        self.location = location


class PythonLaunchDescriptionSource(LaunchDescriptionSource):
    """``PythonLaunchDescriptionSource(launch_file_path)``."""

    kind = "python"

    def __init__(self, launch_file_path: Any) -> None:
        super().__init__(location=launch_file_path)


class AnyLaunchDescriptionSource(LaunchDescriptionSource):
    """``AnyLaunchDescriptionSource(launch_file_path)``."""

    def __init__(self, launch_file_path: Any) -> None:
        super().__init__(location=launch_file_path)


class FrontendLaunchDescriptionSource(LaunchDescriptionSource):
    """``FrontendLaunchDescriptionSource(launch_file_path, parser=...)``."""

    kind = "frontend"

    def __init__(self, launch_file_path: Any, parser: Any = None) -> None:
        super().__init__(location=launch_file_path)


class XMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    """``launch_xml...XMLLaunchDescriptionSource(launch_file_path)``."""

    kind = "xml"


class YAMLLaunchDescriptionSource(FrontendLaunchDescriptionSource):
    """``launch_yaml...YAMLLaunchDescriptionSource(launch_file_path)``."""

    kind = "yaml"


class IncludeLaunchDescription(Action):
    """``IncludeLaunchDescription(launch_description_source, *, launch_arguments=None)``."""

    def __init__(self, launch_description_source: Any, *, launch_arguments: Any = None,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.source = launch_description_source
        pairs = []
        for pair in launch_arguments or []:  # a dict iterates its keys: launch fails there too
            name, value = pair
            pairs.append((check_substitutions(name), check_substitutions(value)))
        self.launch_arguments = pairs

    def to_ir(self, cv: Converter) -> a.Action:
        arguments = tuple(
            a.IncludeArg(name=cv.sub(name), value=cv.sub(value), span=self._span)
            for name, value in self.launch_arguments
        )
        source = self.source
        if isinstance(source, LaunchDescriptionSource) and source.launch_description is not None:
            sets = tuple(a.SetConfig(span=self._span, name=arg.name, value=arg.value)
                         for arg in arguments)
            inner = cv.actions([source.launch_description])
            return a.Group(**cv_common(self, cv), actions=(*sets, *inner), scoped=False)
        if isinstance(source, LaunchDescriptionSource) and not cv.claim(source):
            cv.fail("this include reuses another include's description source: its actions "
                    "are the same objects, and ros2 launch fails executing them a second time "
                    "('executed more than once')", self._span)
        location = source.location if isinstance(source, LaunchDescriptionSource) else source
        kind = source.kind if isinstance(source, LaunchDescriptionSource) else "any"
        return a.Include(**cv_common(self, cv), path=cv.sub(location), arguments=arguments,
                         source_kind=kind)


class GroupAction(Action):
    """``GroupAction(actions, *, scoped=True, forwarding=True, launch_configurations=None)``."""

    def __init__(self, actions: Iterable[Any], *, scoped: bool = True, forwarding: bool = True,
                 launch_configurations: Any = None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.actions = list(actions)
        self.scoped, self.forwarding = bool(scoped), bool(forwarding)
        self.launch_configurations = launch_configurations

    def get_sub_entities(self) -> list[Any]:
        return list(self.actions)

    def to_ir(self, cv: Converter) -> a.Action:
        keep = () if self.launch_configurations is None else cv.pairs(self.launch_configurations)
        return a.Group(**cv_common(self, cv), actions=cv.actions(self.actions),
                       scoped=self.scoped, forwarding=self.forwarding, keep=keep)


class TimerAction(Action):
    """``TimerAction(*, period, actions, cancel_on_shutdown=True)``."""

    ros_time = False

    def __init__(self, *, period: Any, actions: Iterable[Any], cancel_on_shutdown: Any = True,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.period, self.actions = period, list(actions)
        self.cancel_on_shutdown = cancel_on_shutdown

    def to_ir(self, cv: Converter) -> a.Action:
        period = cv.sub(str(self.period) if isinstance(self.period, (int, float)) else self.period)
        cancel = self.cancel_on_shutdown
        return a.Timer(**cv_common(self, cv), period=period, actions=cv.actions(self.actions),
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

    @property
    def label(self) -> str:
        """Return how findings name this action."""
        return f"OpaqueFunction {getattr(self.function, '__name__', 'function')}()"


class ForEach(OpaqueFunction):
    """``ForEach(input_values, *, function)`` (kilted, rolling): one call per mapping."""

    def __init__(self, input_values: Any, *, function: Callable[..., Any], **kwargs: Any) -> None:
        super().__init__(function=function, **kwargs)
        self.input_values = input_values

    def call(self, context: Any) -> Any:
        import yaml

        values = self.input_values
        text = values if isinstance(values, str) else context.perform_substitution(values)
        entities: list[Any] = []
        for chunk in (part for part in text.split(";") if part.strip()):
            mapping = yaml.safe_load(chunk)
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
        self.length = length

    def call(self, context: Any) -> Any:
        length = self.length
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
        self.cmd = list(cmd)
        self.options = {
            "prefix": prefix, "name": name, "cwd": cwd, "env": env,
            "additional_env": additional_env, "shell": shell,
            "sigterm_timeout": sigterm_timeout, "sigkill_timeout": sigkill_timeout,
            "emulate_tty": emulate_tty, "output": output, "log_cmd": log_cmd,
            "on_exit": on_exit, "respawn": respawn, "respawn_delay": respawn_delay,
            "respawn_max_retries": respawn_max_retries,
        }

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
            respawn_delay=o["respawn_delay"],
            respawn_max_retries=o["respawn_max_retries"],
            sigterm_timeout=cv.opt_sub(_text(o["sigterm_timeout"])),
            sigkill_timeout=cv.opt_sub(_text(o["sigkill_timeout"])),
            on_exit=exit_actions,
            log_cmd=bool(o["log_cmd"]),
        )

    def to_ir(self, cv: Converter) -> a.Action:
        return a.ExecuteProcess(**cv_common(self, cv), cmd=tuple(cv.sub(p) for p in self.cmd),
                                process=self.process_options(cv))


ExecuteLocal = ExecuteProcess


def _text(value: Any) -> Any:
    return str(value) if isinstance(value, (int, float)) and not isinstance(value, bool) else value


# ----------------------------------------------------------------------------- environment


class SetEnvironmentVariable(Action):
    """``SetEnvironmentVariable(name, value)``."""

    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name, self.value = name, value

    def to_ir(self, cv: Converter) -> a.Action:
        return a.SetEnv(**cv_common(self, cv), name=cv.sub(self.name), value=cv.sub(self.value))


class UnsetEnvironmentVariable(Action):
    """``UnsetEnvironmentVariable(name)``."""

    def __init__(self, name: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name = name

    def to_ir(self, cv: Converter) -> a.Action:
        return a.UnsetEnv(**cv_common(self, cv), name=cv.sub(self.name))


class AppendEnvironmentVariable(Action):
    """``AppendEnvironmentVariable(name, value, prepend=False, separator=os.pathsep)``."""

    def __init__(self, name: Any, value: Any, prepend: Any = False,
                 separator: Any = os.pathsep, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name, self.value, self.prepend, self.separator = name, value, prepend, separator

    def to_ir(self, cv: Converter) -> a.Action:
        prepend = self.prepend if isinstance(self.prepend, bool) else cv.sub(self.prepend)
        return a.AppendEnv(**cv_common(self, cv), name=cv.sub(self.name),
                           value=cv.sub(self.value), prepend=prepend,
                           separator=cv.sub(self.separator))


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
        self.msg = msg

    def to_ir(self, cv: Converter) -> a.Action:
        return a.Log(**cv_common(self, cv), message=cv.sub(self.msg))


class Log(LogInfo):
    """``Log(*, msg, level)`` (rolling)."""

    def __init__(self, *, msg: Any, level: Any = "INFO", **kwargs: Any) -> None:
        super().__init__(msg=msg, **kwargs)
        self.level = str(level).lower()


class Shutdown(Action):
    """``Shutdown(*, reason='reason not given')``."""

    def __init__(self, *, reason: Any = "reason not given", **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.reason = reason

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
            fields["transition_ids"] = (s.Text(str(event.transition_id)),)
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

    def to_ir(self, cv: Converter) -> a.Action:
        handler = self.event_handler
        entities = getattr(handler, "entities", None)
        if callable(entities):
            cv.unmodeled(f"a callable in {type(handler).__name__} is not modelled", self._span)
            entities = None
        target = getattr(handler, "target_action", None)
        ir_target = cv.action(target) if isinstance(target, LaunchDescriptionEntity) else None
        return a.RegisterEventHandler(**cv_common(self, cv), handler=a.EventHandler(
            event=getattr(handler, "event_name", type(handler).__name__),
            entities=cv.actions(entities if isinstance(entities, (list, tuple)) else
                                [entities] if entities is not None else []),
            span=self._span, target=ir_target,
            handle_once=bool(getattr(handler, "handle_once", False)),
            # a label given as a substitution is compared as an object: it never matches
            filters=tuple((field, value if isinstance(value, str) else "<substitution>")
                          for field, value in getattr(handler, "filters", ())),
            custom_matcher=getattr(handler, "matcher", None) is not None,
        ))


class UnregisterEventHandler(NoGraphEffect):
    """``UnregisterEventHandler(event_handler)``."""


def cv_common(action: Action, cv: Converter) -> dict[str, Any]:
    """Return span and condition for an IR action."""
    return action.common(cv)

