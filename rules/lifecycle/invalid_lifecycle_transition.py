"""LV504 invalid-lifecycle-transition."""

from __future__ import annotations

from collections.abc import Hashable, Iterator

from launchverify.graph import LaunchGraph
from launchverify.lifecycle import bringup
from launchverify.lifecycle.verdicts import (
    impossible_handler_pairs,
    refused_transitions,
    report,
    unanswerable_requests,
)
from launchverify.rule import Finding, PollingRule, RuleContext, Severity


class InvalidLifecycleTransition(PollingRule):
    """A lifecycle transition the node cannot take from the state it is in.

    ## What it does
    Searches every order in which the launch's lifecycle requests can reach their nodes
    (`ChangeState`, `LifecycleTransition`, `autostart`, `ros2 lifecycle set`, nav2
    lifecycle managers) and reports a request that can arrive in a state where rcl
    refuses it (`activate` before `configure`, a second `configure`), or before its node
    is started (launch drops it). Also reports requests that can never arrive: a
    `ChangeState` aimed at a node launched as a plain `Node` (launch_ros delivers it only
    to `LifecycleNode` actions), at a name no launched node has, or with `CREATE` or
    `DESTROY`, which the state machine does not have. When one request's success makes
    another fail, the first is reported; `--explain` prints the trace.

    It also reports an `OnStateTransition` that awaits a transition the node cannot take
    from a state: labels rcl publishes, each in its own field, that no single event
    carries together (`start_state='unconfigured', goal_state='inactive'`: configure
    publishes unconfigured -> configuring, then configuring -> inactive), at the argument
    to change. A label rcl never publishes in its field (`'activated'`, `'Active'`,
    `start_state='finalized'`, any `transition=` before rolling) is LV508's; what such a
    handler gates in the bring-up is LV503's.

    ## Why it matters
    The node logs `Unable to start transition`, launch logs `Failed to make transition`,
    and the node stays where it was: inactive sensors, a lifecycle manager that aborts
    the whole bring-up because someone else configured its node first.

    ## Example
    ```python
    talker = LifecycleNode(package='lifecycle', executable='lifecycle_talker',
                           name='talker', namespace='')
    EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(talker),
                                transition_id=Transition.TRANSITION_ACTIVATE))  # unconfigured
    ```

    ## Fix
    Configure first and activate when the node reaches `inactive` (an `OnStateTransition`
    handler with `goal_state='inactive'`, or `LifecycleTransition` with both ids), and let
    one party (launch or a lifecycle manager) drive each node.
    """

    code = "LV504"
    slug = "invalid-lifecycle-transition"
    severity = Severity.ERROR
    message = "{text}"

    def answers(self, graph: LaunchGraph, ctx: RuleContext
                ) -> Iterator[tuple[Hashable, Finding | None]]:
        analysis = bringup(graph)
        for asked, verdict in unanswerable_requests(graph, analysis) if analysis else ():
            yield asked, None if verdict is None else report(self, verdict)

    def direct(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        for verdict in impossible_handler_pairs(graph):
            yield report(self, verdict)
        analysis = bringup(graph)
        for verdict in refused_transitions(graph, analysis) if analysis else ():
            yield report(self, verdict)
