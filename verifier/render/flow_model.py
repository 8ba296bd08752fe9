"""What the report's computation graph shows: nodes, the topics between them, by namespace.

The nodes are the system picture's (``system_model``), so both agree on who runs; their
endpoints come from the workspace's sources, composed with the launch (``topology``, what
``launchverify graph`` prints as ``topics``/``services``/``actions``). Edges follow the
data: publisher -> topic -> subscriber, client -> service -> server (actions alike).

Reading sources is the heavy part, and optional: without the tree-sitter packages, or
when no launched node has sources in the workspace, nothing is composed and ``reason``
says why. ``/tf`` and ``/tf_static`` (each namespace's pair) become one element whose
edges the page hides until asked: nearly every node touches them.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field, replace

from launchverify.graph import LaunchGraph
from launchverify.render.system_model import SystemModel, SystemNode
from launchverify.topology.compose import Composer, InterfaceSource, NodeEndpoints
from launchverify.topology.connections import ROLES, SECTIONS, Connection, connections

TF_TOPICS = ("tf", "tf_static")
# role -> which side of the element its nodes sit on (sources feed it, sinks read it)
SOURCE_ROLES = ("publishers", "clients")
UNKNOWN_ROLE_LIMIT = 6  # unresolved endpoints listed in a node's tooltip


@dataclass
class FlowNode:
    """A launched node: its box, and what its tooltip says about its endpoints."""

    key: str
    index: int  # the node's row in the system's node table
    fqn: str
    namespace: str
    executable: str
    kind: str
    condition: str | None
    known: bool  # its interface was read from the sources
    note: str | None = None  # why it was not
    unresolved: list[str] = field(default_factory=list)  # endpoints whose name is unknown
    uses: dict[str, list[str]] = field(default_factory=dict)  # "section:role" -> names


@dataclass
class FlowTopic:
    """A topic, service or action (or a namespace's collapsed tf pair) and who uses it."""

    key: str
    section: str  # topics, services or actions
    names: list[str]
    namespace: str
    types: list[str]
    sources: list[str] = field(default_factory=list)  # keys of publishers / clients
    sinks: list[str] = field(default_factory=list)  # keys of subscribers / servers
    tf: bool = False
    ref: str | None = None  # the topic this repeats, in the box of a node using it
    maybe: list[str] = field(default_factory=list)  # nodes whose unnamed endpoint may be on it
    qos: dict[str, str] = field(default_factory=dict)  # node key -> its end's QoS, as read

    @property
    def topic(self) -> str:
        """Return the key of the topic itself (a repeat's original)."""
        return self.ref or self.key

    @property
    def label(self) -> str:
        """Return the shown name: the full name, or ``tf + tf_static`` for a tf pair."""
        if self.tf:
            return " + ".join(n.rsplit("/", 1)[-1] for n in self.names)
        return self.names[0]

    @property
    def missing(self) -> str | None:
        """Return the role nobody in this launch takes, when that deserves a mark.

        A topic read by nobody or written by nobody is marked; a service or action
        nobody calls is not (they are called from outside, ``ros2 service call``), one
        nobody serves is. A node whose endpoint of that role and type has a name not
        known before launch may be on it (``maybe``): then nothing is claimed.
        """
        if self.maybe:
            return None
        if self.section == "topics":
            if not self.sources:
                return "publisher"
            return "subscriber" if not self.sinks else None
        return "server" if not self.sinks else None


@dataclass(frozen=True)
class FlowEdge:
    """One arrow: from a node into a topic, or from a topic into a node."""

    source: str
    target: str
    section: str
    tf: bool = False


@dataclass
class FlowGraph:
    """The computation graph of one root launch file, ready to lay out."""

    nodes: dict[str, FlowNode]
    topics: dict[str, FlowTopic]
    edges: list[FlowEdge]
    containers: int = 0  # containers left out (their components are drawn)
    reason: str | None = None  # why nothing could be composed

    def namespace_of(self, key: str) -> str:
        """Return the namespace box an element goes in."""
        element = self.nodes.get(key) or self.topics[key]
        return element.namespace

    def namespaces(self) -> list[str]:
        """Return the namespaces that hold elements, in reading order (robot2 < robot10)."""
        found = {n.namespace for n in self.nodes.values()}
        found |= {t.namespace for t in self.topics.values()}
        return sorted(found, key=natural)

    def known(self) -> int:
        """Return how many nodes have an interface read from their sources."""
        return sum(1 for n in self.nodes.values() if n.known)


def natural(text: str) -> list[tuple[int, int | str]]:
    """Return a sort key that puts robot2 before robot10 (numbers and words never compared).

    The text itself comes last: ``robot01`` and ``robot1`` must not tie, or their order
    would be the order of a set, which changes between runs.
    """
    return [*((0, int(part)) if part.isdigit() else (1, part)
              for part in re.split(r"(\d+)", text)), (2, text)]


def parsers_missing() -> str | None:
    """Return why sources cannot be read here (tree-sitter absent), else ``None``."""
    try:
        import tree_sitter  # noqa: F401
        import tree_sitter_cpp  # noqa: F401
        import tree_sitter_python  # noqa: F401
    except ImportError as error:
        return (f"reading node sources needs the tree-sitter packages ({error.name} is "
                "missing: pip install tree-sitter tree-sitter-cpp tree-sitter-python)")
    return None


@dataclass
class Composition:
    """A root's nodes composed with their sources, or why they could not be."""

    nodes: list[NodeEndpoints]
    reason: str | None = None

    def names(self) -> dict[int, str]:
        """Return the names the sources give nodes, by the id of their launch record.

        A launch that does not name a node leaves it the name its code (or a shipped
        model) gives: the one the computation graph shows.
        """
        return {id(c.node): c.fqn for c in self.nodes if c.spawner is None and c.fqn}


def compose_view(graph: LaunchGraph, source: InterfaceSource) -> Composition:
    """Return the nodes of one root (under the given arguments) with their sources."""
    missing = parsers_missing()
    if missing is not None:
        return Composition([], missing)
    return Composition(Composer(graph, source, symbolic=False).compose())


def build_flow(model: SystemModel, graph: LaunchGraph, source: InterfaceSource,
               composition: Composition | None = None) -> FlowGraph:
    """Return the computation graph of one root: its nodes composed with their sources.

    ``composition``: the composed nodes when already at hand (the picture named its
    nodes from them).
    """
    if composition is None:
        composition = compose_view(graph, source)
    if composition.reason is not None:
        return FlowGraph({}, {}, [], reason=composition.reason)
    return assemble(model.nodes, composition.nodes)


def assemble(system: Sequence[SystemNode], composed: Sequence[NodeEndpoints]) -> FlowGraph:
    """Return the computation graph of nodes already composed (same order as ``system``).

    ``composed`` may hold more: the controllers a spawner loads come right after it
    (``topology.controllers``); their boxes link to the spawner's row.
    """
    hosts = {n.container for n in system if n.container}
    nodes: dict[str, FlowNode] = {}
    keys: dict[int, str] = {}  # id of the NodeRecord -> key
    containers = 0
    for entry, endpoints, extra in _pair(system, composed):
        if extra:
            node = _controller(entry, endpoints, extra)
            nodes[node.key] = node
            keys[id(endpoints.node)] = node.key
            continue
        if (entry.kind == "node_container" or entry.fqn in hosts) and not endpoints.endpoints:
            containers += 1  # a process for components: they are the graph's nodes
            continue
        node = _node(entry, endpoints)
        nodes[node.key] = node
        keys[id(endpoints.node)] = node.key
    if nodes and not any(n.known for n in nodes.values()):
        notes = sorted({n.note for n in nodes.values() if n.note})
        reason = ("no launched node has its sources in the workspace"
                  + (f" ({notes[0]})" if len(notes) == 1 else ""))
        return FlowGraph(nodes, {}, [], containers, reason)
    topics: dict[str, FlowTopic] = {}
    edges: list[FlowEdge] = []
    grouped = connections(c for c in composed if id(c.node) in keys)
    for section in SECTIONS:
        for connection in grouped[section]:
            _add(topics, edges, connection, keys, nodes)
    namespaces = {n.namespace for n in nodes.values()}
    unnamed = _unnamed([c for c in composed if id(c.node) in keys], keys, nodes)
    for topic in topics.values():
        topic.sources = sorted(set(topic.sources), key=natural)
        topic.sinks = sorted(set(topic.sinks), key=natural)
        topic.maybe = _maybe(topic, unnamed)
        topic.namespace = _home(topic, nodes, namespaces)
    edges = _local(edges, topics, nodes)
    unique = sorted(set(edges), key=lambda e: (natural(e.source), natural(e.target)))
    return FlowGraph(nodes, topics, unique, containers)


def _pair(system: Sequence[SystemNode], composed: Sequence[NodeEndpoints],
          ) -> list[tuple[SystemNode, NodeEndpoints, int]]:
    """Return each composed node with its row of the table, and its rank among extras.

    A launched node takes the next row; a node the launch does not start (a controller)
    shares the row of the one before it (its spawner) and counts from 1.
    """
    out: list[tuple[SystemNode, NodeEndpoints, int]] = []
    rows = iter(system)
    extra = 0
    for endpoints in composed:
        if endpoints.spawner is not None and out:
            extra += 1
            out.append((out[-1][0], endpoints, extra))
            continue
        row = next(rows, None)
        if row is None:
            raise ValueError("more composed nodes than nodes in the picture")
        extra = 0
        out.append((row, endpoints, 0))
    if next(rows, None) is not None:
        raise ValueError("fewer composed nodes than nodes in the picture")
    return out


def _controller(spawner: SystemNode, endpoints: NodeEndpoints, number: int) -> FlowNode:
    """Return a controller's box: a node of its manager's process, started by a spawner."""
    base = replace(spawner, fqn=endpoints.fqn or f"{spawner.fqn} (controller {number})",
                   executable=endpoints.executable or "?", kind="controller")
    node = _node(base, endpoints)
    node.key = f"n{spawner.index}c{number}"
    return node


def _node(entry: SystemNode, endpoints: NodeEndpoints) -> FlowNode:
    fqn = endpoints.fqn or entry.fqn
    namespace = entry.namespace
    if endpoints.fqn and endpoints.fqn.startswith("/"):
        namespace = endpoints.fqn.rsplit("/", 1)[0] or "/"
    node = FlowNode(f"n{entry.index}", entry.index, fqn, namespace, entry.executable,
                    entry.kind, entry.condition, endpoints.interface is not None,
                    endpoints.note)
    for composed in endpoints.endpoints:
        if composed.name is None:
            written = composed.endpoint.name or "?"
            if composed.endpoint.name_parameter:
                written += f" (parameter {composed.endpoint.name_parameter})"
            node.unresolved.append(f"{composed.endpoint.kind.value} {written}: "
                                   f"{composed.reason or 'not known before launch'}")
    return node


def _unnamed(composed: Iterable[NodeEndpoints], keys: dict[int, str],
             nodes: dict[str, FlowNode]) -> list[tuple[str, str, str | None, str]]:
    """Return the endpoints whose name is not known: section, role, type, node.

    The node is named as its box is (``<unnamed talker>`` when nothing knows its name).
    A controller whose interface is not known (its type is not) may be on any name
    (``*``): the picture never says "nobody publishes" on the strength of it.
    """
    found: list[tuple[str, str, str | None, str]] = []
    for node in composed:
        who = nodes[keys[id(node.node)]].fqn
        if node.spawner is not None and node.interface is None:
            found.append(("*", "*", None, who))
        found += [(*ROLES[end.endpoint.kind], end.endpoint.type, who)
                  for end in node.endpoints if end.name is None]
    return found


def _maybe(topic: FlowTopic, unnamed: list[tuple[str, str, str | None, str]]) -> list[str]:
    """Return the nodes that may take the role nobody takes on ``topic``, by their type.

    ``joint_state_broadcaster`` builds its topic's name at run time: ``/joint_states``
    that ``robot_state_publisher`` reads is not "published by nobody" then.
    """
    roles = SECTIONS[topic.section]
    lacking = [role for role in roles
               if not (topic.sources if role in SOURCE_ROLES else topic.sinks)]
    if not lacking:
        return []
    return sorted({node for section, role, kind, node in unnamed
                   if section in (topic.section, "*") and (role in lacking or role == "*")
                   and (kind is None or not topic.types or kind in topic.types)})


def _add(topics: dict[str, FlowTopic], edges: list[FlowEdge], connection: Connection,
         keys: dict[int, str], nodes: dict[str, FlowNode]) -> None:
    """Add one connection as an element (or into its namespace's tf pair) with its edges."""
    parent, _, last = connection.name.rpartition("/")
    tf = connection.section == "topics" and last in TF_TOPICS
    key = f"tf{parent or '/'}" if tf else f"t{len(topics)}"
    topic = topics.get(key)
    if topic is None:
        topic = FlowTopic(key, connection.section, [], "/", [], tf=tf)
        topics[key] = topic
    topic.names.append(connection.name)
    topic.types = sorted({*topic.types, *connection.types()})
    for role in SECTIONS[connection.section]:
        for end in connection.ends.get(role, []):
            node = keys[id(end.node)]
            nodes[node].uses.setdefault(f"{connection.section}:{role}", []).append(
                connection.name)
            if end.endpoint.profile is not None:
                topic.qos[node] = end.endpoint.profile.describe()
            if role in SOURCE_ROLES:
                topic.sources.append(node)
                edges.append(FlowEdge(node, key, connection.section, tf))
            else:
                topic.sinks.append(node)
                edges.append(FlowEdge(key, node, connection.section, tf))


def _home(topic: FlowTopic, nodes: dict[str, FlowNode], namespaces: set[str]) -> str:
    """Return the namespace box a topic goes in.

    By its name: the deepest namespace of launched nodes that holds it
    (``/robot1/amcl/particles`` goes with ``/robot1``'s nodes when none lives in
    ``/robot1/amcl``), else ``/``. A topic all of whose users share one other namespace
    goes in theirs instead (``/sensors/imu`` read and written only in ``/robot1``).
    """
    parent = topic.names[0].rsplit("/", 1)[0] or "/"
    while parent not in namespaces and parent != "/":
        parent = parent.rsplit("/", 1)[0] or "/"
    users = {nodes[k].namespace for k in (*topic.sources, *topic.sinks)}
    if len(users) == 1 and parent not in users:
        return users.pop()
    return parent


def _local(edges: list[FlowEdge], topics: dict[str, FlowTopic],
           nodes: dict[str, FlowNode]) -> list[FlowEdge]:
    """Return the edges with every arrow kept inside one namespace box.

    A node using a topic of another namespace gets a copy of it in its own box (``ref``
    names the original): long arrows across the picture are what makes a big graph
    unreadable, and the copy says where the topic lives.
    """
    out = []
    for edge in edges:
        node, key = (edge.source, edge.target) if edge.source in nodes else \
            (edge.target, edge.source)
        topic, here = topics[key], nodes[node].namespace
        if topic.namespace == here:
            out.append(edge)
            continue
        copy = f"{key}@{here}"
        if copy not in topics:
            topics[copy] = replace(topic, key=copy, namespace=here, ref=key)
        out.append(replace(edge, source=copy) if edge.source == key else
                   replace(edge, target=copy))
    return out

