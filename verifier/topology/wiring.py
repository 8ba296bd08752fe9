"""The composed graph as the wiring rules ask about it: who is on each end of a name.

One view per launch graph, built once and shared by the rules of one check (kept in the
graph's ``derived`` data): the nodes that run under the arguments as given (or may: a
condition not known before launch) and the ros2_control controllers their spawners load,
each with its composed endpoints, grouped into
topics, services and actions (``connections``), and what the launch starts whose
endpoints are not known: nodes without an interface (a package without sources here),
plain processes (``ros2 bag play``, a simulator), and endpoints whose name is unknown.
Those may be on any name, so claims that a name has nobody on the other end are only
made when none of them could be.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from fnmatch import fnmatchcase
from typing import TYPE_CHECKING

from launchverify.dds.bridges import runs_bridge
from launchverify.dds.discovery import meet
from launchverify.events import meeting_origin
from launchverify.graph import LaunchGraph, LaunchRecord, NodeRecord
from launchverify.smt import Witness, reasoner_for
from launchverify.topology.model import EndpointKind

if TYPE_CHECKING:  # composition is imported only once a launched node has sources
    from launchverify.rule import RuleContext
    from launchverify.topology.compose import (
        ComposedEndpoint,
        Composer,
        InterfaceSource,
        NodeEndpoints,
    )
    from launchverify.topology.connections import Connection

READERS = (EndpointKind.SUBSCRIPTION, EndpointKind.CLIENT, EndpointKind.ACTION_CLIENT)
SECTIONS = ("topics", "services", "actions")
WRITERS = {"topics": "publishers", "services": "servers", "actions": "servers"}
VERBS = {  # kind -> what it does to a name, for messages
    EndpointKind.PUBLISHER: "publishes", EndpointKind.SUBSCRIPTION: "subscribes to",
    EndpointKind.SERVICE: "serves", EndpointKind.CLIENT: "calls",
    EndpointKind.ACTION_SERVER: "serves the action", EndpointKind.ACTION_CLIENT:
    "sends goals to the action",
}
# Executables of released packages known to create nothing on user names: a component
# container serves only its own ``~/_container/*`` services.
SILENT_EXECUTABLES = (("rclcpp_components", "component_container*"),)


@dataclass
class WiringView:
    """The composed endpoints of one graph's running nodes, and what is not known."""

    graph: LaunchGraph
    composer: Composer
    nodes: list[NodeEndpoints]
    by_name: dict[str, dict[str, Connection]]  # section -> fully qualified name -> it
    unknown_nodes: list[NodeEndpoints] = field(default_factory=list)
    processes: list[LaunchRecord] = field(default_factory=list)
    # (section, role) -> endpoints of that role whose name is not known
    unresolved: dict[tuple[str, str], list[ComposedEndpoint]] = field(default_factory=dict)

    def connection(self, section: str, name: str) -> Connection | None:
        """Return the topic, service or action of that name, if any endpoint is on it."""
        return self.by_name[section].get(name)

    def writers(self, section: str, name: str) -> list[ComposedEndpoint]:
        """Return the publishers (or servers) on a name."""
        found = self.connection(section, name)
        return [] if found is None else found.ends.get(WRITERS[section], [])

    def anything_may_write(self, section: str) -> bool:
        """Return whether something may write any name of a section unbeknown to us.

        A node without a known interface, a plain process, or an endpoint of the writing
        role whose name is not known.
        """
        return bool(self.unknown_nodes or self.processes
                    or self.unresolved.get((section, WRITERS[section])))


def reads_sources(graph: LaunchGraph, ctx: RuleContext) -> bool:
    """Return whether a node that may run belongs to a package with sources here.

    Without one there is nothing to compose, and the check reads no sources at all.
    """
    if ctx.packages is None:
        return False
    for node in graph.nodes:
        package = graph.base(node.package)
        if package is None or graph.runs(node.origin) is False:
            continue
        found = ctx.packages.find(package)
        if found is not None and found.source is not None:
            return True
    return False


def knows_code(graph: LaunchGraph, ctx: RuleContext) -> bool:
    """Return whether a node that may run has sources here or a shipped model.

    What the node contract rules need: a model tells the parameters a released
    package's nodes declare, without reading any source.
    """
    if reads_sources(graph, ctx):
        return True
    from launchverify.topology.shipped import modelled_packages

    modelled = modelled_packages()
    return any(graph.base(node.package) in modelled for node in graph.nodes
               if graph.runs(node.origin) is not False)


def has_code(ctx: RuleContext, package: str) -> bool:
    """Return whether a package's interfaces can be known: sources here, or a shipped model.

    Asks the package index and the list of models only; reads no source.
    """
    found = ctx.packages.find(package) if ctx.packages is not None else None
    if found is not None and found.source is not None:
        return True
    from launchverify.topology.shipped import modelled_packages

    return package in modelled_packages()


def interfaces_of(ctx: RuleContext) -> InterfaceSource:
    """Return the check's interface reader, shared by the rules (each package read once).

    The workspace's sources (then shipped models) when a package index is known, else
    shipped models only.
    """
    from launchverify.topology.compose import WorkspaceInterfaces
    from launchverify.workspace.packages import PackageIndex

    shared = ctx.memo_for("topology")
    key = "interfaces" if ctx.packages is not None else "models"
    reader = shared.get(key)
    if not isinstance(reader, WorkspaceInterfaces):
        reader = shared[key] = WorkspaceInterfaces(
            ctx.packages if ctx.packages is not None else PackageIndex())
    return reader


