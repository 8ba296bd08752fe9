"""Typed records for the actions of ROS 2 launch and launch_ros.

Every frontend (XML, YAML, Python) builds these. Records compare by identity, as launch's
actions do (event handlers target an action object). Each carries its ``span`` and optional
``condition``; attribute-level spans sit in ``attr_spans`` so findings can point precisely.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from launchverify.ir.conditions import Condition
from launchverify.ir.subst import Sub
from launchverify.span import Span

Spans = dict[str, Span]


@dataclass(frozen=True, eq=False, kw_only=True)
class Action:
    """Base of every action: where it is written and when it runs."""

    span: Span
    condition: Condition | None = None
    attr_spans: Spans = field(default_factory=dict, repr=False)

    kind = "action"

    def at(self, attr: str) -> Span:
        """Return the span of one attribute, or of the whole action when unknown."""
        return self.attr_spans.get(attr, self.span)

    def sub_actions(self) -> tuple[Action, ...]:
        """Return actions nested in this one (groups, timers, handlers), for static walks."""
        return ()


# ----------------------------------------------------------------------------- arguments


@dataclass(frozen=True, eq=False, kw_only=True)
class DeclareArgument(Action):
    """``<arg>`` / ``DeclareLaunchArgument``: sets the default unless already set."""

    name: str
    default: Sub | None = None
    description: str | None = None
    choices: tuple[str, ...] | None = None
    kind = "arg"


@dataclass(frozen=True, eq=False, kw_only=True)
class SetConfig(Action):
    """``<let>`` / ``SetLaunchConfiguration``."""

    name: Sub
    value: Sub
    kind = "let"


@dataclass(frozen=True, eq=False, kw_only=True)
class UnsetConfig(Action):
    """``UnsetLaunchConfiguration``."""

    name: Sub
    kind = "unset"


@dataclass(frozen=True, eq=False, kw_only=True)
class ResetConfigs(Action):
    """``<reset>`` / ``ResetLaunchConfigurations``: clear the scope, keep the given entries."""

    keep: tuple[tuple[Sub, Sub], ...] | None = None
    kind = "reset"


@dataclass(frozen=True, eq=False, kw_only=True)
class PushConfigs(Action):
    """``PushLaunchConfigurations``."""

    kind = "push_configurations"


@dataclass(frozen=True, eq=False, kw_only=True)
class PopConfigs(Action):
    """``PopLaunchConfigurations``."""

    kind = "pop_configurations"


# ----------------------------------------------------------------------------- structure


@dataclass(frozen=True, eq=False, kw_only=True)
class IncludeArg:
    """One ``<arg name value>`` (or ``<let>``) under an include."""

    name: Sub
    value: Sub
    span: Span


@dataclass(frozen=True, eq=False, kw_only=True)
class Include(Action):
    """``<include>`` / ``IncludeLaunchDescription``: not scoped, arguments leak."""

    path: Sub
    arguments: tuple[IncludeArg, ...] = ()
    source_kind: str = "any"
    kind = "include"


@dataclass(frozen=True, eq=False, kw_only=True)
class Group(Action):
    """``<group>`` / ``GroupAction``."""

    actions: tuple[Action, ...]
    scoped: bool = True
    forwarding: bool = True
    keep: tuple[tuple[Sub, Sub], ...] = ()
    kind = "group"

    def sub_actions(self) -> tuple[Action, ...]:
        return self.actions


@dataclass(frozen=True, eq=False, kw_only=True)
class ForLoop(Action):
    """``<for len name>`` / ``ForLoop`` (kilted, rolling)."""

    length: Sub
    name: str
    actions: tuple[Action, ...]
    kind = "for"

    def sub_actions(self) -> tuple[Action, ...]:
        return self.actions


@dataclass(frozen=True, eq=False, kw_only=True)
class ForEach(Action):
    """``<for_each values>`` / ``ForEach`` (kilted, rolling)."""

    values: Sub
    actions: tuple[Action, ...]
    kind = "for_each"

    def sub_actions(self) -> tuple[Action, ...]:
        return self.actions


@dataclass(frozen=True, eq=False, kw_only=True)
class Timer(Action):
    """``<timer>`` / ``TimerAction`` (``ros_timer``/``RosTimer`` when ``ros_time``)."""

    period: Sub
    actions: tuple[Action, ...]
    cancel_on_shutdown: Sub | bool = True
    ros_time: bool = False
    kind = "timer"

    def sub_actions(self) -> tuple[Action, ...]:
        return self.actions


# ----------------------------------------------------------------------------- environment


@dataclass(frozen=True, eq=False, kw_only=True)
class SetEnv(Action):
    """``<set_env>`` / ``SetEnvironmentVariable``."""

    name: Sub
    value: Sub
    kind = "set_env"


@dataclass(frozen=True, eq=False, kw_only=True)
class UnsetEnv(Action):
    """``<unset_env>`` / ``UnsetEnvironmentVariable``."""

    name: Sub
    kind = "unset_env"


@dataclass(frozen=True, eq=False, kw_only=True)
class AppendEnv(Action):
    """``<append_env>`` / ``AppendEnvironmentVariable`` (``prepend`` for prepending)."""

    name: Sub
    value: Sub
    prepend: Sub | bool = False
    separator: Sub | None = None
    kind = "append_env"


@dataclass(frozen=True, eq=False, kw_only=True)
class ResetEnv(Action):
    """``<reset_env>`` / ``ResetEnvironment``."""

    kind = "reset_env"


@dataclass(frozen=True, eq=False, kw_only=True)
class PushEnv(Action):
    """``PushEnvironment``."""

    kind = "push_env"


@dataclass(frozen=True, eq=False, kw_only=True)
class PopEnv(Action):
    """``PopEnvironment``."""

    kind = "pop_env"


# ----------------------------------------------------------------------------- ROS scope


@dataclass(frozen=True, eq=False, kw_only=True)
class PushNamespace(Action):
    """``<push_ros_namespace>`` / ``PushROSNamespace``: lasts until the scope ends."""

    namespace: Sub
    kind = "push_ros_namespace"


@dataclass(frozen=True, eq=False, kw_only=True)
class SetRemap(Action):
    """``<set_remap>`` / ``SetRemap``: a remap rule for later nodes in scope."""

    src: Sub
    dst: Sub
    kind = "set_remap"


@dataclass(frozen=True, eq=False, kw_only=True)
class SetParameter(Action):
    """``<set_parameter>`` / ``SetParameter``: ``-p name:=value`` on later nodes in scope."""

    name: Sub
    value: ParamValue
    kind = "set_parameter"


@dataclass(frozen=True, eq=False, kw_only=True)
class SetParametersFromFile(Action):
    """``<set_parameters_from_file>`` / ``SetParametersFromFile``."""

    filename: Sub
    kind = "set_parameters_from_file"


@dataclass(frozen=True, eq=False, kw_only=True)
class SetUseSimTime(Action):
    """``<set_use_sim_time>``: only the launch process's own node (not launched nodes)."""

    value: Sub | bool
    kind = "set_use_sim_time"


