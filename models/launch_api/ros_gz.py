"""Models of ros_gz's launch actions: what ``GzServer``, ``GzSpawnModel``, ``RosGzBridge`` start.

ros_gz_sim and ros_gz_bridge register launch extensions (``launch.frontend.
launch_extension`` entry points) whose ``@expose_action`` tags are ``<gz_server>``,
``<gz_spawn_model>`` and ``<ros_gz_bridge>``; Python launch files import the same classes
from ``ros_gz_sim.actions`` and ``ros_gz_bridge.actions``. The XML and YAML tags and the
Python classes build the same IR here, learned from the packages' sources (ros_gz 1.0.8
and later on jazzy, 2.x on kilted and rolling):

- ``GzServer`` sets ``GZ_SIM_SYSTEM_PLUGIN_PATH`` and ``GZ_SIM_RESOURCE_PATH`` (their
  values on the machine plus what packages export), then starts ``ros_gz_sim gzserver``
  (its code names the node ``gzserver``) with the parameters ``world_sdf_file`` and
  ``world_sdf_string``; with ``use_composition`` the component ``ros_gz_sim::GzServer``
  named ``gz_server`` instead, in a new ``rclcpp_components component_container`` called
  ``container_name`` when ``create_own_container``, else loaded into that container.
- ``RosGzBridge`` starts ``ros_gz_bridge bridge_node`` named ``bridge_name`` in
  ``namespace`` (``--log-level``, respawned after 2 s with ``use_respawn``), or the
  component ``ros_gz_bridge::RosGzBridge`` in the same two composed set-ups. Its
  parameters are ``config_file``, the ``'key': 'value'`` pairs of ``bridge_params`` and
  ``extra_bridge_params`` (Python) or the ``<topic>``/``<service>`` children (frontends)
  as ``bridges.bridge_N.*`` with ``bridge_names``.
- ``GzSpawnModel`` includes ros_gz_sim's ``gz_spawn_model.launch.py``: its arguments become
  launch configurations of the including scope (an include leaks them) and ``ros_gz_sim
  create`` (node ``ros_gz_sim``) starts with them as parameters. That file reads ``R``,
  ``P`` and ``Y``, not the ``roll``, ``pitch`` and ``yaw`` the action passes, so those
  stay ``0.0`` unless the launch sets ``R``... itself. Omitted arguments are empty (the
  pose ``0.0``), as since ros_gz#909 and #926; earlier releases passed ``None`` and
  launch failed with "'NoneType' object is not iterable", which is not reported here.

The actions pick the set-up from their boolean arguments when they run. A value written
out picks it here; one that depends on launch arguments becomes a condition on each
set-up, so each is checked with the argument values that select it. None of this exists
before jazzy: with humble or iron checked, the tags are unknown and the imports fail.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from typing import Any

from launchverify.ir import actions as a
from launchverify.ir import subst as s
from launchverify.ir.conditions import Condition, IfCondition
from launchverify.models import booleans, distros
from launchverify.models.launch_api.base import Action, Converter
from launchverify.span import Span

FIRST_DISTRO = "jazzy"
CONTAINER = ("rclcpp_components", "component_container")
DEFAULT_CONTAINER = "ros_gz_container"

Flag = s.Sub | bool  # a boolean argument: written out, or an expression


def missing(what: str) -> str | None:
    """Return why ros_gz's launch actions are absent in the checked distribution, if so."""
    distro = distros.current()
    if distro is None or distro not in distros.DISTROS or \
            distros.DISTROS.index(distro) >= distros.DISTROS.index(FIRST_DISTRO):
        return None
    return f"{what} is not in {distro} (since {FIRST_DISTRO})"


@dataclass(frozen=True)
class Written:
    """Where an action is written: the spans its IR points at, and its own condition."""

    span: Span
    condition: Condition | None = None
    attrs: Mapping[str, Span] = field(default_factory=dict)

    def spans(self, **renamed: str) -> dict[str, Span]:
        """Return the spans of IR attributes, each taken from a written attribute."""
        return {key: self.attrs[name] for key, name in renamed.items() if name in self.attrs}


# ----------------------------------------------------------------------------- values


