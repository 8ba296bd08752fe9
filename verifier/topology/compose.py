"""Each launched node's endpoints, fully qualified: the launch graph meets the sources.

For every node a launch starts, the interface its executable (or component plugin) has in
the workspace's sources (``nodes.package_interfaces``) is taken, and each endpoint's name
as written (or the value the launch gives the parameter it comes from, else that
parameter's default) is resolved against the node's namespace, name and remap rules
(``resolve``). Runs after evaluation, next to the rules, and reads only the graph and the
sources; ``check`` imports it only when a launched node has sources (the wiring rules).

Unknowns stay unknown: a name that needs something not known before launch (a symbolic
namespace, a remap rule with an argument in it, a parameter set from an expression) comes
out as ``None`` with the reason.
The controllers ros2_control's spawners load are added after their spawner
(``topology.controllers``).
"""

from __future__ import annotations

import shlex
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING, Protocol

from launchverify.graph import LaunchGraph, NodeRecord, Origin
from launchverify.ir.subst import Sub, Text, walk
from launchverify.ir.symbolic import Arg, EnvInput, Select
from launchverify.models.ros2_control import CONTROL_NODE, MANAGER_NAME
from launchverify.models.ros_names import node_fqn
from launchverify.parameters import effective_parameters
from launchverify.span import Span
from launchverify.topology.model import Endpoint, EndpointKind, NodeInterface
from launchverify.topology.resolve import (
    Resolution,
    RuleLike,
    UnknownRule,
    expand,
    node_identity,
    parse_rule,
    resolve,
)
from launchverify.workspace.packages import Package, PackageIndex
from launchverify.workspace.paths import display_path

if TYPE_CHECKING:
    from launchverify.frontends.param_file import ParamFile

SERVICE_KINDS = (EndpointKind.SERVICE, EndpointKind.CLIENT)
# Names a node's code gives itself where the extractor cannot see it (a variable).
DEFAULT_NODE_NAMES = {CONTROL_NODE: MANAGER_NAME}


class InterfaceSource(Protocol):
    """Where a node's interface comes from (the workspace's sources, or a test's table)."""

    def interface(self, package: str, executable: str,
                  component: bool) -> tuple[NodeInterface | None, str | None]:
        """Return the interface of an executable or plugin, or ``None`` and why not."""


class WorkspaceInterfaces:
    """Node interfaces read from the sources of the packages a ``PackageIndex`` knows.

    Each package is read once, when a node of it is first asked for. A package with no
    sources in the workspace (a released one, installed or not, or a folder holding only
    launch and configuration files) falls back to the model shipped with launchverify
    (``topology.shipped``), read the same lazy way; sources in the workspace always win
    over a model.
    """

    def __init__(self, index: PackageIndex, models: bool = True) -> None:
        self.index = index
        self.models = models
        self._read: dict[str, list[NodeInterface]] = {}
        self._failed: dict[str, str] = {}
        self._param_files: dict[Path, ParamFile] = {}

    def interface(self, package: str, executable: str,
                  component: bool) -> tuple[NodeInterface | None, str | None]:
        """Return the interface of ``executable`` (or plugin) of ``package``, or why none.

        The second item is the reason when there is no interface, and where a model's
        interface comes from when there is one.
        """
        found = self.index.find(package)
        if found is None or found.source is None:
            return self._modelled(package, executable, component, found is None)
        if package not in self._read:
            from launchverify.topology.nodes import package_interfaces

            try:
                self._read[package] = package_interfaces(
                    Package(package, source=found.source), self.index.lookup())
            except Exception as error:  # one package's surprise must not end the graph
                self._failed[package] = f"{type(error).__name__}: {error}"
                self._read[package] = []
        if package in self._failed:
            return None, (f"the sources of {package} could not be read: "
                          f"{self._failed[package]}")
        if not any(i.sources for i in self._read[package]):  # launch files and configs only
            return self._modelled(package, executable, component, False)
        match = _match(self._read[package], executable, component)
        if match is None:
            what = "component" if component else "executable"
            return None, f"no {what} {executable} found in the sources of {package}"
        return match, None

    def parameter_file(self, path: str) -> ParamFile | None:
        """Return a parameter file a command line names (a spawner's ``--param-file``).

        Read as the evaluator reads a node's: found as ros2 launch would, and only inside
        the workspace; ``None`` when it is elsewhere, missing or not readable.
        """
        from launchverify.frontends.param_file import load_param_file
        from launchverify.workspace.paths import resolved

        if not path or not Path(path).is_absolute():
            return None
        located = self.index.locate(Path(path))
        if located is None or not any(resolved(located).is_relative_to(w)
                                      for w in self.index.workspaces):
            return None
        if located not in self._param_files:
            self._param_files[located] = load_param_file(located)
        loaded = self._param_files[located]
        return loaded if loaded.readable else None

    def _modelled(self, package: str, executable: str, component: bool,
                  missing: bool) -> tuple[NodeInterface | None, str | None]:
        """Return the interface the shipped model of a package without sources gives."""
        from launchverify.models import distros
        from launchverify.topology.shipped import ModelError, shipped_model

        why = (f"package {package} is not found" if missing else
               f"package {package} has no C++ or Python sources in the workspace")
        try:
            model = shipped_model(package, distros.current()) if self.models else None
        except ModelError as error:
            return None, f"{why}, and its shipped interface model is broken: {error}"
        if model is None:
            return None, f"{why}: its node interfaces are not known (no model is shipped)"
        match = _match(list(model.interfaces), executable, component)
        if match is None:
            what = "component" if component else "executable"
            return None, (f"{why}, and the model shipped for it (extracted from "
                          f"{model.source.describe()}) has no {what} {executable}")
        return match, (f"interface from the model shipped with launchverify, extracted from "
                       f"{model.source.describe()}")


