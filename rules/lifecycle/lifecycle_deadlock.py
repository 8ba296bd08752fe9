"""LV503 lifecycle-deadlock."""

from __future__ import annotations

from collections.abc import Hashable, Iterator

from launchverify.graph import LaunchGraph
from launchverify.lifecycle import bringup
from launchverify.lifecycle.verdicts import deadlocks, report
from launchverify.rule import Finding, PollingRule, RuleContext, Severity


class LifecycleDeadlock(PollingRule):
    """A lifecycle bring-up that can never complete.

    ## What it does
    Follows the bring-up the launch drives (`ChangeState` events, `LifecycleTransition`,
    `autostart`, `ros2 lifecycle set` commands, nav2 lifecycle managers, and the
    `OnStateTransition`, `OnProcessStart`/`OnProcessExit` handlers and timers that chain
    them) through every order in which its events can happen, with every transition
    callback succeeding, and reports:

    - handlers that wait for each other in a cycle (the handler that activates `/b` waits
      for `/a` to become active, and the one that activates `/a` waits for `/b`);
    - a handler waiting for a bring-up state (configuring, inactive, activating, active)
      that its node never reaches, because nothing in the launch moves it on;
    - a handler that never fires because its labels match no lifecycle event
      (`goal_state='activated'`, `'Active'`, `start_state='unconfigured',
      goal_state='inactive'`, `transition=` before rolling: see LV504), when the bring-up
      needed what it runs: a `configure`/`activate` its node would have accepted, a node
      it starts. Handlers that wait for what only such a handler would do are its
      consequence, not reported apart;
    - a nav2 lifecycle manager that never gets to configure its nodes, because one of
      them is started only by something that never happens.

    Nodes that nothing in the launch moves (driven from outside) are not judged, nor
    handlers that wait for a shutdown or an error. `--explain` prints the trace to the
    furthest state the node reaches.

    ## Why it matters
    Nothing fails: the launch sits there, nodes stay unconfigured, and the robot never
    starts driving. On the robot this looks like a hang, found only after a timeout.

    ## Example
    ```python
    RegisterEventHandler(OnStateTransition(target_lifecycle_node=a, goal_state='active',
        entities=[EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(b),
                                              transition_id=Transition.TRANSITION_ACTIVATE))])),
    RegisterEventHandler(OnStateTransition(target_lifecycle_node=b, goal_state='active',
        entities=[EmitEvent(event=ChangeState(lifecycle_node_matcher=matches_action(a),
                                              transition_id=Transition.TRANSITION_ACTIVATE))])),
    # 'Active' is no label rcl publishes: the planner never starts
    RegisterEventHandler(OnStateTransition(target_lifecycle_node=a, goal_state='Active',
        entities=[Node(package='nav2_planner', executable='planner_server')])),
    ```

    ## Fix
    Break the cycle: activate one node unconditionally (when it reaches `inactive`), or
    let one lifecycle manager bring the nodes up in order. A handler that never fires
    needs the label LV504 names.
    """

    code = "LV503"
    slug = "lifecycle-deadlock"
    severity = Severity.ERROR
    message = "{text}"

    def answers(self, graph: LaunchGraph, ctx: RuleContext
                ) -> Iterator[tuple[Hashable, Finding | None]]:
        analysis = bringup(graph)
        for asked, verdict in deadlocks(graph, analysis) if analysis else ():
            yield asked, None if verdict is None else report(self, verdict)