def truth(flag: Flag) -> bool | None:
    """Return a boolean argument as the action coerces it when written out, else ``None``.

    ``None`` also for text launch cannot coerce: the conditions built from it then fail
    where the walker evaluates them, as the action fails when it runs.
    """
    if isinstance(flag, bool):
        return flag
    if isinstance(flag, s.Text):
        try:
            return booleans.typed_truth(flag.text)
        except booleans.InvalidBoolean:
            return None
    return None


def _sub(flag: Flag) -> s.Sub:
    """Return a flag as an expression, for conditions (``True`` reads as ``true``)."""
    return s.Text(booleans.bool_text(flag)) if isinstance(flag, bool) else flag


def flag_or_sub(flag: Flag) -> Flag:
    """Return a flag as a bool when written out (``respawn=True``), else as an expression."""
    known = truth(flag)
    return known if known is not None else _sub(flag)


def _invalid(flag: Flag) -> bool:
    """Return whether a written-out flag is text the action cannot coerce (it fails)."""
    return isinstance(flag, s.Text) and truth(flag) is None


Setup = tuple[str, Condition | None, str]  # kind, what selects it, the attribute deciding


def setups(use_composition: Flag, create_own_container: Flag) -> list[Setup]:
    """Return the set-ups that can run (``node``, ``container``, ``load``) and what selects each.

    A written value launch cannot coerce makes the action fail when it runs: one set-up
    under a condition that fails the same way stands for it.
    """
    for name, flag in (("use_composition", use_composition),
                       ("create_own_container", create_own_container)):
        if _invalid(flag):
            return [("node", IfCondition(s.NotSub(_sub(flag))), name)]
    use, own = truth(use_composition), truth(create_own_container)
    composed, own_sub = _sub(use_composition), _sub(create_own_container)
    out: list[Setup] = []
    if use is not True:
        out.append(("node", None if use is False else IfCondition(s.NotSub(composed)),
                    "use_composition"))
    if use is False:
        return out
    for kind, wanted in (("container", True), ("load", False)):
        if own is not None and own is not wanted:
            continue
        parts: list[s.Sub] = [] if use is True else [composed]
        if own is None:
            parts.append(own_sub if wanted else s.NotSub(own_sub))
        condition = None if not parts else IfCondition(
            parts[0] if len(parts) == 1 else s.AndSub(parts[0], parts[1]))
        out.append((kind, condition,
                    "create_own_container" if use is True else "use_composition"))
    return out


def bridge_param_pairs(text: str) -> dict[str, str]:
    """Parse ``bridge_params`` as the action does; raise its ``ValueError`` on a bad pair.

    Braces, quotes and spaces are dropped, pairs split at ``,`` and each at ``:``.

    Examples:
        >>> bridge_param_pairs("'qos_overrides./clock.publisher.durability': 'volatile'")
        {'qos_overrides./clock.publisher.durability': 'volatile'}
        >>> bridge_param_pairs("")
        {}
    """
    simplified = text.translate({ord(c): None for c in "{} \"'"})
    if not simplified:
        return {}
    out: dict[str, str] = {}
    for index, pair in enumerate(simplified.split(",")):
        parts = pair.split(":")
        if len(parts) != 2:
            raise ValueError(f"dictionary update sequence element #{index} has length "
                             f"{len(parts)}; 2 is required")
        out[parts[0]] = parts[1]
    return out


def bridge_params_problem(given: s.Sub) -> str | None:
    """Return why ``bridge_params`` cannot be read here (LV003), or ``None``.

    Releases differ on text that is not ``'key': 'value'`` pairs (ros_gz#899, #903), so
    such text is left unknown rather than called an error.
    """
    if not isinstance(given, s.Text):
        return (f"bridge_params {given.describe()} is only known when the launch runs: "
                "the bridge parameters it adds are unknown")
    try:
        bridge_param_pairs(given.text)
    except ValueError:
        return (f"bridge_params {given.text!r} is not 'key': 'value' pairs: the bridge "
                "parameters it adds are unknown")
    return None


def param_dict(values: Mapping[str, a.ParamValue], span: Span) -> a.ParamDict:
    """Return inline parameters (one Python dict of ``parameters=[...]``)."""
    return a.ParamDict(items=tuple(a.ParamItem(name=s.Text(name), value=value, span=span)
                                   for name, value in values.items()), span=span)


