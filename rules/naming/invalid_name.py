"""LV102 invalid-name."""

from __future__ import annotations

from collections.abc import Callable, Iterator

from launchverify.graph import LaunchGraph
from launchverify.models.ros_names import (
    validate_namespace,
    validate_node_name,
    validate_remap_name,
)
from launchverify.rule import Finding, Rule, RuleContext, Severity

VALIDATORS: dict[str, Callable[[str], str | None]] = {
    "node name": validate_node_name,
    "namespace": validate_namespace,
    "remap": validate_remap_name,
}


class InvalidName(Rule):
    """A node name, namespace or remap rule that ROS 2 rejects.

    ## What it does
    Checks node names, namespaces (after pushed namespaces are applied) and both sides of
    remap rules against the rmw/rcl naming rules: allowed characters, no leading digit in a
    token, no `//`, `~` only at the start, balanced `{}`.

    ## Why it matters
    launch raises `InvalidNodeNameException` / `InvalidNamespaceException` and stops; a bad
    remap rule makes the node exit at start-up with `Couldn't parse remap rule`.

    ## Example
    ```xml
    <node pkg="demo_nodes_cpp" exec="talker" name="front-camera"/>
    <push_ros_namespace namespace="2nd_robot"/>
    ```

    ## Fix
    Use only letters, digits and underscores, and do not start a name or namespace token
    with a digit (`front_camera`, `robot_2`).
    """

    code = "LV102"
    slug = "invalid-name"
    severity = Severity.ERROR
    message = "invalid {kind} {value!r}: {reason}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        seen: set[tuple[object, ...]] = set()
        for record in graph.names:
            reason = VALIDATORS[record.kind](record.value)
            key = (record.kind, record.value, record.origin.span)
            if reason is None or key in seen:
                continue
            seen.add(key)
            yield self.finding(record.origin, kind=record.kind, value=record.value,
                               reason=reason)
