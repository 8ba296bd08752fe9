"""LV604 competing-publishers."""

from __future__ import annotations

from collections.abc import Hashable, Iterator
from typing import TYPE_CHECKING

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, PollingRule, Related, RuleContext, Severity

if TYPE_CHECKING:
    from launchverify.topology.compose import ComposedEndpoint
    from launchverify.topology.wiring import WiringView

DEFAULT_SINGLE_WRITER = ("*cmd_vel",)


class CompetingPublishers(PollingRule):
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
    velocity smoother) gives each input its own name, and is never reported. A file
    that others include is judged by every launch that runs the node: it is reported
    when each of them sees the two meet (one that keeps them apart, by a namespace or
    another remap, says no; one where the node does not run has no say).

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
    message = ("{node} publishes {name}, which {peer} publishes too: {name} is meant to "
               "have one publisher ({why})")

    def answers(self, graph: LaunchGraph, ctx: RuleContext
                ) -> Iterator[tuple[Hashable, Finding | None]]:
        """Each publisher on a single-writer topic: does it meet another node's here?

        Asked by place (the node's launch, the publisher in the code), so that an
        evaluation where the node does not run abstains (an includer that starts the
        file's other branch), one where an includer's namespaces set the two apart says
        no, and one instance meeting another (a robot of a fleet) is enough for a yes. One
        where an earlier node publishes a topic whose name is unknown there (from a
        parameter file given by an environment variable) cannot say no: it abstains.
        """
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
        answers: dict[Hashable, Finding | None] = {}
        for name, connection in view.by_name["topics"].items():
            if not name_matches(name, patterns):
                continue
            for end, finding in self.topic(view, connection.ends.get("publishers", []), why):
                question = (end.node.origin.span, end.endpoint.span)
                if answers.get(question) is None:
                    answers[question] = finding
        yield from answers.items()

    def topic(self, view: WiringView, publishers: list[ComposedEndpoint],
              why: str) -> Iterator[tuple[ComposedEndpoint, Finding | None]]:
        """Yield each publisher with a finding when it meets an earlier one of another node."""
        from launchverify.topology.wiring import describe_node, together

        # in the order of their places, the same in every evaluation: "earlier" must not
        # depend on which root walked the nodes first
        publishers = sorted(publishers, key=_place)
        unnamed = view.unresolved.get(("topics", "publishers"), [])
        for index, end in enumerate(publishers):
            before = publishers[:index]
            if any(earlier.node is end.node for earlier in before):
                continue  # the same node again: its first publisher answered for it
            met = None
            for earlier in before:
                witness = together(view.graph, earlier.node, end.node)
                if witness is None:
                    continue
                peer = describe_node(view, earlier.node)
                met = self.finding(
                    end.node.origin,
                    related=(Related(end.endpoint.span, f"publishes {end.name} here"),
                             Related(earlier.node.origin.span, f"{peer} is launched here"),
                             Related(earlier.endpoint.span, f"{peer} publishes it here")),
                    witness=witness.values or None, node=describe_node(view, end.node),
                    name=end.name, peer=peer, why=why)
                break
            if met is None and any(_place(e) < _place(end) and e.node is not end.node
                                   for e in unnamed):
                continue  # an earlier node publishes a topic unknown here: it may be this
            yield end, met


def _place(end: ComposedEndpoint) -> tuple[str, int, int, str, int]:
    """Where a publisher's node is launched and where its code publishes: its order."""
    return (str(end.node.origin.span.file), end.node.origin.span.line,
            end.node.origin.span.column, str(end.endpoint.span.file), end.endpoint.span.line)