def _match(candidates: list[NodeInterface], executable: str,
           component: bool) -> NodeInterface | None:
    """Return the interface of an executable (its own, before a component's) or plugin."""
    if component:
        matches = [i for i in candidates if i.component == executable]
    else:
        matches = sorted((i for i in candidates if i.executable == executable),
                         key=lambda i: i.component is not None)
    return matches[0] if matches else None


@dataclass(frozen=True, slots=True)
class ComposedEndpoint:
    """One endpoint of one launched node with its fully qualified name (or why not).

    ``value_from`` says where a name read from a parameter came from: ``launch`` (the
    launch sets the parameter for this node) or ``default`` (the sources' default).
    """

    node: NodeRecord
    endpoint: Endpoint
    name: str | None
    reason: str | None = None
    value_from: str | None = None
    remapped_by: str | None = None


@dataclass(frozen=True, slots=True)
class Spawn:
    """How a ros2_control controller becomes a node: a spawner asks its manager to load it.

    ``undefined``: no source gives the controller's type although every one was read, so
    the manager refuses to load it; ``defined`` then names the controllers it does know.
    ``type_at`` is where the type (``kind``) is written literally, in a launch file or a
    parameter file (``None``: it is not, a launch argument gives it); ``type_exact`` says
    that place holds exactly its text (a fix may replace it).
    """

    spawner: NodeRecord
    name: str
    manager: str | None  # the manager's fully qualified name, when known
    undefined: bool = False
    defined: tuple[str, ...] = ()
    kind: str | None = None  # the controller's type, when known
    type_at: Span | None = None
    type_exact: bool = False


@dataclass(frozen=True, slots=True)
class NodeEndpoints:
    """A launched node, its interface (``None``: ``note`` says why) and its endpoints.

    With an interface, ``note`` says which shipped model it comes from, if one does.
    """

    node: NodeRecord
    package: str | None
    executable: str | None
    interface: NodeInterface | None
    endpoints: tuple[ComposedEndpoint, ...] = ()
    note: str | None = None
    fqn: str | None = None  # from the launch, else from the name its sources give
    spawn: Spawn | None = None  # a controller: how it is loaded

    @property
    def spawner(self) -> NodeRecord | None:
        """Return the spawner that loads this node, a controller; ``None`` for others."""
        return None if self.spawn is None else self.spawn.spawner


@dataclass
class _Identity:
    """A node's name and namespace as far as known, and why not where not."""

    name: str | None
    namespace: str | None
    name_reason: str | None = None
    namespace_reason: str | None = None
    rules: list[RuleLike] = field(default_factory=list)


