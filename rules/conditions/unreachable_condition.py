"""LV205 unreachable-condition."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Rule, RuleContext, Severity
from launchverify.smt import reasoner_for


class UnreachableCondition(Rule):
    """An action whose condition can never be true where it is evaluated.

    ## What it does
    Looks at every condition (`if`, `unless`, `LaunchConfigurationEquals`...) that depends
    on launch arguments, together with the conditions of the groups and includes around
    it, and reports one that no argument values can make true: the action never runs.
    The message names the facts that contradict each other (conditions with their
    places, and argument `choices`). Arguments range over every value `ros2 launch`
    accepts: their choices, or any string. A condition in a file reached through several
    launches is reported only when it can never be true in any of them.

    ## Why it matters
    The action is dead code that looks alive: a sensor that never starts in simulation, a
    mode that can never be selected because its name is not among the choices. Nothing
    fails at run time; the robot just lacks the node.

    ## Example
    ```xml
    <arg name="mode" default="slow"><choice value="slow"/><choice value="safe"/></arg>
    <node pkg="demo_nodes_cpp" exec="talker" if="$(equals $(var mode) fast)"/>
    ```

    ## Fix
    Correct the condition (a misspelt choice, an inverted `unless`), or remove the action.
    """

    code = "LV205"
    slug = "unreachable-condition"
    severity = Severity.WARNING
    message = "`{condition}` can never be true here: {reasons} cannot all hold"
    every_context = True

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        reachable = ctx.settled_for(self.code)
        for record in graph.conditions:
            if record.verdict is True or not record.symbolic:
                continue  # constants are written on purpose (if="false")
            if record.origin.span in reachable:
                continue  # true in some evaluation: the finding could not stand
            why = reasoner_for(graph).never(record.origin.path, record.guard)
            if why is None:
                reachable.add(record.origin.span)
            else:
                yield self.finding(record.origin, condition=record.text,
                                   reasons=why.describe())
