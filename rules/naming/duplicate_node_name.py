"""LV101 duplicate-node-name."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph, NodeRecord
from launchverify.models.ros_names import node_fqn
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity


class DuplicateNodeName(Rule):
    """Two nodes that run together resolve to the same fully qualified name.

    ## What it does
    Resolves every node's namespace (pushed namespaces, `namespace=`, absolute names) and
    name as ROS 2 does and reports a node whose fully qualified name is already taken by
    another node started in the same launch. A node launched without a namespace is in
    `/`. Nodes under conditions that exclude each other are not compared.

    ## Why it matters
    ROS 2 starts both. Parameter services, lifecycle transitions, `ros2 node` tools and
    logging then reach either node at random; launch itself only prints a warning.

    ## Example
    ```xml
    <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>
    <node pkg="demo_nodes_py" exec="talker" name="talker"/>
    ```

    ## Fix
    Rename one node, push it into its own namespace (`<group>` with
    `<push_ros_namespace>`), or make the conditions exclusive.
    """

    code = "LV101"
    slug = "duplicate-node-name"
    severity = Severity.ERROR
    message = "node name {fqn} is already used by the node at {other}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        first: dict[str, NodeRecord] = {}
        for node in graph.running_nodes():
            fqn = resolved_fqn(graph, node)
            if fqn is None:
                continue
            earlier = first.get(fqn)
            if earlier is None:
                first[fqn] = node
                continue
            yield self.finding(
                node.origin,
                related=(Related(earlier.origin.span, "first started here"),),
                fqn=fqn,
                other=earlier.origin.span.short(),
            )


def resolved_fqn(graph: LaunchGraph, node: NodeRecord) -> str | None:
    """Return a node's fully qualified name under the given arguments, if known."""
    name = graph.base(node.name)
    if name is None:
        return None
    namespace = "/" if node.namespace is None else graph.base(node.namespace)
    if namespace is None:
        return None
    return node_fqn(namespace, name.lstrip("/"))