# ----------------------------------------------------------------------------- what starts


def _component(package: str, plugin: str, name: s.Sub, namespace: s.Sub | None,
               parameters: tuple[a.ParamEntry, ...], where: Written) -> a.ComposableNode:
    """Return the component form of a node; each set-up gets its own description object."""
    return a.ComposableNode(
        package=s.Text(package), plugin=s.Text(plugin), name=name, namespace=namespace,
        parameters=parameters, span=where.span,
        extra_arguments=(a.ParamItem(name=s.Text("use_intra_process_comms"),
                                     value=a.ParamValue(value=True), span=where.span),),
        attr_spans=where.spans(name="bridge_name", namespace="namespace"),
    )


def _started(where: Written, use_composition: Flag, create_own_container: Flag,
             container_name: s.Sub, node: Callable[[Condition | None, dict[str, Span]], a.Node],
             component: Callable[[], a.ComposableNode]) -> list[a.Action]:
    """Return the node, or the component in its container, under what selects each."""
    out: list[a.Action] = []
    for kind, condition, deciding in setups(use_composition, create_own_container):
        spans = where.spans(**{"if": deciding}) if condition is not None else {}
        if kind == "node":
            out.append(node(condition, spans))
        elif kind == "container":
            out.append(a.ComposableNodeContainer(
                span=where.span, condition=condition,
                attr_spans={**spans, **where.spans(name="container_name")},
                package=s.Text(CONTAINER[0]), executable=s.Text(CONTAINER[1]),
                name=container_name, namespace=s.Text(""),
                process=a.ProcessOptions(output=s.Text("screen")),
                composable_nodes=(component(),)))
        else:
            out.append(a.LoadComposableNodes(
                span=where.span, condition=condition,
                attr_spans={**spans, **where.spans(target="container_name")},
                target=container_name, composable_nodes=(component(),)))
    return out


def _group(where: Written, actions: Iterable[a.Action]) -> a.Group:
    """Return what an action runs: its entities, in its own scope, when its condition holds."""
    return a.Group(span=where.span, condition=where.condition,
                   attr_spans=where.spans(**{"if": "if", "unless": "unless"}),
                   actions=tuple(actions), scoped=False)


def gz_server(where: Written, *, container_name: s.Sub, create_own_container: Flag,
              use_composition: Flag, parameters: tuple[a.ParamEntry, ...]) -> a.Group:
    """Return what ``GzServer`` runs; ``parameters`` hold ``world_sdf_file``/``_string``."""
    env = [a.SetEnv(span=where.span, name=s.Text(name), value=s.concat(value)) for name, value in (
        ("GZ_SIM_SYSTEM_PLUGIN_PATH", [
            s.EnvVar(s.Text("GZ_SIM_SYSTEM_PLUGIN_PATH"), s.Text("")), s.Text(":"),
            s.EnvVar(s.Text("LD_LIBRARY_PATH"), s.Text("")), s.Text(":"),
            s.Opaque("plugin paths exported by packages (gazebo_ros plugin_path)")]),
        ("GZ_SIM_RESOURCE_PATH", [
            s.EnvVar(s.Text("GZ_SIM_RESOURCE_PATH"), s.Text("")), s.Text(":"),
            s.Opaque("model paths exported by packages (gazebo_ros gazebo_model_path)")]),
    )]

    def node(condition: Condition | None, spans: dict[str, Span]) -> a.Node:
        return a.Node(span=where.span, condition=condition, attr_spans=spans,
                      package=s.Text("ros_gz_sim"), executable=s.Text("gzserver"),
                      parameters=parameters, process=a.ProcessOptions(output=s.Text("screen")))

    def component() -> a.ComposableNode:
        return _component("ros_gz_sim", "ros_gz_sim::GzServer", s.Text("gz_server"), None,
                          parameters, where)

    return _group(where, [*env, *_started(where, use_composition, create_own_container,
                                          container_name, node, component)])


