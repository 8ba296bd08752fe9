"""LV103 remap-collision."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph, NodeRecord, RemapRecord
from launchverify.ir.subst import walk
from launchverify.ir.symbolic import Arg
from launchverify.models.ros_names import expand_topic_name
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity


class RemapCollision(Rule):
    """A remap rule that never applies, or two names remapped onto one.

    ## What it does
    Takes each node's remap rules in the order ROS 2 applies them (`set_remap` rules in
    scope first, then the node's own; a `node:from` rule only for the node it names),
    expands both sides the way rcl does (relative names into the node's namespace, `~`
    into its name) and reports, within one node:
    - a source remapped again to another target: the first rule wins, the later one never
      applies;
    - two different sources remapped to the same target: two topics merged into one.
    The same rule written twice is not reported, nor a collision of targets taken from
    arguments in a file meant to be included (its defaults are placeholders that the
    includers replace; every includer's own evaluation is judged).

    ## Why it matters
    The node silently keeps using the name the author meant to change, or publishes and
    subscribes on one topic where two were meant, mixing unrelated data. `ros2 topic
    list` shows nothing wrong at a glance.

    ## Example
    ```xml
    <set_remap from="cmd_vel" to="cmd_vel_nav"/>
    <node pkg="nav2_controller" exec="controller_server" name="controller_server">
      <remap from="cmd_vel" to="cmd_vel_smoothed"/>   <!-- never applies -->
    </node>
    ```

    ## Fix
    Keep one rule per source (a group's `set_remap` or the node's own `remap`), and give
    different sources different targets.
    """

    code = "LV103"
    slug = "remap-collision"
    severity = Severity.WARNING
    message = "{text}"
    # Targets often come from arguments: a collision of defaults that every includer
    # overrides is no collision (autoware's input and output trajectory defaults).
    every_context = True

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        for node in graph.nodes:
            if graph.runs(node.origin) is False:
                continue
            yield from self.node_rules(graph, node)

    def node_rules(self, graph: LaunchGraph, node: NodeRecord) -> Iterator[Finding]:
        namespace = "/" if node.namespace is None else graph.base(node.namespace)
        name = graph.base(node.name)
        by_source: dict[str, tuple[str, RemapRecord]] = {}
        by_target: dict[str, tuple[str, RemapRecord]] = {}
        for remap in node.remappings:
            src, dst = graph.base(remap.src), graph.base(remap.dst)
            if src is None or dst is None or namespace is None:
                continue
            prefix, colon, bare = src.rpartition(":")
            if colon:
                if prefix != name:
                    continue  # a rule for another node of the process
                src = bare
            if name is None and (src.startswith("~") or dst.startswith("~")):
                continue
            source = expand_topic_name(src, namespace, name or "")
            target = expand_topic_name(dst, namespace, name or "")
            earlier = by_source.get(source)
            if earlier is not None:
                if earlier[0] != target:
                    yield self.finding(
                        remap.origin, related=(Related(earlier[1].origin.span,
                                                       f"{source} -> {earlier[0]} wins"),),
                        text=f"remap {src} -> {dst} never applies: {source} is already "
                             f"remapped to {earlier[0]} (the first rule wins)")
                continue
            by_source[source] = (target, remap)
            merged = by_target.get(target)
            if merged is not None and merged[0] != source and not (
                    _from_arguments(remap, merged[1]) and not graph.launchable_alone()):
                yield self.finding(
                    remap.origin,
                    related=(Related(merged[1].origin.span, f"{merged[0]} -> {target}"),),
                    text=f"remap {src} -> {dst} sends {source} to {target}, where "
                         f"{merged[0]} already goes: two names become one")
                continue
            by_target.setdefault(target, (source, remap))


def _from_arguments(*remaps: RemapRecord) -> bool:
    """Return whether remap targets come from arguments (their defaults, checked alone)."""
    return any(isinstance(part, Arg) for remap in remaps for part in walk(remap.dst))
