"""LV502 dangling-event-target."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.events import describe_action
from launchverify.graph import ExecutedRecord, LaunchGraph
from launchverify.ir.actions import OpaqueAction
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity
from launchverify.smt import reasoner_for


class DanglingEventTarget(Rule):
    """An event handler waits for an action that never runs.

    ## What it does
    For every handler with a target (`OnProcessExit(target_action=...)`,
    `OnProcessStart`, `OnProcessIO`, `OnExecutionComplete`, `OnStateTransition`), checks
    that the target action is executed somewhere in the launch, and that it can run
    where the handler is registered (their conditions can hold together). Reports a
    handler whose target is never added to the launch description, or only under a
    condition that excludes the handler's.

    ## Why it matters
    The handler never fires: the controller spawner that should start after the robot
    description never starts, the shutdown that should follow a test never comes, and
    the launch waits forever or silently does less.

    ## Example
    ```python
    spawner = Node(package='controller_manager', executable='spawner', arguments=['arm'])
    return LaunchDescription([
        RegisterEventHandler(OnProcessExit(target_action=spawner, on_exit=[rviz])),
    ])   # spawner itself is never added
    ```

    ## Fix
    Add the target action to the launch description (or to the handler chain that
    should start it), or make the conditions agree.
    """

    code = "LV502"
    slug = "dangling-event-target"
    severity = Severity.ERROR
    message = "the handler waits for {target}, which {why}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        executed: dict[int, list[ExecutedRecord]] = {}
        for record in graph.executed:
            executed.setdefault(id(record.action), []).append(record)
        handed = graph.handed()
        for handler in graph.handlers:
            if handler.target is None or handler.event == "shutdown":
                continue
            runs = executed.get(id(handler.target), [])
            target_span = getattr(handler.target, "span", None)
            label = describe_action(handler.target)
            related = (Related(target_span, "the target"),) if target_span else ()
            if not runs:
                if id(handler.target) in handed or isinstance(handler.target, OpaqueAction):
                    continue  # code launchverify cannot see holds it, or is it, and runs it
                if graph.stopped_early:
                    continue  # the evaluation stopped before its end: it may run later
                yield self.finding(handler.origin, related=related, target=label,
                                   why="is never executed (is it added to the launch?)")
                continue
            reasoner = reasoner_for(graph)
            if reasoner.together(handler.origin.path) is None:
                continue  # the handler itself is not registered under the switches
            if all(reasoner.apart(handler.origin.path, r.origin.path) for r in runs):
                yield self.finding(handler.origin, related=related, target=label,
                                   why="cannot run where the handler is registered")