@dataclass(frozen=True, eq=False, kw_only=True)
class SetRosLogDir(Action):
    """``<set_ros_log_dir>`` / ``SetROSLogDir``."""

    new_log_dir: Sub
    kind = "set_ros_log_dir"


# ----------------------------------------------------------------------------- parameters


@dataclass(frozen=True, eq=False, kw_only=True)
class ParamValue:
    """A parameter value: text with substitutions, a list of them, or a typed literal.

    ``value_type`` is the frontend ``type=`` (``str``, ``int``, ..., ``yaml``) or ``None``
    for YAML typing rules.
    """

    value: Sub | tuple[Sub, ...] | bool | int | float | str | tuple[object, ...] | None
    value_type: str | None = None


@dataclass(frozen=True, eq=False, kw_only=True)
class ParamItem:
    """One named parameter (``<param name value>``); nested names are joined with dots."""

    name: Sub
    value: ParamValue
    span: Span


@dataclass(frozen=True, eq=False, kw_only=True)
class ParamDict:
    """Inline parameters given together (one dict of ``parameters=[...]``)."""

    items: tuple[ParamItem, ...]
    span: Span


@dataclass(frozen=True, eq=False, kw_only=True)
class ParamFile:
    """A parameter file (``<param from>``, a path, ``ParameterFile``)."""

    path: Sub
    span: Span
    allow_substs: Sub | bool = False


