"""LV603 type-mismatch."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator
from typing import TYPE_CHECKING

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity

if TYPE_CHECKING:
    from launchverify.topology.compose import ComposedEndpoint
    from launchverify.topology.connections import Connection
    from launchverify.topology.wiring import WiringView


class TypeMismatch(Rule):
    """Two ends of one topic, service or action that use different message types.

    ## What it does
    Composes the launch's nodes with their interfaces, read from the workspace's sources
    (as `launchverify graph` shows them), and compares the types on each fully qualified
    name: a subscriber (or client) whose type differs from a publisher's (or server's),
    or a publisher whose type differs from an earlier publisher's. Only ends whose types
    the sources give are compared, and only nodes that can run at the same time (as
    LV101 decides it: conditions that exclude each other, a node started once the other
    has exited); the finding names the argument values under which they meet when the
    arguments as given do not start both.

    A `domain_bridge` subscribes and publishes with the type its configuration names: a
    publisher in the bridge's source domain, or a subscriber in its target domain, of
    another type is reported at the configuration's entry.

    It is an error when both ends are read from the workspace's sources, a warning when
    an interface comes from elsewhere (a model of a released package).

    ## Why it matters
    ROS 2 does not connect endpoints of different types: the subscriber receives
    nothing, the client waits forever, and `ros2 topic info` lists two types for one
    name. Nothing in the logs says so unless the middleware warns about it.

    ## Example
    ```xml
    <!-- publishes cmd_vel as geometry_msgs/msg/Twist -->
    <node pkg="my_robot" exec="teleop"/>
    <!-- subscribes to cmd_vel as geometry_msgs/msg/TwistStamped (Jazzy's controllers) -->
    <node pkg="my_robot" exec="base_controller"/>
    ```

    ## Fix
    Make both ends use the same type, or give them different names and convert in
    between (a relay node).
    """

    code = "LV603"
    slug = "type-mismatch"
    severity = Severity.ERROR
    every_context = True  # an includer's namespaces may set the two apart
    message = "{node} {verb} {name} as {mine}, but {peer} {peer_verb} it as {theirs}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        from launchverify.topology.wiring import reads_sources, workspace_view

        if not reads_sources(graph, ctx):
            return
        view = workspace_view(graph, ctx)
        for by_name in view.by_name.values():
            for connection in by_name.values():
                if len(connection.types()) > 1:
                    yield from self.connection(view, connection)
        yield from self.bridged(view)

    def bridged(self, view: WiringView) -> Iterator[Finding]:
        """Yield a finding for each end whose type differs from what a bridge forwards.

        A domain_bridge subscribes with the type its configuration names, in the source
        domain, and publishes with it in the target domain: a publisher there of another
        type feeds nothing across, a subscriber of another type hears nothing.
        """
        from launchverify.dds.bridges import crossings, message_type
        from launchverify.dds.discovery import discovery_of
        from launchverify.topology.wiring import VERBS, describe_node, from_sources

        for crossing in crossings(view.graph) or []:
            if crossing.type is None or crossing.span is None:
                continue
            forwarded = message_type(crossing.type)
            connections = view.by_name.get("topics", {})
            for name, there, role in ((crossing.reads, crossing.leaves, "publishers"),
                                      (crossing.writes, crossing.enters, "subscribers")):
                connection = connections.get(name)
                for end in connection.ends.get(role, []) if connection else []:
                    theirs = end.endpoint.type
                    if theirs is None or message_type(theirs) == forwarded or \
                            not there(discovery_of(view.graph, end.node).domain):
                        continue
                    peer = describe_node(view, end.node)
                    finding = self.finding(
                        crossing.span, node=f"a domain_bridge (domain {crossing.source} to "
                        f"{crossing.target})", verb="forwards", name=name, mine=forwarded,
                        peer=peer, peer_verb=VERBS[end.endpoint.kind], theirs=theirs,
                        related=(Related(end.endpoint.span, f"{peer}'s type is {theirs} here"),
                                 Related(end.node.origin.span, f"{peer} is launched here")))
                    yield finding if from_sources(view, end) else dataclasses.replace(
                        finding, severity=Severity.WARNING)

    def connection(self, view: WiringView, connection: Connection) -> Iterator[Finding]:
        """Yield a finding for each end whose type differs from a writer it meets."""
        from launchverify.topology.wiring import WRITERS, together

        writers = [e for e in connection.ends.get(WRITERS[connection.section], [])
                   if e.endpoint.type is not None]
        position = {id(w): index for index, w in enumerate(writers)}
        for end in connection.endpoints():
            if end.endpoint.type is None:
                continue
            earlier = writers[:position[id(end)]] if id(end) in position else writers
            for writer in earlier:
                if writer.endpoint.type == end.endpoint.type:
                    continue
                witness = together(view.graph, writer.node, end.node)
                if witness is not None:
                    yield self.mismatch(view, end, writer, witness.values)
                    break

    def mismatch(self, view: WiringView, end: ComposedEndpoint, writer: ComposedEndpoint,
                 witness: dict[str, str]) -> Finding:
        """Return the finding at ``end``'s node, naming the writer it disagrees with."""
        from launchverify.topology.wiring import VERBS, describe_node

        peer = describe_node(view, writer.node)
        finding = self.finding(
            end.node.origin,
            related=(Related(end.endpoint.span, f"the type is {end.endpoint.type} here"),
                     Related(writer.node.origin.span, f"{peer} is launched here"),
                     Related(writer.endpoint.span,
                             f"{peer}'s type is {writer.endpoint.type} here")),
            witness=witness or None, node=describe_node(view, end.node),
            verb=VERBS[end.endpoint.kind], name=end.name, mine=end.endpoint.type,
            peer=peer, peer_verb=VERBS[writer.endpoint.kind], theirs=writer.endpoint.type)
        from launchverify.topology.wiring import from_sources

        if not (from_sources(view, end) and from_sources(view, writer)):
            finding = dataclasses.replace(finding, severity=Severity.WARNING)
        return finding
