"""Models of ``launch_ros``: actions, substitutions and descriptions.

Import paths users write (``launch_ros.actions.Node``, ``launch_ros.actions.node.Node``,
``launch_ros.descriptions.ParameterValue``, ``launch_ros.parameter_descriptions``...) all
reach these classes through the module table in ``launch_api/__init__.py``.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from launchverify.ir import actions as a
from launchverify.ir import subst as s
from launchverify.models import distros
from launchverify.models.launch_api.base import Action, Converter, Substitution, caller_span
from launchverify.models.launch_api.launch_actions import ExecuteProcess, TimerAction, cv_common
from launchverify.models.launch_api.launch_substitutions import PathJoinSubstitution

# ----------------------------------------------------------------------------- descriptions


class ParameterFile:
    """``ParameterFile(param_file, *, allow_substs=False)``."""

    def __init__(self, param_file: Any, *, allow_substs: Any = False) -> None:
        self._span = caller_span()
        self.param_file = param_file
        self.allow_substs = allow_substs


class ParameterValue:
    """``ParameterValue(value, *, value_type=None)``."""

    def __init__(self, value: Any, *, value_type: Any = None) -> None:
        self.value = value
        self.value_type = value_type


class Parameter:
    """``launch_ros.descriptions.Parameter(name, value, value_type=None)``."""

    def __init__(self, name: Any, value: Any, value_type: Any = None) -> None:
        self._span = caller_span()
        self.name, self.value, self.value_type = name, value, value_type


class ComposableNode:
    """``ComposableNode(*, package, plugin, name=None, namespace=None, ...)``."""

    lifecycle = False

    def __init__(self, *, package: Any, plugin: Any, name: Any = None, namespace: Any = None,
                 parameters: Any = None, remappings: Any = None, extra_arguments: Any = None,
                 condition: Any = None) -> None:
        self._span = caller_span()
        self.package, self.plugin, self.name, self.namespace = package, plugin, name, namespace
        self.parameters, self.remappings = parameters, remappings
        self.extra_arguments, self.condition = extra_arguments, condition

    def to_description(self, cv: Converter) -> a.ComposableNode:
        """Return the IR description."""
        extra = []
        for entry in self.extra_arguments or []:
            for key, value in (entry.items() if isinstance(entry, dict) else [entry]):
                extra.append(a.ParamItem(name=cv.sub(key), value=cv.param_value(value),
                                         span=self._span))
        return a.ComposableNode(
            package=cv.sub(self.package), plugin=cv.sub(self.plugin), span=self._span,
            name=cv.opt_sub(self.name), namespace=cv.opt_sub(self.namespace),
            parameters=cv.parameters(self.parameters, self._span),
            remappings=cv.remaps(self.remappings, self._span),
            extra_arguments=tuple(extra), condition=cv.condition(self.condition),
            lifecycle=self.lifecycle,
        )


class ComposableLifecycleNode(ComposableNode):
    """``ComposableLifecycleNode`` (rolling)."""

    lifecycle = True

    def __init__(self, *, autostart: Any = False, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.autostart = autostart


# ----------------------------------------------------------------------------- actions


class Node(ExecuteProcess):
    """``Node(*, executable, package=None, name=None, namespace=None, ...)``."""

    def __init__(self, *, executable: Any, package: Any = None, name: Any = None,
                 namespace: Any = None, exec_name: Any = None, parameters: Any = None,
                 remappings: Any = None, ros_arguments: Any = None, arguments: Any = None,
                 **kwargs: Any) -> None:
        super().__init__(cmd=[], **kwargs)
        if parameters is not None and not isinstance(parameters, list):
            raise TypeError(f"Expected 'parameters' to be one of [<class 'list'>], but got "
                            f"'{parameters}' of type '{type(parameters)}'")
        self.node_executable, self.node_package = executable, package
        self.node_name_value, self.node_namespace = name, namespace
        self.exec_name = exec_name
        self.parameters, self.remappings = parameters, remappings
        self.ros_arguments, self.arguments = ros_arguments, arguments

    def node_fields(self, cv: Converter) -> dict[str, Any]:
        """Return what every Node-like IR action takes."""
        return {
            **cv_common(self, cv),
            "executable": cv.sub(self.node_executable),
            "package": cv.opt_sub(self.node_package),
            "name": cv.opt_sub(self.node_name_value),
            "namespace": cv.opt_sub(self.node_namespace),
            "exec_name": cv.opt_sub(self.exec_name),
            "parameters": cv.parameters(self.parameters, self._span),
            "remappings": cv.remaps(self.remappings, self._span),
            "ros_arguments": tuple(cv.sub(x) for x in self.ros_arguments or []),
            "arguments": tuple(cv.sub(x) for x in self.arguments or []),
            "process": self.process_options(cv, with_name=False),
        }

    def to_ir(self, cv: Converter) -> a.Action:
        return a.Node(**self.node_fields(cv))


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
        self.descriptions = list(composable_node_descriptions or [])

    def to_ir(self, cv: Converter) -> a.Action:
        return a.ComposableNodeContainer(
            **self.node_fields(cv),
            composable_nodes=tuple(d.to_description(cv) for d in self.descriptions),
        )


class LoadComposableNodes(Action):
    """``LoadComposableNodes(*, composable_node_descriptions, target_container)``."""

    def __init__(self, *, composable_node_descriptions: Iterable[Any], target_container: Any,
                 **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.descriptions = list(composable_node_descriptions)
        self.target_container = target_container

    def to_ir(self, cv: Converter) -> a.Action:
        target = self.target_container
        if isinstance(target, ComposableNodeContainer):
            ir_target: s.Sub | a.Action = _container_name(target, cv)
        else:
            ir_target = cv.sub(target)
        return a.LoadComposableNodes(
            **cv_common(self, cv), target=ir_target,
            composable_nodes=tuple(d.to_description(cv) for d in self.descriptions),
        )


def _container_name(container: ComposableNodeContainer, cv: Converter) -> s.Sub:
    parts = [cv.sub(container.node_namespace), s.Text("/"), cv.sub(container.node_name_value)]
    return s.concat(parts)


class PushRosNamespace(Action):
    """``PushRosNamespace(namespace)`` / ``PushROSNamespace``."""

    def __init__(self, namespace: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.namespace = namespace

    def to_ir(self, cv: Converter) -> a.Action:
        return a.PushNamespace(**cv_common(self, cv), namespace=cv.sub(self.namespace))


PushROSNamespace = PushRosNamespace


class SetRemap(Action):
    """``SetRemap(src, dst)``."""

    def __init__(self, src: Any, dst: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.src, self.dst = src, dst

    def to_ir(self, cv: Converter) -> a.Action:
        return a.SetRemap(**cv_common(self, cv), src=cv.sub(self.src), dst=cv.sub(self.dst))


class SetParameter(Action):
    """``SetParameter(name, value)``."""

    def __init__(self, name: Any, value: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.name, self.value = name, value

    def to_ir(self, cv: Converter) -> a.Action:
        return a.SetParameter(**cv_common(self, cv), name=cv.sub(self.name),
                              value=cv.param_value(self.value))


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
        self.value = value

    def to_ir(self, cv: Converter) -> a.Action:
        value = self.value if isinstance(self.value, bool) else cv.sub(self.value)
        return a.SetUseSimTime(**cv_common(self, cv), value=value)


class SetROSLogDir(Action):
    """``SetROSLogDir(new_log_dir)``."""

    def __init__(self, new_log_dir: Any, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self.new_log_dir = new_log_dir

    def to_ir(self, cv: Converter) -> a.Action:
        return a.SetRosLogDir(**cv_common(self, cv), new_log_dir=cv.sub(self.new_log_dir))


class RosTimer(TimerAction):
    """``RosTimer`` / ``ROSTimer``: a timer on ROS time."""

    ros_time = True


ROSTimer = RosTimer


class LifecycleTransition(Action):
    """``LifecycleTransition(*, lifecycle_node_names, transition_ids)``."""

    def __init__(self, *, lifecycle_node_names: Iterable[Any], transition_ids: Iterable[Any],
                 **kwargs: Any) -> None:
        if why := distros.missing("LifecycleTransition"):
            raise ImportError(f"cannot import name 'LifecycleTransition' from "
                              f"'launch_ros.actions' ({why})")
        super().__init__(**kwargs)
        self.names = list(lifecycle_node_names)
        self.transition_ids = list(transition_ids)
        if not self.names or not self.transition_ids:
            raise ValueError("LifecycleTransition needs node names and transition ids")

    def to_ir(self, cv: Converter) -> a.Action:
        return a.EmitEvent(**cv_common(self, cv), event="LifecycleTransition",
                           transition_ids=tuple(cv.sub(str(t) if isinstance(t, int) else t)
                                                for t in self.transition_ids),
                           matcher="name", target_names=tuple(cv.sub(n) for n in self.names))


# ----------------------------------------------------------------------------- substitutions


class FindPackageShare(PathJoinSubstitution):
    """``FindPackageShare(package)`` (a ``PathSubstitution`` in rolling: ``/`` appends)."""

    def __init__(self, package: Any) -> None:
        super().__init__([])
        self.package = package

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.FindPackageShare(cv.sub(self.package))

    def __truediv__(self, other: Any) -> PathJoinSubstitution:
        return PathJoinSubstitution([self, other])

    def find(self, package_name: str) -> str:
        """Return the share folder (launch_ros's API)."""
        from launchverify.models.launch_api.ament import get_package_share_directory

        return get_package_share_directory(package_name)


class FindPackagePrefix(PathJoinSubstitution):
    """``FindPackagePrefix(package)`` (a ``PathSubstitution`` in rolling)."""

    def __init__(self, package: Any) -> None:
        super().__init__([])
        self.package = package

    def __truediv__(self, other: Any) -> PathJoinSubstitution:
        return PathJoinSubstitution([self, other])

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.FindPackagePrefix(cv.sub(self.package))


class FindPackage(FindPackagePrefix):
    """``FindPackage(package)`` (the old name of FindPackagePrefix)."""


class ExecutableInPackage(Substitution):
    """``ExecutableInPackage(executable, package)``."""

    def __init__(self, executable: Any, package: Any) -> None:
        super().__init__()
        self.executable, self.package = executable, package

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.ExecutableInPackage(cv.sub(self.executable), cv.sub(self.package))


class ParameterSubstitution(Substitution):
    """``launch_ros.substitutions.Parameter(name, *, default=None)``."""

    def __init__(self, name: Any, *, default: Any = None) -> None:
        super().__init__()
        self.name, self.default = name, default

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.RosParameter(cv.sub(self.name), cv.opt_sub(self.default))