class Composer:
    """Composes one graph's nodes with their interfaces, in one view.

    ``symbolic``: values that depend on launch arguments stay unknown (the view of every
    branch); otherwise the arguments as given (then defaults) decide them.
    """

    def __init__(self, graph: LaunchGraph, source: InterfaceSource, symbolic: bool) -> None:
        self.graph = graph
        self.source = source
        self.symbolic = symbolic

    def text(self, sub: Sub | None) -> str | None:
        """Return a value when this view knows it."""
        if sub is None or (self.symbolic and _has_inputs(sub)):
            return None
        return self.graph.base(sub)

    def describe(self, sub: Sub) -> str:
        """Return a value as an expression, for reasons."""
        return self.graph.display(sub) or sub.describe()

    def shown(self, origin: Origin) -> bool:
        """Return whether a record belongs in this view (as ``graph`` lists nodes)."""
        return self.symbolic or self.graph.runs(origin) is not False

    def compose(self) -> list[NodeEndpoints]:
        """Return every node of the view with its fully qualified endpoints.

        The controllers spawners load come right after their spawner.
        """
        from launchverify.topology.controllers import with_controllers

        return with_controllers(
            self, [self.node(node) for node in self.graph.nodes if self.shown(node.origin)])

    def node(self, node: NodeRecord) -> NodeEndpoints:
        """Return one node's endpoints (none, with a note, when its interface is unknown)."""
        package, executable = self.text(node.package), self.text(node.executable)
        if package is None or executable is None:
            return NodeEndpoints(node, package, executable, None,
                                 note="its package or executable is not known before "
                                 f"launch: {node.executable_label()}")
        interface, note = self.source.interface(package, executable,
                                                node.composable)
        if interface is None:
            return NodeEndpoints(node, package, executable, None, note=note)
        identity = self.identity(node, interface)
        endpoints = tuple(self.endpoint(node, e, identity) for e in interface.endpoints)
        fqn = None
        if identity.name is not None and identity.namespace is not None:
            fqn = node_fqn(identity.namespace, identity.name)
        return NodeEndpoints(node, package, executable, interface, endpoints, fqn=fqn,
                             note=note)  # a model's origin, when the interface is one

    def identity(self, node: NodeRecord, interface: NodeInterface) -> _Identity:
        """Return the node's name, namespace and remap rules as this view knows them."""
        identity = _Identity(None, "/")
        if node.name is not None:
            identity.name = self.text(node.name)
            if identity.name is None:
                identity.name_reason = ("the node's name is not known before launch: "
                                        + self.describe(node.name))
        else:
            identity.name = interface.node_name or DEFAULT_NODE_NAMES.get(
                (interface.package, interface.executable))
            if identity.name is None:
                identity.name_reason = "neither the launch nor the sources give the node's name"
        if node.namespace is not None:
            identity.namespace = self.text(node.namespace)
            if identity.namespace is None:
                identity.namespace_reason = ("the node's namespace is not known before "
                                             "launch: " + self.describe(node.namespace))
        given, reason = self.ros_argument_rules(node)
        if given:  # before launch's own __node/__ns: they win over name= and namespace=
            identity.name, identity.namespace, _ = node_identity(
                identity.name, identity.namespace, given, False, False)
            identity.rules.extend(given)
        if reason is not None:  # an unknown one after them: whatever it renames is unknown
            identity.rules.append(UnknownRule(reason))
        identity.rules.extend(self.remap_rules(node))
        name, namespace, reason = node_identity(
            identity.name, identity.namespace, identity.rules,
            launch_named=node.name is not None, launch_namespaced=node.namespace is not None)
        if reason is not None and name is None and identity.name is not None:
            identity.name_reason = reason
        if reason is not None and namespace is None and identity.namespace is not None:
            identity.namespace_reason = reason
        identity.name, identity.namespace = name, namespace
        return identity

    def ros_argument_rules(self, node: NodeRecord) -> tuple[list[RuleLike], str | None]:
        """Return the ``-r``/``--remap`` rules of a node's command line (they come first).

        rcl reads every ``--ros-args`` section of the command line, in order: those inside
        the node's ``arguments`` (up to ``--``), then its ``ros_arguments`` (launch_ros
        puts ``--ros-args`` before them). The second item says why the rules are not all
        known (a word not known before launch where a rule could be), ``None`` when they are.
        """
        launch = self.graph.launch_of(node)
        if launch is None or not (launch.arguments or launch.ros_arguments):
            return [], None
        where = f"{display_path(launch.origin.span.file)}:{launch.origin.span.line}"
        rules: list[RuleLike] = []
        for words, inside in ((self.words(launch.arguments), False),
                              (self.words(launch.ros_arguments), True)):
            found, unknown = _remap_rules(words, inside, where)
            rules.extend(found)
            if unknown is not None:  # the rules after it come after an unknown one
                return rules, unknown
        return rules, None

    def words(self, arguments: tuple[Sub, ...]) -> list[str | Sub]:
        """Return command-line words, split as launch splits them (a ``Sub`` when unknown)."""
        words: list[str | Sub] = []
        for argument in arguments:
            text = self.text(argument)
            if text is None:
                words.append(argument)
                continue
            try:
                words.extend(shlex.split(text))
            except ValueError:
                words.append(text)
        return words

    def remap_rules(self, node: NodeRecord) -> list[RuleLike]:
        """Return the rules of a node's launch remappings that this view applies."""
        return [self.rule(remap.src, remap.dst, remap.origin) for remap in node.remappings
                if not (remap.scope and not self.symbolic
                        and self.graph.runs(remap.origin) is False)]

    def rule(self, src: Sub, dst: Sub, origin: Origin) -> RuleLike:
        """Return one remap rule, or an unknown one saying which side is not known."""
        where = f"{display_path(origin.span.file)}:{origin.span.line}"
        source, target = self.text(src), self.text(dst)
        if source is not None and target is not None:
            return parse_rule(source, target, where)
        reason = (f"{self.describe(src)}:={self.describe(dst)} at {where}")
        if source is None:
            return UnknownRule(reason)
        known = parse_rule(source, "", where)
        return UnknownRule(reason, known.node, known.src)

    def endpoint(self, node: NodeRecord, endpoint: Endpoint,
                 identity: _Identity) -> ComposedEndpoint:
        """Return one endpoint with its fully qualified name, or the reason it is unknown."""
        written, value_from, reason = self.written_name(node, endpoint)
        if written is None:
            return ComposedEndpoint(node, endpoint, None, reason, value_from)
        if identity.namespace is None:
            absolute = expand(written, "/", None) if written.startswith("/") else None
            if absolute is None or absolute.name is None or identity.rules:
                return ComposedEndpoint(node, endpoint, None, identity.namespace_reason,
                                        value_from)
            return ComposedEndpoint(node, endpoint, absolute.name, None, value_from)
        resolution: Resolution = resolve(written, identity.namespace, identity.name,
                                         identity.rules,
                                         service=endpoint.kind in SERVICE_KINDS)
        reason = resolution.reason
        if resolution.name is None and identity.name is None and identity.name_reason:
            reason = f"{reason} ({identity.name_reason})"
        return ComposedEndpoint(node, endpoint, resolution.name, reason, value_from,
                                resolution.remapped_by)

    def written_name(self, node: NodeRecord, endpoint: Endpoint,
                     ) -> tuple[str | None, str | None, str | None]:
        """Return ``(name, value_from, reason)``: the name the node's code passes to rcl.

        A name read from a parameter is the value the launch gives that parameter on this
        node, else the default the sources declare.
        """
        parameter = endpoint.name_parameter
        if parameter is None:
            if endpoint.name is None:
                return None, None, endpoint.unresolved_reason or "the name is not known"
            return endpoint.name, None, None
        unknown = self.unknown_parameter(node, parameter)
        if unknown is not None:
            return None, None, unknown
        effective = effective_parameters(self.graph, node)
        winner = effective.winner(parameter)
        if winner is not None:
            where = f"{display_path(winner.span.file)}:{winner.span.line}"
            if winner.value is None:
                return None, "launch", (f"parameter {parameter} is set at {where} to a value "
                                        "not known before launch")
            if not isinstance(winner.value, str):
                return None, "launch", (f"parameter {parameter} is set at {where} to a "
                                        f"{winner.kind}, not a name")
            return winner.value, "launch", None
        if not effective.complete:
            return None, None, (f"parameter {parameter} may be set by a parameter source of "
                                "this node that could not be read")
        if endpoint.name is None:
            return None, "default", (endpoint.unresolved_reason or f"parameter {parameter} "
                                     "has no default in the sources and the launch does "
                                     "not set it")
        return endpoint.name, "default", None

    def unknown_parameter(self, node: NodeRecord, parameter: str) -> str | None:
        """Return why this view cannot tell what a node's parameter is, or ``None``.

        Parameter files are keyed by node name: when the launch does not give the name, a
        file may hold a block for the name the code picks. In the symbolic view, a value
        (or file) that depends on launch arguments is unknown.
        """
        files = [p for p in node.parameters if p.file is not None]
        if files and self.graph.base(node.fqn) is None:
            return (f"parameter {parameter} may be set by a parameter file under the node's "
                    "name, which the launch does not give")
        if not self.symbolic:
            return None
        for param in node.parameters:
            if param.file is not None and _has_inputs(param.file):
                return (f"parameter {parameter} may be set by a parameter file chosen by "
                        f"launch arguments: {self.describe(param.file)}")
            if param.name is not None and self.text(param.name) in (parameter, None) and (
                    isinstance(param.value, Sub) and _has_inputs(param.value)):
                return (f"parameter {parameter} is set from launch arguments: "
                        f"{self.describe(param.value)}")
        return None


