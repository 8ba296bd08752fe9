"""LV601 unused-remap."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator
from typing import TYPE_CHECKING

from launchverify.graph import LaunchGraph, NodeRecord, RemapRecord
from launchverify.rule import Finding, Rule, RuleContext, Severity
from launchverify.suggest import typos

if TYPE_CHECKING:
    from launchverify.topology.compose import Composer
    from launchverify.topology.model import NodeInterface

# Names every node has without its code creating them (rcl's and rclcpp's own): a remap
# of them does something whatever the sources say.
BUILT_IN = ("/rosout", "/parameter_events", "/clock", "/tf", "/tf_static")
BUILT_IN_NAMES = tuple(name.lstrip("/") for name in BUILT_IN)  # however a rule writes them
BUILT_IN_PRIVATE = (
    "describe_parameters", "get_parameters", "get_parameter_types", "set_parameters",
    "set_parameters_atomically", "list_parameters", "get_type_description",
    "change_state", "get_state", "get_available_states", "get_available_transitions",
    "get_transition_graph", "transition_event", "get_logger_levels", "set_logger_levels",
)


class UnusedRemap(Rule):
    """A remap rule whose source name the node's code never uses: the remap does nothing.

    ## What it does
    Reads, from the workspace's own sources, the names the node's executable (or
    component) passes to rcl: its publishers, subscriptions, services, clients, actions,
    tf2, image_transport and message_filters wrappers, and names read from a parameter
    (the value the launch sets, else the default in the code). Each of the node's own
    remap rules is expanded as rcl expands it (relative names into the node's namespace,
    `~` into its name) and compared with those names, also expanded. A rule whose source
    is one or two edits from a name the code uses is a warning (a misspelt remap); one
    that matches nothing in a node whose every name is known from its sources is an info
    (the name may come from a library the node links). Nodes of packages without sources
    in the workspace, rules of `set_remap` (they apply to many nodes), rules of other
    nodes (`node:from:=to`) and the names every node has (`rosout`, `parameter_events`,
    `clock`, `tf`, the parameter and lifecycle services) are left alone.

    ## Why it matters
    The launch looks wired, but the node keeps using its default name: it never receives
    the data meant for it, or publishes where nobody listens. Nothing fails; `ros2 topic
    list` just shows one more topic.

    ## Example
    ```xml
    <node pkg="my_robot" exec="imu_filter" name="imu_filter">
      <remap from="imu_data" to="/sensors/imu"/>  <!-- the code subscribes to imu/data -->
    </node>
    ```

    ## Fix
    Remap the name the code uses (`imu/data`), or remove the rule.
    """

    code = "LV601"
    slug = "unused-remap"
    severity = Severity.WARNING
    message = ("remap of '{source}' does nothing: {executable} uses no such name"
               "{hint}")

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        composer: Composer | None = None
        for node in graph.nodes:
            own = [r for r in node.remappings if not r.scope]
            if not own or graph.runs(node.origin) is False or not self.has_sources(
                    graph, node, ctx):
                continue
            if composer is None:
                composer = self.composer(graph, ctx)
            yield from self.node_rules(graph, node, own, composer)

    @staticmethod
    def has_sources(graph: LaunchGraph, node: NodeRecord, ctx: RuleContext) -> bool:
        """Return whether the node's package has sources here (before reading any)."""
        package = graph.base(node.package)
        found = None if package is None or ctx.packages is None else ctx.packages.find(package)
        return found is not None and found.source is not None

    @staticmethod
    def composer(graph: LaunchGraph, ctx: RuleContext) -> Composer:
        """Return a composer over this graph, sharing the check's one source reader."""
        from launchverify.topology.wiring import workspace_view

        return workspace_view(graph, ctx).composer

    def node_rules(self, graph: LaunchGraph, node: NodeRecord, own: list[RemapRecord],
                   composer: Composer) -> Iterator[Finding]:
        from launchverify.topology.resolve import expand, parse_rule

        package, executable = graph.base(node.package), graph.base(node.executable)
        if package is None or executable is None:
            return
        interface, _ = composer.source.interface(package, executable,
                                                 node.composable)
        if interface is None:
            return
        identity = composer.identity(node, interface)
        if identity.namespace is None or identity.name is None:
            return
        used, complete = self.used_names(composer, node, interface, identity.namespace,
                                         identity.name)
        for remap in own:
            written = graph.base(remap.src)
            if written is None:
                continue
            rule = parse_rule(written, "")
            if rule.src.startswith("__") or (rule.node is not None
                                             and rule.node != identity.name):
                continue
            source = expand(rule.src, identity.namespace, identity.name).name
            if source is None or rule.src.lstrip("/") in BUILT_IN_NAMES or self.built_in(
                    source, identity.namespace, identity.name):
                continue
            if any(source == name or name.startswith(source + "/")
                   or source.startswith(name + "/") for name in used):
                continue  # used, or a sub-topic of one (image transports, actions)
            close = typos(source, used)
            label = f"{package}/{executable}"
            if close:
                yield self.finding(remap.origin, source=written, executable=label,
                                   hint=f" (did you mean '{used[close[0]]}'?)")
            elif complete:
                finding = self.finding(
                    remap.origin, source=written, executable=label,
                    hint=" in its sources (unless a library it links creates it)")
                yield dataclasses.replace(finding, severity=Severity.INFO)

    @staticmethod
    def used_names(composer: Composer, node: NodeRecord, interface: NodeInterface,
                   namespace: str, name: str) -> tuple[dict[str, str], bool]:
        """Return the names the code uses, expanded (to how it writes them); all known?"""
        from launchverify.topology.resolve import expand

        used: dict[str, str] = {}
        complete = not interface.problems
        for endpoint in interface.endpoints:
            written, _, _ = composer.written_name(node, endpoint)
            expanded = None if written is None else expand(written, namespace, name).name
            if expanded is None or written is None:
                complete = False
            else:
                used.setdefault(expanded, written)
        return used, complete

    @staticmethod
    def built_in(source: str, namespace: str, name: str) -> bool:
        """Return whether a name is one every node has, whatever its code."""
        if source in BUILT_IN:
            return True
        own = (namespace.rstrip("/") + "/" + name) + "/"
        return source.startswith(own) and source[len(own):] in BUILT_IN_PRIVATE
