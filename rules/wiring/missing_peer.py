"""LV602 missing-peer."""

from __future__ import annotations

import dataclasses
from collections.abc import Hashable, Iterator
from typing import TYPE_CHECKING

from launchverify.dds.bridges import crossings, feeding
from launchverify.dds.discovery import CALLER, discovery_of
from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, PollingRule, Related, RuleContext, Severity
from launchverify.rules.wiring.unused_remap import BUILT_IN_NAMES, BUILT_IN_PRIVATE
from launchverify.suggest import edit_distance, typos

if TYPE_CHECKING:
    from launchverify.topology.compose import ComposedEndpoint, NodeEndpoints
    from launchverify.topology.wiring import WiringView

WRITE_VERBS = {"topics": "publishes", "services": "serves", "actions": "serves"}
MOST_CANDIDATES = 2  # close names shown in one message


class MissingPeer(PollingRule):
    """A subscription or client that nothing in the launch serves, next to a close name that is.

    ## What it does
    Composes the launch's nodes with their interfaces, read from the workspace's sources
    (as `launchverify graph` shows them), under the arguments as given, and looks at each
    subscription, service client and action client of a node that runs: when no node of
    the launch publishes (or serves) its fully qualified name, but one publishes a *close*
    name, it reports both ends and the likely cause:

    - the same name in another namespace: a namespace pushed around one side only, or
      two different namespaces;
    - a private name (`~/input`) that resolves under the node's own name, or a relative
      name that a namespace moved away from its peer's absolute one (and the reverse);
    - a remap rule that sends the name elsewhere;
    - a name one or two edits away (a typo); names that differ only in their numbers
      (`robot1`/`robot2`, `camera_1`/`camera_2`) are deliberate and never matched, nor
      are peers whose message type is known to differ.

    A name nothing in the launch serves, with nothing close served either, is most
    likely fed from outside the launch (drivers, other machines, a bag): it is an info,
    only when every interface of the launch is known completely, and nothing for names
    matching the `external-names` globs of the configuration and for the names every
    node has (`/rosout`, `/parameter_events`, `/clock`, `/tf`, `/tf_static`, the
    parameter and lifecycle services).

    The rule stays quiet when anything in the launch could serve the name without the
    sources saying so: a node whose interface is not known (a package without sources in
    the workspace), a plain process (`ros2 bag play`, a simulator), or an endpoint whose
    name is only known at run time. It judges a launch file only where it is the whole
    launch: as an entry point, complete as given, or through the files that include it.

    Ends in different DDS domains never meet (`ROS_DOMAIN_ID` set per group or per
    node), nor does a process whose discovery is off (`ROS_AUTOMATIC_DISCOVERY_RANGE=OFF`)
    meet any other: a subscription whose every publisher is kept apart so is reported
    too, naming both domains, unless a `domain_bridge` forwards the topic between them
    (its YAML configuration: `from_domain`, `to_domain`, `topics`, a `remap` naming what
    the subscriber hears); a bridge whose configuration cannot be read may forward
    anything. A domain the launch leaves to its caller may be any: no finding rests on it.

    ## Why it matters
    Nothing fails: the node starts, waits for data that never comes, and `ros2 topic
    list` shows both names. This is the "why does my node receive nothing" bug, usually
    found on the robot.

    ## Example
    ```xml
    <group>
      <push_ros_namespace namespace="robot1"/>
      <node pkg="my_nav" exec="scan_filter"/>   <!-- subscribes to scan: /robot1/scan -->
    </group>
    <node pkg="my_drivers" exec="lidar"/>       <!-- publishes scan: /scan -->
    ```

    ## Fix
    Put both ends in the same namespace (push it around the driver too), or remap the
    subscription to the name the publisher uses (`<remap from="scan" to="/scan"/>`).
    Names that really come from outside the launch go in `external-names` in
    `launchverify.toml` (or `[tool.launchverify]`).
    """

    code = "LV602"
    slug = "missing-peer"
    severity = Severity.WARNING
    message = "{node} {verb} {name}, which nothing in this launch {writes}{hint}"

    def answers(self, graph: LaunchGraph, ctx: RuleContext
                ) -> Iterator[tuple[Hashable, Finding | None]]:
        if graph.included_elsewhere or graph.stopped_early or not graph.complete_as_given():
            return  # the whole launch is not here: another evaluation judges
        from launchverify.topology.wiring import globs_option, reads_sources, workspace_view

        if not reads_sources(graph, ctx):
            return
        view = workspace_view(graph, ctx)
        external = globs_option(ctx, "external-names")
        complete = not view.unknown_nodes and not view.processes and all(
            not node.interface.problems for node in view.nodes if node.interface is not None)
        for composed in view.nodes:
            if composed.interface is None or graph.runs(composed.node.origin) is not True:
                continue
            for end in composed.endpoints:
                question = self.question(end)
                if question is not None:
                    yield question, self.judge(view, composed, end, external, complete)

    @staticmethod
    def question(end: ComposedEndpoint) -> Hashable | None:
        """Return what is asked of a reading endpoint, in words no context changes."""
        from launchverify.topology.wiring import READERS

        if end.endpoint.kind not in READERS or end.name is None:
            return None
        endpoint = end.endpoint
        return (end.node.origin.span, endpoint.span, endpoint.kind, endpoint.name,
                endpoint.name_parameter, endpoint.type)

    def judge(self, view: WiringView, composed: NodeEndpoints, end: ComposedEndpoint,
              external: tuple[str, ...], complete: bool) -> Finding | None:
        """Return the finding for one reading endpoint, ``None`` when all is well."""
        from launchverify.topology.connections import ROLES
        from launchverify.topology.wiring import VERBS, describe_node, name_matches

        assert end.name is not None
        section = ROLES[end.endpoint.kind][0]
        name = end.name
        if built_in(name) or name_matches(name, external) or view.anything_may_write(section):
            return None
        writers = view.writers(section, name)
        if writers:
            return self.across_domains(view, composed, end, section, writers)
        if bridged_in(view, composed, name):
            return None
        close = close_writers(view, composed, end, section)
        who = describe_node(view, composed.node)
        related: tuple[Related, ...] = (
            Related(end.endpoint.span, f"{VERBS[end.endpoint.kind]} {name} here"),)
        if close:
            parts = [f"{describe_node(view, w.node)} {WRITE_VERBS[section]} {w.name} "
                     f"({cause})" for w, cause in close[:MOST_CANDIDATES]]
            related += tuple(Related(w.node.origin.span,
                                     f"{describe_node(view, w.node)} is launched here")
                             for w, _ in close[:MOST_CANDIDATES])
            return self.finding(composed.node.origin, related=related, node=who,
                                verb=VERBS[end.endpoint.kind], name=name,
                                writes=WRITE_VERBS[section], hint="; " + "; ".join(parts))
        if not complete:
            return None
        finding = self.finding(
            composed.node.origin, related=related, node=who, verb=VERBS[end.endpoint.kind],
            name=name, writes=WRITE_VERBS[section],
            hint=", nor anything close: fed from outside the launch? (then list it in "
                 "external-names)")
        return dataclasses.replace(finding, severity=Severity.INFO)


    def across_domains(self, view: WiringView, composed: NodeEndpoints, end: ComposedEndpoint,
                       section: str, writers: list[ComposedEndpoint]) -> Finding | None:
        """Return the finding when DDS keeps every writer of the name from the node.

        Different domains, or a discovery range ``OFF``, on facts only. Nothing crosses
        domains but a bridge: one whose configuration forwards the topic from a writer's
        domain into the node's serves it, and a bridge whose configuration is not known
        may serve anything.
        """
        from launchverify.topology.wiring import VERBS, describe_node

        graph = view.graph
        mine = discovery_of(graph, composed.node)
        theirs = [discovery_of(graph, w.node) for w in writers]
        if any(mine.meets(other) is not False for other in theirs):
            return None
        bridges = crossings(graph)
        if bridges is None or any(
                c.enters(mine.domain) and (c.reads != end.name  # fed from another name
                                           or any(c.leaves(other.domain) for other in theirs))
                for c in feeding(bridges, end.name or "")):
            return None
        writer = writers[0]
        peer = describe_node(view, writer.node)
        apart = mine.why_apart(theirs[0])
        where = (f" in its DDS domain {mine.domain}: {peer} {WRITE_VERBS[section]} it in "
                 f"domain {theirs[0].domain}, and no bridge carries it"
                 if apart.startswith("domain") else
                 f": {peer} {WRITE_VERBS[section]} it, but {apart}")
        return self.finding(
            composed.node.origin, node=describe_node(view, composed.node),
            verb=VERBS[end.endpoint.kind], name=end.name, writes=WRITE_VERBS[section],
            hint=where,
            related=(Related(end.endpoint.span, f"{VERBS[end.endpoint.kind]} "
                             f"{end.name} here"),
                     Related(writer.node.origin.span, f"{peer} is launched here")))


