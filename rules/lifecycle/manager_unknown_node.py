"""LV505 lifecycle-manager-unknown-node."""

from __future__ import annotations

from collections.abc import Hashable, Iterator

from launchverify.graph import LaunchGraph
from launchverify.lifecycle import bringup
from launchverify.lifecycle.verdicts import UnknownManagedNode, unknown_managed_nodes
from launchverify.rule import Finding, PollingRule, Related, RuleContext, Severity


class ManagerUnknownNode(PollingRule):
    """A nav2 lifecycle manager waits for a node the launch never starts.

    ## What it does
    Reads each `nav2_lifecycle_manager` node's `node_names` as it receives them (inline
    parameters or files), resolves every name in the manager's own namespace, as the
    manager does, and reports a name that no launched node has. The message says when a
    node of that name runs in another namespace, or names the node it was probably meant
    to be.

    ## Why it matters
    The manager creates its service clients in order and waits for each node's
    `get_state` service without a timeout: one missing or misnamed node blocks the bring-up
    of every node it manages, and the logs only repeat `Waiting for service ...`.

    ## Example
    ```python
    Node(package='nav2_lifecycle_manager', executable='lifecycle_manager',
         name='lifecycle_manager_localization',
         parameters=[{'autostart': True, 'node_names': ['map_server', 'amlc']}])
    ```

    ## Fix
    Use the node's name as launched (relative names resolve in the manager's namespace),
    or start the manager in the same namespace as its nodes.
    """

    code = "LV505"
    slug = "lifecycle-manager-unknown-node"
    severity = Severity.ERROR
    message = ("{manager} waits for {resolved} ('{name}' in node_names), which is never "
               "launched{hint}: the manager blocks and brings up none of its nodes")

    def answers(self, graph: LaunchGraph, ctx: RuleContext
                ) -> Iterator[tuple[Hashable, Finding | None]]:
        analysis = bringup(graph)
        if analysis is None:
            return
        for asked, unknown in unknown_managed_nodes(graph, analysis, ctx.packages):
            yield asked, None if unknown is None else self.describe(unknown)

    def describe(self, unknown: UnknownManagedNode) -> Finding:
        """Return the finding for one name no launched node has."""
        hint = ""
        if unknown.elsewhere:
            hint = f"; {unknown.elsewhere} runs in another namespace"
        elif unknown.suggestion:
            hint = f" (did you mean {unknown.suggestion}?)"
        names, manager = unknown.names_span, unknown.manager.span
        related = ((Related(names, "node_names is set here"),)
                   if names is not None and (names.file, names.line) != (
                       manager.file, manager.line) else ())
        return self.finding(unknown.manager, related=related, manager=unknown.manager_name,
                            resolved=unknown.resolved, name=unknown.name, hint=hint)