ParamEntry = ParamDict | ParamFile


@dataclass(frozen=True, eq=False, kw_only=True)
class Remap:
    """One ``<remap from to>`` rule of a node.

    ``call``: the action the rule is written inside when ``span`` is a piece of it (a
    Python tuple in ``Node(remappings=[...])``); findings show it as related.
    """

    src: Sub
    dst: Sub
    span: Span
    call: Span | None = None


# ----------------------------------------------------------------------------- processes


@dataclass(frozen=True, eq=False, kw_only=True)
class ProcessOptions:
    """What ExecuteProcess/ExecuteLocal take besides the command."""

    name: Sub | None = None
    cwd: Sub | None = None
    prefix: Sub | None = None
    env: tuple[tuple[Sub, Sub], ...] | None = None
    additional_env: tuple[tuple[Sub, Sub], ...] = ()
    output: Sub | None = None
    shell: bool = False
    emulate_tty: bool | None = None
    respawn: Sub | bool = False
    respawn_delay: float | None = None
    respawn_max_retries: int | None = None
    sigterm_timeout: Sub | float | None = None
    sigkill_timeout: Sub | float | None = None
    on_exit: tuple[Action, ...] = ()
    log_cmd: bool = False


@dataclass(frozen=True, eq=False, kw_only=True)
class ExecuteProcess(Action):
    """``<executable>`` / ``ExecuteProcess``."""

    cmd: tuple[Sub, ...]
    process: ProcessOptions = field(default_factory=ProcessOptions)
    kind = "executable"

    def sub_actions(self) -> tuple[Action, ...]:
        return self.process.on_exit


@dataclass(frozen=True, eq=False, kw_only=True)
class Node(Action):
    """``<node>`` / ``launch_ros.actions.Node``."""

    executable: Sub
    package: Sub | None = None
    name: Sub | None = None
    namespace: Sub | None = None
    exec_name: Sub | None = None
    parameters: tuple[ParamEntry, ...] = ()
    remappings: tuple[Remap, ...] = ()
    ros_arguments: tuple[Sub, ...] = ()
    arguments: tuple[Sub, ...] = ()
    process: ProcessOptions = field(default_factory=ProcessOptions)
    kind = "node"

    def sub_actions(self) -> tuple[Action, ...]:
        return self.process.on_exit


@dataclass(frozen=True, eq=False, kw_only=True)
class LifecycleNode(Node):
    """``<lifecycle_node>`` / ``LifecycleNode``: a managed node (name and namespace required)."""

    autostart: Sub | bool = False
    kind = "lifecycle_node"


@dataclass(frozen=True, eq=False, kw_only=True)
class ComposableNode:
    """``<composable_node>`` / ``ComposableNode`` description (loaded into a container)."""

    package: Sub
    plugin: Sub
    span: Span
    name: Sub | None = None
    namespace: Sub | None = None
    parameters: tuple[ParamEntry, ...] = ()
    remappings: tuple[Remap, ...] = ()
    extra_arguments: tuple[ParamItem, ...] = ()
    condition: Condition | None = None
    lifecycle: bool = False
    autostart: Sub | bool = False
    attr_spans: Spans = field(default_factory=dict, repr=False)

    def at(self, attr: str) -> Span:
        """Return the span of one attribute, or of the description."""
        return self.attr_spans.get(attr, self.span)


@dataclass(frozen=True, eq=False, kw_only=True)
class ComposableNodeContainer(Node):
    """``<node_container>`` / ``ComposableNodeContainer``."""

    composable_nodes: tuple[ComposableNode, ...] = ()
    kind = "node_container"


@dataclass(frozen=True, eq=False, kw_only=True)
class LoadComposableNodes(Action):
    """``<load_composable_node>`` / ``LoadComposableNodes``."""

    target: Sub | Action
    composable_nodes: tuple[ComposableNode, ...]
    kind = "load_composable_node"