def ros_gz_bridge(where: Written, *, bridge_name: s.Sub, namespace: s.Sub,
                  container_name: s.Sub, create_own_container: Flag, use_composition: Flag,
                  use_respawn: Flag, log_level: s.Sub,
                  parameters: tuple[a.ParamEntry, ...]) -> a.Group:
    """Return what ``RosGzBridge`` runs; ``parameters`` hold ``config_file`` and the rest."""

    def node(condition: Condition | None, spans: dict[str, Span]) -> a.Node:
        return a.Node(
            span=where.span, condition=condition,
            attr_spans={**spans, **where.spans(name="bridge_name", namespace="namespace",
                                               respawn="use_respawn")},
            package=s.Text("ros_gz_bridge"), executable=s.Text("bridge_node"),
            name=bridge_name, namespace=namespace, parameters=parameters,
            arguments=(s.Text("--ros-args"), s.Text("--log-level"), log_level),
            process=a.ProcessOptions(output=s.Text("screen"), respawn=flag_or_sub(use_respawn),
                                     respawn_delay=2.0))

    def component() -> a.ComposableNode:
        return _component("ros_gz_bridge", "ros_gz_bridge::RosGzBridge", bridge_name,
                          namespace, parameters, where)

    return _group(where, _started(where, use_composition, create_own_container,
                                  container_name, node, component))


# The arguments GzSpawnModel passes to its include, and the defaults of those omitted.
SPAWN_ARGUMENTS = ("world", "file", "model_string", "topic", "entity_name", "allow_renaming",
                   "x", "y", "z", "roll", "pitch", "yaw")
SPAWN_DEFAULTS = {"allow_renaming": "False", "x": "0.0", "y": "0.0", "z": "0.0",
                  "roll": "0.0", "pitch": "0.0", "yaw": "0.0"}
# parameter of create -> (launch configuration it is read from, default of that read); the
# launch file reads R/P/Y, which the action never sets.
SPAWN_PARAMETERS = (("world", "world", None), ("file", "file", None),
                    ("string", "model_string", None), ("topic", "topic", None),
                    ("name", "entity_name", None), ("allow_renaming", "allow_renaming", None),
                    ("x", "x", "0.0"), ("y", "y", "0.0"), ("z", "z", "0.0"),
                    ("R", "R", "0.0"), ("P", "P", "0.0"), ("Y", "Y", "0.0"))


def gz_spawn_model(where: Written, arguments: Mapping[str, s.Sub | None]) -> a.Group:
    """Return what ``GzSpawnModel`` runs: its include's configurations, then ``create``."""
    sets = [a.SetConfig(span=where.attrs.get(name, where.span), name=s.Text(name),
                        value=value if value is not None
                        else s.Text(SPAWN_DEFAULTS.get(name, "")))
            for name in SPAWN_ARGUMENTS for value in [arguments.get(name)]]
    values = {parameter: a.ParamValue(value=s.LaunchConfig(
        s.Text(config), None if default is None else s.Text(default)))
        for parameter, config, default in SPAWN_PARAMETERS}
    create = a.Node(span=where.span, package=s.Text("ros_gz_sim"), executable=s.Text("create"),
                    parameters=(param_dict(values, where.span),),
                    process=a.ProcessOptions(output=s.Text("screen")))
    return _group(where, [*sets, create])


# ----------------------------------------------------------------------------- Python


class _RosGzAction(Action):
    """What the three actions share: unknown before jazzy, like their modules."""

    module = ""

    def __init__(self, **kwargs: Any) -> None:
        if why := missing(f"{self.module}.{type(self).__name__}"):
            raise ImportError(f"No module named '{self.module}' ({why})")
        super().__init__(**kwargs)

    def written(self, cv: Converter) -> Written:
        """Return where the action is written, with its own condition."""
        common = self.common(cv)
        return Written(common["span"], common["condition"], common.get("attr_spans", {}))


def _flag(value: Any, cv: Converter) -> Flag:
    """``normalize_typed_substitution(value, bool)``: a bool stays, the rest is an expression."""
    return value if isinstance(value, bool) else cv.sub(value)