def compose(graph: LaunchGraph, source: InterfaceSource, *,
            symbolic: bool = False) -> list[NodeEndpoints]:
    """Return every node of the view with its fully qualified endpoints."""
    return Composer(graph, source, symbolic).compose()


def named_record(graph: LaunchGraph, composed: NodeEndpoints) -> NodeRecord:
    """Return a node's record named as its code names it, when the launch gives no name.

    Parameter file blocks keyed by that name are the node's own (``ros2_control_node`` is
    ``controller_manager``; a node's constructor gives its default name). The record is
    kept with the graph, whose parameter cache knows records by identity.
    """
    if composed.fqn is None or graph.base(composed.node.fqn) is not None:
        return composed.node
    kept = graph.derived.setdefault("named_records", {})
    record = kept.get(id(composed.node))
    if not isinstance(record, NodeRecord):
        record = kept[id(composed.node)] = replace(composed.node, fqn=Text(composed.fqn))
    return record


@dataclass(frozen=True, slots=True)
class CodeName:
    """The name a node runs under because its code gives it and the launch leaves it so.

    ``at`` is where the code gives it (``None`` when not recorded: a model extracted
    before ``node_name_at`` was); ``origin`` says what it was read from, for messages.
    """

    name: str
    interface: NodeInterface
    at: Span | None
    origin: str


