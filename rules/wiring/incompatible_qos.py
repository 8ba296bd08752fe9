"""LV605 incompatible-qos."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator
from typing import TYPE_CHECKING

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity

if TYPE_CHECKING:
    from launchverify.parameters import Contribution
    from launchverify.topology.compose import ComposedEndpoint
    from launchverify.topology.qos import Qos
    from launchverify.topology.wiring import WiringView

class IncompatibleQos(Rule):
    """A publisher and a subscription of one topic whose QoS never match.

    ## What it does
    Reads the QoS each endpoint is created with from the workspace's sources: a named
    profile (`rclcpp::SensorDataQoS()`, `qos_profile_sensor_data`, nav2's
    `LatchedPublisherQoS`), a depth (the default profile: reliable, volatile) and the
    policies set on it (`.best_effort()`, `.transient_local()`, `QoSProfile(reliability=
    ...)`). An endpoint whose options carry `QosOverridingOptions` takes, as rclcpp and
    rclpy do, the `qos_overrides.<topic>.<publisher|subscription>[_<id>].<policy>`
    parameters its node receives (files, `/**` blocks, inline values), keyed by the topic's
    name after remapping, for the policies the options list and no others. On each
    topic it reports a subscription that a publisher it meets can never serve, by the
    rmw rules: a best-effort publisher and a reliable subscription, or a volatile
    publisher and a transient-local subscription. Only ends whose policies are settled
    are compared (a profile from a parameter or a function, an override not known before
    launch, stays unknown), and only nodes that can run at the same time. It is an error
    when both ends are read from the workspace's sources.

    ## Why it matters
    DDS never connects them: `ros2 topic list` shows the topic, `ros2 topic info -v`
    shows both ends, and nothing arrives. rclcpp logs an "incompatible QoS" warning once,
    if anyone reads it. A lidar driver publishing with sensor-data QoS (best effort) and a
    node subscribing with the default (reliable) is the classic case; a map or a robot
    description subscribed transient-local from a volatile publisher is the other.

    ## Example
    ```cpp
    // driver
    create_publisher<sensor_msgs::msg::LaserScan>("scan", rclcpp::SensorDataQoS());
    // consumer
    create_subscription<sensor_msgs::msg::LaserScan>("scan", 10, callback);  // reliable
    ```

    ## Fix
    Subscribe with the publisher's policy or a weaker one: `rclcpp::SensorDataQoS()` (or
    `.best_effort()`) for sensor streams, volatile durability unless the publisher is
    transient-local. A best-effort subscription takes both kinds of publisher. Where an
    end opts in to overrides, set its policy in the launch, under the remapped name:
    `qos_overrides./front/scan.publisher.reliability: reliable`.
    """

    code = "LV605"
    slug = "incompatible-qos"
    severity = Severity.ERROR
    every_context = True
    message = ("{reader} subscribes to {name} with {mine}, but {writer} publishes it with "
               "{theirs}: {why}, so it never receives from it")

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        from launchverify.topology.wiring import reads_sources, workspace_view

        if not reads_sources(graph, ctx):
            return
        view = workspace_view(graph, ctx)
        for connection in view.by_name["topics"].values():
            writers = connection.ends.get("publishers", [])
            readers = connection.ends.get("subscribers", [])
            if writers and readers:
                yield from self.topic(view, writers, readers)

    def topic(self, view: WiringView, writers: list[ComposedEndpoint],
              readers: list[ComposedEndpoint]) -> Iterator[Finding]:
        """Yield a finding for each reader that a writer it meets cannot serve."""
        from launchverify.topology.qos import clash, incompatible
        from launchverify.topology.wiring import describe_node, from_sources, together

        published = [(writer, *_effective(view, writer, "publisher")) for writer in writers]
        for reader in readers:
            mine, my_overrides = _effective(view, reader, "subscription")
            if mine is None:
                continue
            for writer, theirs, their_overrides in published:
                why = None if theirs is None else incompatible(theirs, mine)
                if why is None or theirs is None:
                    continue
                witness = together(view.graph, writer.node, reader.node)
                if witness is None:
                    continue
                peer = describe_node(view, writer.node)
                finding = self.finding(
                    reader.node.origin, witness=witness.values or None,
                    reader=describe_node(view, reader.node), name=reader.name,
                    mine=mine.describe(), writer=peer, theirs=theirs.describe(), why=why,
                    related=(Related(reader.endpoint.span, "the subscription is created here"),
                             Related(writer.endpoint.span,
                                     f"{peer}'s publisher is created here"),
                             *_overrides([*my_overrides, *their_overrides],
                                         clash(theirs, mine))))
                if not (from_sources(view, reader) and from_sources(view, writer)):
                    finding = dataclasses.replace(finding, severity=Severity.WARNING)
                yield finding
                break


def _effective(view: WiringView, end: ComposedEndpoint, role: str,
               ) -> tuple[Qos | None, list[tuple[str, Contribution]]]:
    """Return an end's QoS with the ``qos_overrides`` its node receives applied.

    Only an endpoint whose code opts in with ``QosOverridingOptions`` reads them, under
    its resolved, remapped name. Also returns the overrides that settled a policy.
    """
    from launchverify.parameters import effective_parameters
    from launchverify.topology.compose import named_record
    from launchverify.topology.qos import overridden

    profile = end.endpoint.profile
    if profile is None or profile.overriding is None or end.name is None:
        return profile, []
    composed = next((n for n in view.nodes if n.node is end.node), None)
    record = named_record(view.graph, composed) if composed is not None else end.node
    received = effective_parameters(view.graph, record)
    return overridden(profile, end.name, role, received,
                      python=end.endpoint.span.file.suffix == ".py")


def _overrides(settled: list[tuple[str, Contribution]], policy: str | None) -> list[Related]:
    """Return a note for each override that gave an end the policy they clash on."""
    return [Related(given.span, f"{name} is set here") for name, given in settled
            if name.endswith(f".{policy}")]