class GzServer(_RosGzAction):
    """``ros_gz_sim.actions.GzServer(*, world_sdf_file='', world_sdf_string='', ...)``."""

    module = "ros_gz_sim.actions"

    def __init__(self, *, world_sdf_file: Any = "", world_sdf_string: Any = "",
                 container_name: Any = DEFAULT_CONTAINER, create_own_container: Any = False,
                 use_composition: Any = False, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._world_sdf_file, self._world_sdf_string = world_sdf_file, world_sdf_string
        self._container_name = container_name
        self._create_own_container, self._use_composition = create_own_container, use_composition

    def to_ir(self, cv: Converter) -> a.Action:
        return gz_server(
            self.written(cv), container_name=cv.sub(self._container_name),
            create_own_container=_flag(self._create_own_container, cv),
            use_composition=_flag(self._use_composition, cv),
            parameters=cv.parameters([{"world_sdf_file": self._world_sdf_file,
                                       "world_sdf_string": self._world_sdf_string}], self._span))


class GzSpawnModel(_RosGzAction):
    """``ros_gz_sim.actions.GzSpawnModel(*, world=None, file=None, ..., yaw=None)``."""

    module = "ros_gz_sim.actions"

    def __init__(self, *, world: Any = None, file: Any = None, model_string: Any = None,
                 topic: Any = None, entity_name: Any = None, allow_renaming: Any = None,
                 x: Any = None, y: Any = None, z: Any = None, roll: Any = None,
                 pitch: Any = None, yaw: Any = None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        given = (world, file, model_string, topic, entity_name, allow_renaming, x, y, z, roll,
                 pitch, yaw)
        self._arguments = dict(zip(SPAWN_ARGUMENTS, given, strict=True))

    def to_ir(self, cv: Converter) -> a.Action:
        return gz_spawn_model(self.written(cv), {name: cv.opt_sub(value)
                                                 for name, value in self._arguments.items()})


class RosGzBridge(_RosGzAction):
    """``ros_gz_bridge.actions.RosGzBridge(*, bridge_name, config_file='', ...)``."""

    module = "ros_gz_bridge.actions"

    def __init__(self, *, bridge_name: Any, config_file: Any = "",
                 container_name: Any = DEFAULT_CONTAINER, create_own_container: Any = False,
                 namespace: Any = "", use_composition: Any = False, use_respawn: Any = False,
                 log_level: Any = "info", bridge_params: Any = "",
                 extra_bridge_params: Any = None, **kwargs: Any) -> None:
        super().__init__(**kwargs)
        self._bridge_name, self._config_file = bridge_name, config_file
        self._container_name, self._namespace = container_name, namespace
        self._create_own_container, self._use_composition = create_own_container, use_composition
        self._use_respawn, self._log_level = use_respawn, log_level
        self._bridge_params, self._extra_bridge_params = bridge_params, extra_bridge_params

    def _parameters(self, cv: Converter) -> tuple[a.ParamEntry, ...]:
        """Return ``[{'config_file': ..., **bridge_params, **extra_bridge_params}]``."""
        parsed: dict[Any, Any] = {}
        given = cv.sub(self._bridge_params)
        problem = bridge_params_problem(given)
        if problem is None and isinstance(given, s.Text):
            parsed.update(bridge_param_pairs(given.text))
        elif problem is not None:
            cv.unmodeled(problem, self._span)
        extra = self._extra_bridge_params
        # a dict; jazzy's releases took a list holding one (extra_bridge_params[0])
        extras = [extra] if isinstance(extra, Mapping) else extra
        if isinstance(extras, (list, tuple)) and all(isinstance(e, Mapping) for e in extras):
            for item in extras:
                parsed.update(item)
        elif extra is not None:
            cv.unmodeled(f"extra_bridge_params of type {type(extra).__name__} is not "
                         "modelled: the bridge parameters it adds are unknown", self._span)
        return cv.parameters([{"config_file": self._config_file, **parsed}], self._span)

    def to_ir(self, cv: Converter) -> a.Action:
        return ros_gz_bridge(
            self.written(cv), bridge_name=cv.sub(self._bridge_name),
            namespace=cv.sub(self._namespace), container_name=cv.sub(self._container_name),
            create_own_container=_flag(self._create_own_container, cv),
            use_composition=_flag(self._use_composition, cv),
            use_respawn=_flag(self._use_respawn, cv), log_level=cv.sub(self._log_level),
            parameters=self._parameters(cv))