def bridged_in(view: WiringView, composed: NodeEndpoints, name: str) -> bool:
    """Return whether a bridge publishes the name into a domain that may be the node's."""
    bridges = crossings(view.graph)
    if not bridges:
        return False
    mine = discovery_of(view.graph, composed.node).domain
    return any(mine in (None, CALLER) or c.enters(mine) for c in feeding(bridges, name))


def built_in(name: str) -> bool:
    """Return whether a name is one every node has (or every tf user listens to)."""
    last = name.rpartition("/")[2]
    return last in BUILT_IN_NAMES or last in BUILT_IN_PRIVATE


def close_writers(view: WiringView, composed: NodeEndpoints, end: ComposedEndpoint,
                  section: str) -> list[tuple[ComposedEndpoint, str]]:
    """Return the writers of names close to the endpoint's, with the likely cause.

    Only writers of other nodes that run under the arguments as given, whose type (when
    both are known) is the endpoint's; names that differ only in numbers are not close.
    """
    from launchverify.topology.wiring import WRITERS, numbered_siblings

    assert end.name is not None
    name, graph = end.name, view.graph
    writers = {
        written: [w for w in connection.ends.get(WRITERS[section], [])
                  if w.node is not composed.node and graph.runs(w.node.origin) is True
                  and compatible(end, w)]
        for written, connection in view.by_name[section].items()
        if written != name and not numbered_siblings(written, name)}
    writers = {n: ends for n, ends in writers.items() if ends}
    nodes = {id(n.node): n for n in view.nodes}
    found: list[tuple[ComposedEndpoint, str]] = []
    mine = tails(name, composed)
    for written, ends in sorted(writers.items()):
        for writer in ends:
            if mine & tails(written, nodes[id(writer.node)]):
                found.append((writer, moved_cause(view, composed, end,
                                                  nodes[id(writer.node)], writer)))
                break
    if found:
        return found
    for written in typos(name, frozenset(writers)):
        distance = edit_distance(name, written)
        found.append((writers[written][0], f"{distance} edit{'s' * (distance > 1)} "
                      f"from {name}: a typo?"))
    return found


