"""LV604 competing-publishers."""

from __future__ import annotations

from collections.abc import Iterator
from typing import TYPE_CHECKING

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity

if TYPE_CHECKING:
    from launchverify.topology.compose import ComposedEndpoint
    from launchverify.topology.wiring import WiringView

DEFAULT_SINGLE_WRITER = ("*cmd_vel",)


class CompetingPublishers(Rule):
    """Two nodes that run together publish a topic meant to have one publisher (`cmd_vel`).

    ## What it does
    Composes the launch's nodes with their interfaces, read from the workspace's sources
    (as `launchverify graph` shows them), and looks at the topics configured as
    single-writer: by default every name ending in `cmd_vel`, else the globs of
    `single-writer-topics` in `launchverify.toml` (or `[tool.launchverify]`; `[]` turns
    the rule off). A second node publishing such a topic is reported when both can run
    at the same time, as LV101 decides it: conditions that exclude each other (`if` and
    `unless` of one argument) or a node started once the other has exited keep them
    apart; the finding names the argument values under which they meet when the
    arguments as given do not start both. A mux in between (`twist_mux`, nav2's
    velocity smoother) gives each input its own name, and is never reported.

    ## Why it matters
    Velocity commands from two sources interleave: the robot jerks between them, or a
    teleop stop is overridden by the planner a few milliseconds later. Nothing warns.

    ## Example
    ```xml
    <node pkg="my_robot" exec="follower"/>        <!-- publishes cmd_vel -->
    <node pkg="my_robot" exec="keyboard_teleop"/> <!-- publishes cmd_vel too -->
    ```

    ## Fix
    Give each source its own topic and arbitrate with a mux (`twist_mux`), or make the
    nodes exclusive (`if`/`unless` on one argument).
    """

    code = "LV604"
    slug = "competing-publishers"
    severity = Severity.WARNING
    every_context = True  # an includer's namespaces may set the two apart
    message = ("{node} publishes {name}, which {peer} publishes too: {name} is meant to "
               "have one publisher ({why})")

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        from launchverify.topology.wiring import (
            globs_option,
            name_matches,
            reads_sources,
            workspace_view,
        )

        patterns = globs_option(ctx, "single-writer-topics", DEFAULT_SINGLE_WRITER)
        if not patterns or not reads_sources(graph, ctx):
            return
        why = ("single-writer-topics" if "single-writer-topics" in ctx.options
               else "the default single-writer topics: *cmd_vel")
        view = workspace_view(graph, ctx)
        for name, connection in view.by_name["topics"].items():
            if name_matches(name, patterns):
                yield from self.topic(view, connection.ends.get("publishers", []), why)

    def topic(self, view: WiringView, publishers: list[ComposedEndpoint],
              why: str) -> Iterator[Finding]:
        """Yield a finding for each publisher that meets an earlier one of another node."""
        from launchverify.topology.wiring import describe_node, together

        for index, end in enumerate(publishers):
            before = publishers[:index]
            if any(earlier.node is end.node for earlier in before):
                continue  # the same node again: its first publisher answered for it
            for earlier in before:
                witness = together(view.graph, earlier.node, end.node)
                if witness is None:
                    continue
                peer = describe_node(view, earlier.node)
                yield self.finding(
                    end.node.origin,
                    related=(Related(end.endpoint.span, f"publishes {end.name} here"),
                             Related(earlier.node.origin.span, f"{peer} is launched here"),
                             Related(earlier.endpoint.span, f"{peer} publishes it here")),
                    witness=witness.values or None, node=describe_node(view, end.node),
                    name=end.name, peer=peer, why=why)
                break