# Remap sources that rename a node or move it to another namespace
RENAMING = frozenset({"__node", "__name", "__ns"})


def code_name(graph: LaunchGraph, source: InterfaceSource, node: NodeRecord) -> CodeName | None:
    """Return the name a node's code gives it, when that is the name the node runs under.

    Only a fact: the launch gives no name, the package and executable (or plugin) do not
    depend on launch arguments, the code gives one literal name (``NodeInterface.node_name``),
    and no remap rule of the node (its command line's ``-r``, ``remappings``, a
    ``SetRemap``) renames it or moves it, nor may (a rule not known before launch).
    """
    if node.name is not None:
        return None
    composer = Composer(graph, source, symbolic=True)  # what depends on arguments: unknown
    package, executable = composer.text(node.package), composer.text(node.executable)
    if package is None or executable is None:
        return None
    interface, _ = source.interface(package, executable, node.composable)
    if interface is None or not interface.node_name:
        return None
    rules, unknown = composer.ros_argument_rules(node)
    if unknown is not None:
        return None
    for rule in (*rules, *composer.remap_rules(node)):
        if rule.src is None or rule.src in RENAMING:  # an unknown source may be __node
            return None
    origin = f"the sources of {package}" if interface.model is None else (
        f"the model of {package} shipped with launchverify, extracted from "
        f"{interface.model}")
    return CodeName(interface.node_name, interface, interface.node_name_at, origin)


def _has_inputs(sub: Sub) -> bool:
    """Return whether a value depends on launch arguments or the environment."""
    return any(isinstance(part, (Arg, EnvInput, Select)) for part in walk(sub))


# ROS arguments that take a value (the value is no flag: ``--log-level -r`` is no rule)
_VALUED_FLAGS = frozenset({"-r", "--remap", "-p", "--param", "--params-file", "-e", "--enclave",
                           "--log-level", "--log-config-file", "--log-file-name"})


def _remap_rules(words: list[str | Sub], inside: bool,
                 where: str) -> tuple[list[RuleLike], str | None]:
    """Return the remap rules of ROS arguments among command-line words, and why not all.

    ``inside``: the words start inside a ``--ros-args`` section. Outside one, only
    ``--ros-args`` matters; ``--`` ends a section.
    """
    rules: list[RuleLike] = []
    index = 0
    while index < len(words):
        word = words[index]
        index += 1
        if not isinstance(word, str):
            if inside:  # it could be -r and its rule: not known
                return rules, f"a ROS argument not known before launch at {where}"
            continue
        if not inside:
            inside = word == "--ros-args"
        elif word == "--":
            inside = False
        elif word in _VALUED_FLAGS:
            value = words[index] if index < len(words) else ""
            index += 1
            if word not in ("-r", "--remap"):
                continue
            if not isinstance(value, str):
                return rules, f"a remap rule not known before launch at {where}"
            if ":=" in value:
                src, _, dst = value.partition(":=")
                rules.append(parse_rule(src, dst, where))
    return rules, None
