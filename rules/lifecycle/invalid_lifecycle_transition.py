"""LV504 invalid-lifecycle-transition."""

from __future__ import annotations

from collections.abc import Hashable, Iterator

from launchverify.graph import LaunchGraph
from launchverify.lifecycle import bringup
from launchverify.lifecycle.verdicts import (
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

    A handler waiting under a label no lifecycle event carries is LV508's; what it gates
    in the bring-up is LV503's.

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
        analysis = bringup(graph)
        for verdict in refused_transitions(graph, analysis) if analysis else ():
            yield report(self, verdict)
