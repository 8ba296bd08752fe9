"""LV504 invalid-lifecycle-transition."""

from __future__ import annotations

from collections.abc import Hashable, Iterator

from launchverify.graph import LaunchGraph
from launchverify.lifecycle import bringup
from launchverify.lifecycle.verdicts import (
    dead_handler_labels,
    refused_transitions,
    report,
    unanswerable_requests,
)
from launchverify.rule import Finding, PollingRule, RuleContext, Severity


class InvalidLifecycleTransition(PollingRule):
    """A lifecycle transition the node cannot take, or one awaited under a label rcl lacks.

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

    It also checks the labels of every `OnStateTransition(start_state=, goal_state=,
    transition=)` against rcl's state machine, at the argument to change, with the label
    most likely meant. launch_ros compares each with the event's label by `==`, so the
    handler never fires when a label is not one rcl publishes (`'activated'`,
    `'configured'`, `'Active'`, `transition='activating'`, a substitution), when no single
    event carries the pair (`start_state='unconfigured', goal_state='inactive'`: configure
    publishes unconfigured -> configuring, then configuring -> inactive), or when a state
    is never left or reached (`start_state='finalized'`). Before rolling, rcl publishes
    events with an empty transition label (ros2/rcl#1019), so for a distribution checked
    (`--distro`, `ROS_DISTRO`) up to kilted any `transition=` is reported too. A handler
    with its own `matcher` is not checked: launch_ros then ignores the labels. What such a
    handler gates in the bring-up is LV503's.

    ## Why it matters
    The node logs `Unable to start transition`, launch logs `Failed to make transition`,
    and the node stays where it was: inactive sensors, a lifecycle manager that aborts
    the whole bring-up because someone else configured its node first. A handler under a
    label no event carries is worse: nothing is logged at all, and what it runs (the
    activation, the nodes that wait for it) never starts.

    ## Example
    ```python
    talker = LifecycleNode(package='lifecycle', executable='lifecycle_talker',
                           name='talker', namespace='')
    EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(talker),
                                transition_id=Transition.TRANSITION_ACTIVATE))  # unconfigured
    RegisterEventHandler(OnStateTransition(
        target_lifecycle_node=talker, goal_state='configured',  # the state is 'inactive'
        entities=[EmitEvent(event=ChangeState(
            lifecycle_node_matcher=matches_action(talker),
            transition_id=Transition.TRANSITION_ACTIVATE))]))
    ```

    ## Fix
    Configure first and activate when the node reaches `inactive` (an `OnStateTransition`
    handler with `goal_state='inactive'`, or `LifecycleTransition` with both ids), and let
    one party (launch or a lifecycle manager) drive each node. In handlers, write the
    labels rcl publishes, lower case: states `unconfigured`, `inactive`, `active`,
    `finalized` and the transition states `configuring`, `activating`, ...; filter on
    `start_state`/`goal_state` rather than `transition`.
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
        for verdict in dead_handler_labels(graph):
            yield report(self, verdict)
        analysis = bringup(graph)
        for verdict in refused_transitions(graph, analysis) if analysis else ():
            yield report(self, verdict)