# ----------------------------------------------------------------------------- misc


@dataclass(frozen=True, eq=False, kw_only=True)
class Log(Action):
    """``<log>`` / ``LogInfo`` / ``Log``."""

    message: Sub
    level: str = "info"
    kind = "log"


@dataclass(frozen=True, eq=False, kw_only=True)
class Shutdown(Action):
    """``<shutdown>`` / ``Shutdown``."""

    reason: Sub | None = None
    kind = "shutdown"


@dataclass(frozen=True, eq=False, kw_only=True)
class EventHandler:
    """An event handler (``OnProcessExit``, ``OnShutdown``, ...) and what it runs."""

    event: str
    entities: tuple[Action, ...]
    span: Span
    target: Action | None = None
    handle_once: bool = False
    # OnStateTransition: the labels it compares (transition, start_state, goal_state)
    filters: tuple[tuple[str, str], ...] = ()
    filter_spans: tuple[tuple[str, Span], ...] = ()  # where each label is written
    custom_matcher: bool = False  # a matcher function launchverify cannot read


@dataclass(frozen=True, eq=False, kw_only=True)
class RegisterEventHandler(Action):
    """``RegisterEventHandler``: its entities run later, when the event happens."""

    handler: EventHandler
    kind = "register_event_handler"

    def sub_actions(self) -> tuple[Action, ...]:
        return self.handler.entities


@dataclass(frozen=True, eq=False, kw_only=True)
class EmitEvent(Action):
    """``EmitEvent``: queues an event (``Shutdown``, ``ChangeState``, ...).

    Lifecycle requests (``ChangeState``, and ``LifecycleTransition``, which emits them)
    say whom they address: ``matcher`` is ``action`` (``matches_action``: ``target``),
    ``name`` (``matches_node_name`` or node names: ``target_names``) or ``custom``.
    """

    event: str
    details: dict[str, object] = field(default_factory=dict)
    transition_ids: tuple[Sub, ...] = ()
    matcher: str = ""
    target: Action | None = None
    target_names: tuple[Sub, ...] = ()
    kind = "emit_event"


@dataclass(frozen=True, eq=False, kw_only=True)
class OpaqueResult:
    """What running an OpaqueFunction gave: actions to visit, problems to report."""

    actions: tuple[Action, ...]
    problems: tuple[object, ...] = ()
    # name, found, has a default [, where the read failed]
    reads: tuple[tuple[str, bool, bool] | tuple[str, bool, bool, Span], ...] = ()
    lookups: tuple[tuple[str, Span], ...] = ()  # packages looked up by Python code
    mentions: tuple[str, ...] = ()  # strings its code holds: reads on untaken paths
    # it read the configurations as a whole (iterated, copied, printed them): what it gave
    # may depend on any of them, not only on ``reads``
    reads_all: bool = False


@dataclass(frozen=True, eq=False, kw_only=True)
class OpaqueFunction(Action):
    """``OpaqueFunction``: Python run with a concrete context when the walk reaches it.

    ``run`` takes the launch configurations (name to value; unknown values as
    placeholders) and the current launch file, and returns what the function yields.
    """

    description: str
    run: Callable[[Mapping[str, Any], Path], OpaqueResult]
    kind = "opaque_function"


@dataclass(frozen=True, eq=False, kw_only=True)
class OpaqueAction(Action):
    """Something launchverify cannot see into (``OpaqueFunction``, an unknown class).

    ``anywhere``: it stands for what the code may have built anywhere in its list (other
    answers about unknown values), not for something done at its place.
    """

    description: str
    anywhere: bool = False
    kind = "opaque"


@dataclass(frozen=True, eq=False, kw_only=True)
class LaunchFile:
    """A parsed launch file: its top-level actions."""

    path: Path
    format: str
    actions: tuple[Action, ...]
    span: Span
    deprecated: str | None = None
    lookups: tuple[tuple[str, Span], ...] = ()  # packages looked up by Python code
    # actions given to code launchverify cannot see, which may run them (Python files)
    handed: tuple[Action, ...] = ()
    # configurations given to such code, which may read them (Python files)
    mentions: tuple[str, ...] = ()
