"""Models of ``launch_ros``: actions, substitutions and descriptions.

Import paths users write (``launch_ros.actions.Node``, ``launch_ros.actions.node.Node``,
``launch_ros.descriptions.ParameterValue``, ``launch_ros.parameter_descriptions``...) all
reach these classes through the module table in ``launch_api/__init__.py``.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from launchverify.ir import actions as a
from launchverify.ir import subst as s
from launchverify.models import distros
from launchverify.models.launch_api.base import (
    Action,
    Converter,
    Modelled,
    Substitution,
    _unknown,
    caller_span,
    check_substitutions,
    described,
    launch_getter,
    normalized,
    typed,
)
from launchverify.models.launch_api.launch_actions import ExecuteProcess, TimerAction, cv_common
from launchverify.models.launch_api.launch_substitutions import (
    LocalSubstitution,
    PathJoinSubstitution,
)

# ----------------------------------------------------------------------------- descriptions


# The attributes the Python frontend's converter reads (``param_file``, ``allow_substs``,
# ``name``, ``value``, ``value_type``) keep the values as given; launch normalizes them to
# lists of substitutions.


class ParameterFile(Modelled):
    """``ParameterFile(param_file, *, allow_substs=False)``."""

    def __init__(self, param_file: Any, *, allow_substs: Any = False) -> None:
        self._span = caller_span()
        self.param_file = param_file
        self.allow_substs = allow_substs

    def evaluate(self, context: Any) -> Path:
        """Return the file's path in ``context`` (launch's API).

        With ``allow_substs`` launch writes a substituted copy to a temporary file when the
        launch runs; statically the copy stands for its source file, as ``RewrittenYaml``.
        """
        param_file = self.param_file
        if not isinstance(param_file, (os.PathLike, bytes)):
            param_file = _perform(context, param_file)
        return Path(os.fsdecode(param_file))

    def cleanup(self) -> None:
        """Remove the temporary copy (launch's API): statically none was written."""


class ParameterValue(Modelled):
    """``ParameterValue(value, *, value_type=None)``."""

    def __init__(self, value: Any, *, value_type: Any = None) -> None:
        self.value = value
        self.value_type = value_type

    def evaluate(self, context: Any) -> Any:
        """Return the value in ``context``, typed as launch types it (launch's API)."""
        from launchverify.models.launch_api.context import perform_typed_substitution

        return perform_typed_substitution(context, typed(self.value), self.value_type)


class Parameter(Modelled):
    """``launch_ros.descriptions.Parameter(name, value, *, value_type=None)``."""

    def __init__(self, name: Any, value: Any, value_type: Any = None) -> None:
        self._span = caller_span()
        self.name, self.value, self.value_type = name, value, value_type

    def evaluate(self, context: Any) -> tuple[str, Any]:
        """Return ``(name, value)`` in ``context`` (launch's API)."""
        value = ParameterValue(self.value, value_type=self.value_type).evaluate(context)
        return _perform(context, self.name), value


def _perform(context: Any, value: Any) -> str:
    from launchverify.models.launch_api.context import perform_substitutions

    return perform_substitutions(context, value)


def _remap_rules(rules: Any) -> list[tuple[list[Any], list[Any]]] | None:
    """``normalize_remap_rules``: each rule a pair of lists of substitutions."""
    if rules is None:
        return None
    return [(normalized(src), normalized(dst)) for src, dst in rules]


class ComposableNode(Modelled):
    """``ComposableNode(*, package, plugin, name=None, namespace=None, ...)``."""

    lifecycle = False

    def __init__(self, *, package: Any, plugin: Any, name: Any = None, namespace: Any = None,
                 parameters: Any = None, remappings: Any = None, extra_arguments: Any = None,
                 condition: Any = None) -> None:
        self._span = caller_span()
        self._package, self._plugin, self._name, self._namespace = (
            package, plugin, name, namespace)
        self._parameters, self._remappings = parameters, remappings
        self._extra_arguments, self._condition = extra_arguments, condition

    package = launch_getter("_package", "Return the package as substitutions (launch_ros's API).")

    node_plugin = launch_getter("_plugin",
                                "Return the plugin as substitutions (launch_ros's API).")

    node_name = launch_getter("_name",
                              "Return the name as substitutions, or ``None`` (launch_ros's API).")

    node_namespace = launch_getter(
        "_namespace", "Return the namespace as substitutions, or ``None`` (launch_ros's API).")

    @property
    def parameters(self) -> Any:
        """Return the parameters as given, or ``None`` (launch_ros normalizes them)."""
        return self._parameters

    @property
    def remappings(self) -> list[tuple[list[Any], list[Any]]] | None:
        """Return the remapping rules as pairs of substitutions (launch_ros's API)."""
        return _remap_rules(self._remappings)

    @property
    def extra_arguments(self) -> Any:
        """Return the extra arguments as given, or ``None`` (launch_ros normalizes them)."""
        return self._extra_arguments

    def condition(self) -> Any:
        """Return the condition (a method, not a property, in launch_ros 0.30)."""
        return self._condition

    def to_description(self, cv: Converter) -> a.ComposableNode:
        """Return the IR description."""
        extra = []
        for entry in self._extra_arguments or []:
            for key, value in (entry.items() if isinstance(entry, dict) else [entry]):
                extra.append(a.ParamItem(name=cv.sub(key), value=cv.param_value(value),
                                         span=self._span))
        return a.ComposableNode(
            package=cv.written(self._span, self._package, position=0, keyword="package"),
            plugin=cv.sub(self._plugin), span=self._span,
            name=cv.opt_sub(self._name), namespace=cv.opt_sub(self._namespace),
            parameters=cv.parameters(self._parameters, self._span),
            remappings=cv.remaps(self._remappings, self._span),
            extra_arguments=tuple(extra), condition=cv.condition(self._condition),
            lifecycle=self.lifecycle,
        )


class ComposableLifecycleNode(ComposableNode):
    """``ComposableLifecycleNode`` (rolling)."""

    lifecycle = True

    def __init__(self, *, autostart: Any = False, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.autostart = autostart

    @property
    def node_autostart(self) -> Any:
        """Return whether the node is brought up on its own (launch_ros's API)."""
        return typed(self.autostart)


# ----------------------------------------------------------------------------- actions


class Node(ExecuteProcess):
    """``Node(*, executable, package=None, name=None, namespace=None, ...)``."""

    UNSPECIFIED_NODE_NAME = "<node_name_unspecified>"
    UNSPECIFIED_NODE_NAMESPACE = "<node_namespace_unspecified>"

    def __init__(self, *, executable: Any, package: Any = None, name: Any = None,
                 namespace: Any = None, exec_name: Any = None, parameters: Any = None,
                 remappings: Any = None, ros_arguments: Any = None, arguments: Any = None,
                 **kwargs: Any) -> None:
        super().__init__(cmd=[], **kwargs)
        if parameters is not None and not isinstance(parameters, list) and not _unknown(
                parameters):  # a vendor's list of parameters: what it holds is unknown
            raise TypeError(f"Expected 'parameters' to be one of [<class 'list'>], but got "
                            f"'{parameters}' of type '{type(parameters)}'")
        self.node_executable, self.node_package = executable, package
        self._node_name, self._node_namespace = name, namespace
        self.options["name"] = exec_name  # the process's name, as launch_ros passes it
        self._exec_name = exec_name
        self._parameters, self._remappings = parameters, remappings
        self._ros_arguments, self._arguments = ros_arguments, arguments

    @property
    def node_name(self) -> str:
        """Raise as launch_ros does: the full name is only known once the node runs."""
        raise RuntimeError("cannot access 'node_name' before executing action")

    @property
    def expanded_node_namespace(self) -> str:
        """Return the namespace launch computes when executing: unspecified until then."""
        return self.UNSPECIFIED_NODE_NAMESPACE

    @property
    def expanded_remapping_rules(self) -> None:
        """Return the remappings launch computes when executing: ``None`` until then."""
        return None

    def is_node_name_fully_specified(self) -> bool:
        """Return whether name and namespace are known (needs ``node_name``, as in launch_ros)."""
        keywords = (self.UNSPECIFIED_NODE_NAME, self.UNSPECIFIED_NODE_NAMESPACE)
        return all(keyword not in self.node_name for keyword in keywords)

    @property
    def cmd(self) -> list[list[Any]]:
        """Return the command line launch_ros builds for the node (launch's API)."""
        cmd: list[Any] = [ExecutableInPackage(package=self.node_package,
                                              executable=self.node_executable)
                          if self.node_package is not None else self.node_executable]
        cmd += list(self._arguments or [])
        if self._ros_arguments is not None:
            cmd += ["--ros-args", *self._ros_arguments]
        cmd += ["--ros-args"]
        if self._node_name is not None:
            cmd += ["-r", LocalSubstitution("ros_specific_arguments['name']",
                                            description="node name")]
        return [normalized(part) for part in cmd]

    def node_fields(self, cv: Converter) -> dict[str, Any]:
        """Return what every Node-like IR action takes."""
        return {
            **cv_common(self, cv),
            "executable": cv.written(self._span, self.node_executable, keyword="executable"),
            "package": (None if self.node_package is None
                        else cv.written(self._span, self.node_package, keyword="package")),
            "name": cv.opt_sub(performed_later(self._node_name, "name")),
            "namespace": cv.opt_sub(performed_later(self._node_namespace, "namespace")),
            "exec_name": cv.opt_sub(self._exec_name),
            "parameters": cv.parameters(self._parameters, self._span),
            "remappings": cv.remaps(self._remappings, self._span),
            "ros_arguments": tuple(cv.sub(x) for x in self._ros_arguments or []),
            "arguments": self.arguments_written(cv),
            "process": self.process_options(cv, with_name=False),
        }

    def arguments_written(self, cv: Converter) -> tuple[s.Sub, ...]:
        """Return ``arguments=``, each literal located where the call's list writes it."""
        given = list(self._arguments or [])
        return tuple(cv.written(self._span, x, keyword="arguments", item=i, items=len(given))
                     for i, x in enumerate(given))

    def to_ir(self, cv: Converter) -> a.Action:
        return a.Node(**self.node_fields(cv))


def performed_later(value: Any, field: str) -> Any:
    """Return a field launch_ros normalizes only in ``execute``, or the IR of its failure.

    A name that is no text (``name=5``) fails only where the node runs, under its condition.
    """
    if value is None:
        return None
    try:
        return check_substitutions(value)
    except TypeError as error:
        return s.Raises(f"TypeError: {error} (the node's {field})")


_NOT_GIVEN: Any = object()


class LifecycleNode(Node):
    """``LifecycleNode(*, name, namespace, autostart=False, **Node)``."""

    def __init__(self, *, name: Any, namespace: Any, autostart: Any = _NOT_GIVEN,
                 **kwargs: Any) -> None:
        if autostart is not _NOT_GIVEN and (why := distros.missing(
                "LifecycleNode(autostart=...)")):
            raise TypeError(f"LifecycleNode.__init__() got an unexpected keyword argument "
                            f"'autostart' ({why})")
        super().__init__(name=name, namespace=namespace, **kwargs)
        self.autostart = False if autostart is _NOT_GIVEN else autostart

    @property
    def node_autostart(self) -> Any:
        """Return whether the node is brought up on its own (launch_ros's API)."""
        return typed(self.autostart)

    @property
    def is_lifecycle_node(self) -> bool:
        """Return ``True`` (launch_ros's API)."""
        return True

    def get_lifecycle_event_manager(self) -> None:
        """Return the manager launch_ros creates when executing: ``None`` until then."""
        return None

    def to_ir(self, cv: Converter) -> a.Action:
        autostart = self.autostart if isinstance(self.autostart, bool) else cv.sub(
            self.autostart)
        return a.LifecycleNode(**self.node_fields(cv), autostart=autostart)


class ComposableNodeContainer(Node):
    """``ComposableNodeContainer(*, name, namespace, composable_node_descriptions=None)``."""

    def __init__(self, *, name: Any, namespace: Any,
                 composable_node_descriptions: Iterable[Any] | None = None,
                 **kwargs: Any) -> None:
        super().__init__(name=name, namespace=namespace, **kwargs)
        self._descriptions = _descriptions(composable_node_descriptions or [])

    def to_ir(self, cv: Converter) -> a.Action:
        return a.ComposableNodeContainer(
            **self.node_fields(cv),
            composable_nodes=tuple(_described(d, cv, self._span) for d in self._descriptions),
        )


def _descriptions(value: Any) -> list[Any]:
    """Return composable node descriptions as a list: an unknown list is one unknown item."""
    return [value] if _unknown(value) else list(value)


def _described(description: Any, cv: Converter, span: Any) -> a.ComposableNode:
    """Return a description's IR: one that code launchverify cannot see built is unknown.

    Its package, plugin and name are unknowns (never one another's: each its own).
    """
    if not _unknown(description):
        return description.to_description(cv)  # type: ignore[no-any-return]
    what = f"a composable node of code launchverify cannot see ({id(description):x})"
    return a.ComposableNode(package=s.Opaque(f"{what}: package"),
                            plugin=s.Opaque(f"{what}: plugin"), span=span,
                            name=s.Opaque(f"{what}: name"))


class LoadComposableNodes(Action):
    """``LoadComposableNodes(*, composable_node_descriptions, target_container)``."""

    def __init__(self, *, composable_node_descriptions: Iterable[Any], target_container: Any,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._descriptions = _descriptions(composable_node_descriptions)
        self._target_container = target_container

    def to_ir(self, cv: Converter) -> a.Action:
        target = self._target_container
        ir_target: s.Sub | a.Action | None = (
            cv.action(target) if isinstance(target, ComposableNodeContainer) else None)
        if ir_target is None:  # launch_ros takes the container's node_name once it ran
            ir_target = cv.sub(target)
        return a.LoadComposableNodes(
            **cv_common(self, cv), target=ir_target,
            composable_nodes=tuple(_described(d, cv, self._span) for d in self._descriptions),
        )


class PushRosNamespace(Action):
    """``PushRosNamespace(namespace)`` / ``PushROSNamespace``."""

    def __init__(self, namespace: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._namespace = namespace

    namespace = launch_getter("_namespace",
                              "Return the namespace as substitutions (launch_ros's API).")

    def to_ir(self, cv: Converter) -> a.Action:
        return a.PushNamespace(**cv_common(self, cv), namespace=cv.sub(self._namespace))


PushROSNamespace = PushRosNamespace


class SetRemap(Action):
    """``SetRemap(src, dst)``."""

    def __init__(self, src: Any, dst: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._src, self._dst = src, dst

    src = launch_getter("_src", "Return what is remapped, as substitutions (launch_ros's API).")

    dst = launch_getter("_dst",
                        "Return what it is remapped to, as substitutions (launch_ros's API).")

    def to_ir(self, cv: Converter) -> a.Action:
        return a.SetRemap(**cv_common(self, cv), src=cv.sub(self._src), dst=cv.sub(self._dst))


class SetParameter(Action):
    """``SetParameter(name, value)``."""

    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._name, self._value = name, value

    @property
    def name(self) -> tuple[Any, ...]:
        """Return the parameter's name: a tuple of substitutions (launch_ros's API)."""
        return tuple(normalized(self._name))

    @property
    def value(self) -> Any:
        """Return the value: scalars as given, substitutions as lists (launch_ros's API)."""
        return typed(self._value)

    def to_ir(self, cv: Converter) -> a.Action:
        return a.SetParameter(**cv_common(self, cv), name=cv.sub(self._name),
                              value=cv.param_value(self._value))


class SetParametersFromFile(Action):
    """``SetParametersFromFile(filename)``."""

    def __init__(self, filename: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.filename = filename

    def to_ir(self, cv: Converter) -> a.Action:
        return a.SetParametersFromFile(**cv_common(self, cv), filename=cv.sub(self.filename))


class SetUseSimTime(Action):
    """``SetUseSimTime(value)``: only the launch process's own node."""

    def __init__(self, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._value = value

    @property
    def value(self) -> Any:
        """Return the value: a bool, or substitutions (launch_ros's API)."""
        return typed(self._value)

    def to_ir(self, cv: Converter) -> a.Action:
        value = self._value if isinstance(self._value, bool) else cv.sub(self._value)
        return a.SetUseSimTime(**cv_common(self, cv), value=value)


class SetROSLogDir(Action):
    """``SetROSLogDir(new_log_dir)``."""

    def __init__(self, new_log_dir: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._new_log_dir = new_log_dir

    log_dir = launch_getter("_new_log_dir",
                            "Return the new log folder as substitutions (launch_ros's API).")

    def to_ir(self, cv: Converter) -> a.Action:
        return a.SetRosLogDir(**cv_common(self, cv), new_log_dir=cv.sub(self._new_log_dir))


class RosTimer(TimerAction):
    """``RosTimer`` / ``ROSTimer``: a timer on ROS time."""

    ros_time = True


ROSTimer = RosTimer


class LifecycleTransition(Action):
    """``LifecycleTransition(*, lifecycle_node_names, transition_ids)``."""

    transition_targets = {
        1: {"start_state": "configuring", "goal_state": "inactive"},
        2: {"start_state": "cleaningup", "goal_state": "unconfigured"},
        3: {"start_state": "activating", "goal_state": "active"},
        4: {"start_state": "deactivating", "goal_state": "inactive"},
        5: {"start_state": "shuttingdown", "goal_state": "finalized"},
        6: {"start_state": "shuttingdown", "goal_state": "finalized"},
        7: {"start_state": "shuttingdown", "goal_state": "finalized"},
    }

    def __init__(self, *, lifecycle_node_names: Iterable[Any], transition_ids: Iterable[Any],
                 **kwargs: Any) -> None:
        if why := distros.missing("LifecycleTransition"):
            raise ImportError(f"cannot import name 'LifecycleTransition' from "
                              f"'launch_ros.actions' ({why})")
        super().__init__(**kwargs)
        # a vendor's list (our own list() of it is empty) stands for unknown items
        self.names = [lifecycle_node_names] if _unknown(lifecycle_node_names) \
            else list(lifecycle_node_names)
        self.transition_ids = [transition_ids] if _unknown(transition_ids) \
            else list(transition_ids)
        if not self.names or not self.transition_ids:
            raise ValueError("LifecycleTransition needs node names and transition ids")

    def to_ir(self, cv: Converter) -> a.Action:
        return a.EmitEvent(**cv_common(self, cv), event="LifecycleTransition",
                           transition_ids=tuple(cv.sub(str(t) if isinstance(t, int) else t)
                                                for t in self.transition_ids),
                           matcher="name", target_names=tuple(cv.sub(n) for n in self.names))


# ----------------------------------------------------------------------------- substitutions


class _FindPackageBase(PathJoinSubstitution):
    """What launch_ros's ``FindPackage`` substitutions share: a ``PathSubstitution`` of itself."""

    def __init__(self, package: Any) -> None:
        super().__init__([self])
        self._package = package

    package = launch_getter("_package", "Return the package as substitutions (launch_ros's API).")

    def describe(self) -> str:
        return f"{type(self).__name__}(pkg={described(self._package)})"


class FindPackagePrefix(_FindPackageBase):
    """``FindPackagePrefix(package)`` (``/`` appends)."""

    def find(self, package_name: str) -> str:
        """Return the package's install prefix (launch_ros's API)."""
        from launchverify.models.launch_api.ament import get_package_prefix

        return get_package_prefix(package_name)

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.FindPackagePrefix(cv.written(self._span, self._package, position=0,
                                              keyword="package"))


class FindPackageShare(_FindPackageBase):
    """``FindPackageShare(package)`` (``/`` appends)."""

    def find(self, package_name: str) -> str:
        """Return the share folder (launch_ros's API)."""
        from launchverify.models.launch_api.ament import get_package_share_directory

        return get_package_share_directory(package_name)

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.FindPackageShare(cv.written(self._span, self._package, position=0,
                                             keyword="package"))


class FindPackage(FindPackagePrefix):
    """``FindPackage(package)``: launch_ros's base of the two; taken as FindPackagePrefix."""


class ExecutableInPackage(FindPackagePrefix):
    """``ExecutableInPackage(executable, package)``."""

    def __init__(self, executable: Any, package: Any) -> None:
        super().__init__(package)
        self._executable = executable

    executable = launch_getter("_executable",
                               "Return the executable as substitutions (launch_ros's API).")

    def describe(self) -> str:
        return (f"ExecInPkg(pkg={described(self._package)}, "
                f"exec={described(self._executable)})")

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.ExecutableInPackage(cv.sub(self._executable), cv.sub(self._package))


class ParameterSubstitution(Substitution):
    """``launch_ros.substitutions.Parameter(name, *, default=None)``."""

    def __init__(self, name: Any, *, default: Any = None) -> None:
        super().__init__()
        self._name, self._default = name, default

    name = launch_getter("_name",
                         "Return the parameter's name as substitutions (launch_ros's API).")

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.RosParameter(cv.sub(self._name), cv.opt_sub(self._default))