def workspace_view(graph: LaunchGraph, ctx: RuleContext) -> WiringView:
    """Return the graph's view with interfaces read from the workspace's sources.

    One reader per check, shared by the rules (each package's sources are read once).
    """
    assert ctx.packages is not None
    return view_of(graph, interfaces_of(ctx))


def any_view(graph: LaunchGraph, ctx: RuleContext) -> WiringView:
    """Return the graph's view for rules that need no sources (shipped models suffice).

    The workspace's view when a package index is known, else one of shipped models only.
    """
    return view_of(graph, interfaces_of(ctx))


def globs_option(ctx: RuleContext, key: str, default: tuple[str, ...] = ()) -> tuple[str, ...]:
    """Return a configured list of name globs (``default`` when the configuration is silent)."""
    value = ctx.options.get(key)
    if isinstance(value, (list, tuple)):
        return tuple(str(item) for item in value)
    return default


def view_of(graph: LaunchGraph, source: InterfaceSource) -> WiringView:
    """Return the graph's wiring view (composed once per graph, then kept)."""
    kept = graph.derived.setdefault("wiring", {})
    found = kept.get("view")
    if isinstance(found, WiringView):
        return found
    from launchverify.topology.compose import Composer
    from launchverify.topology.connections import ROLES, connections

    composer = Composer(graph, source, symbolic=False)
    nodes = composer.compose()  # the symbolic=False view: the nodes that run or may
    grouped = connections(nodes)
    view = WiringView(graph, composer, nodes,
                      {section: {c.name: c for c in grouped[section]} for section in SECTIONS})
    for composed in nodes:
        if composed.interface is None:
            if not silent(composed) and not runs_bridge(graph, composed.node.origin):
                view.unknown_nodes.append(composed)
            continue
        for end in composed.endpoints:
            if end.name is None:
                view.unresolved.setdefault(ROLES[end.endpoint.kind], []).append(end)
    view.processes = [p for p in graph.processes if graph.runs(p.origin) is not False
                      and not runs_bridge(graph, p.origin)]
    kept["view"] = view
    return view


def silent(composed: NodeEndpoints) -> bool:
    """Return whether a node without interface is known to create no user names."""
    return any(composed.package == package and composed.executable is not None
               and fnmatchcase(composed.executable, executable)
               for package, executable in SILENT_EXECUTABLES)


def describe_node(view: WiringView, node: NodeRecord) -> str:
    """Return a node's fully qualified name, else ``package/executable``."""
    for composed in view.nodes:
        if composed.node is node and composed.fqn is not None:
            return composed.fqn
    return view.graph.display(node.fqn) or node.executable_label()


def namespace_of(composed: NodeEndpoints) -> str | None:
    """Return the namespace part of a node's fully qualified name."""
    if composed.fqn is None:
        return None
    return composed.fqn.rpartition("/")[0] or "/"


def together(graph: LaunchGraph, first: NodeRecord, second: NodeRecord) -> Witness | None:
    """Return under which arguments two nodes run at the same time, ``None``: never.

    As LV101 decides it: the event structure may keep them apart (one starts once the
    other has ended), and their conditions may exclude each other; an empty witness
    means under the arguments as given. Nodes DDS may keep apart (``dds.discovery.meet``)
    never meet: an error rests only on nodes that surely see each other.
    """
    first_origin = meeting_origin(graph, first, second)
    if first_origin is None:
        return None
    if meet(graph, first, second) is not True:
        return None  # DDS keeps them apart, or may (a domain left to the caller)
    if graph.runs(first_origin) is True and graph.runs(second.origin) is True:
        return Witness()
    return reasoner_for(graph).together(first_origin.path, second.origin.path)


def name_matches(name: str, patterns: tuple[str, ...] | list[str]) -> bool:
    """Return whether a fully qualified name matches one of the configured globs.

    A pattern that starts with ``/`` matches the whole name; one that does not matches at
    any depth (``cmd_vel`` matches ``/cmd_vel`` and ``/robot1/cmd_vel``).

    Examples:
        >>> name_matches("/robot1/cmd_vel", ["*cmd_vel"])
        True
        >>> name_matches("/cmd_vel_nav", ["*cmd_vel"])
        False
        >>> name_matches("/robot1/scan", ["/scan"])
        False
    """
    return any(fnmatchcase(name, p if p.startswith("/") else "*/" + p) for p in patterns)


_DIGITS = re.compile(r"\d+")


def numbered_siblings(first: str, second: str) -> bool:
    """Return whether two names differ only in their numbers (``robot1`` / ``robot2``).

    Such names are deliberate (one per robot, per camera), never a typo of each other.

    Examples:
        >>> numbered_siblings("/robot1/odom", "/robot2/odom")
        True
        >>> numbered_siblings("/scan", "/scna")
        False
    """
    return _DIGITS.sub("#", first) == _DIGITS.sub("#", second)


def from_sources(view: WiringView, end: ComposedEndpoint) -> bool:
    """Return whether an end was read from the sources of the workspace (not a model)."""
    for composed in view.nodes:
        if composed.node is end.node:
            interface = composed.interface
            return interface is not None and end.endpoint.span.file in interface.sources
    return False