def compatible(first: ComposedEndpoint, second: ComposedEndpoint) -> bool:
    """Return whether two ends may carry the same type (unknown types may)."""
    one, other = first.endpoint.type, second.endpoint.type
    return one is None or other is None or one == other


def tails(name: str, composed: NodeEndpoints) -> set[str]:
    """Return the ways a name can be written relative to its node: ``scan``, ``ns/scan``.

    The name without its node's namespace, or without the node's own name (a private
    name), and the name itself without the leading slash.

    Examples:
        >>> from types import SimpleNamespace
        >>> sorted(tails("/robot1/scan", SimpleNamespace(fqn="/robot1/driver")))
        ['robot1/scan', 'scan']
        >>> sorted(tails("/robot1/nav/in", SimpleNamespace(fqn="/robot1/nav")))
        ['in', 'nav/in', 'robot1/nav/in']
    """
    from launchverify.topology.wiring import namespace_of

    out = {name.lstrip("/")}
    for base in (namespace_of(composed), composed.fqn):
        if base is not None and base != "/" and name.startswith(base + "/"):
            out.add(name[len(base) + 1:])
    return out


def moved_cause(view: WiringView, reader: NodeEndpoints, end: ComposedEndpoint,
                writer_node: NodeEndpoints, writer: ComposedEndpoint) -> str:
    """Return, in words, why the same name ends up in two places."""
    from launchverify.topology.wiring import describe_node, namespace_of

    read, _, _ = view.composer.written_name(reader.node, end.endpoint)
    wrote, _, _ = view.composer.written_name(writer_node.node, writer.endpoint)
    mine, theirs = namespace_of(reader) or "?", namespace_of(writer_node) or "?"
    who, peer = describe_node(view, reader.node), describe_node(view, writer_node.node)
    if read is not None and read.startswith("~") and end.remapped_by is None:
        return f"{who}'s name '{read}' is private: it resolves under the node's own name"
    if wrote is not None and wrote.startswith("~") and writer.remapped_by is None:
        return f"{peer}'s name '{wrote}' is private: it resolves under that node's own name"
    assert end.name is not None and writer.name is not None
    if mine != theirs and under(end.name, mine) and under(writer.name, theirs):
        if theirs == "/" or mine == "/":
            pushed, around = (mine, who) if theirs == "/" else (theirs, peer)
            return f"namespace {pushed} is pushed around {around} only"
        return f"{who} is in namespace {mine}, {peer} in {theirs}"
    if read is not None and wrote is not None:
        if wrote.startswith("/") and not read.startswith("/") and mine != "/":
            return (f"{peer} uses the absolute name '{wrote}', {who} the relative "
                    f"'{read}' in namespace {mine}")
        if read.startswith("/") and not wrote.startswith("/") and theirs != "/":
            return (f"{who} uses the absolute name '{read}', {peer} the relative "
                    f"'{wrote}' in namespace {theirs}")
    if end.remapped_by is not None:
        return f"a remap rule at {end.remapped_by} sends {who}'s name there"
    if writer.remapped_by is not None:
        return f"a remap rule at {writer.remapped_by} sends {peer}'s name there"
    return "the same name in another place"


def under(name: str, namespace: str) -> bool:
    """Return whether a name lies in a namespace (every name lies in ``/``)."""
    return namespace == "/" or name.startswith(namespace.rstrip("/") + "/")
