"""LV206 constant-condition."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import ConditionRecord, LaunchGraph
from launchverify.ir.symbolic import describe_placed
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity
from launchverify.smt import reasoner_for


class ConstantCondition(Rule):
    """A condition that is always true where it is evaluated.

    ## What it does
    Reports a condition written without any input (`if="true"`, `$(eval '1 < 2')`), and a
    condition on launch arguments that every argument value makes true, given the
    conditions of the groups and includes around it (a group `if="$(var sim)"` holding a
    node `if="$(var sim)"`). Arguments range over every value `ros2 launch` accepts. A
    condition in a file reached through several launches is reported only when it is
    always true in all of them. It reports too a condition on an argument that a `<let>`
    (`SetLaunchConfiguration`, YAML `let`) replaced after the argument's declaration:
    true or false, it no longer depends on what the user gives (the override is named).

    ## Why it matters
    The condition does nothing, which is rarely what its author meant: often a copy of
    the enclosing condition where its opposite was intended, or a leftover switch.

    ## Example
    ```xml
    <group if="$(var use_sim)">
      <node pkg="gazebo_ros" exec="spawn_entity.py" if="$(var use_sim)"/>
    </group>
    ```

    ```xml
    <arg name="use_rviz" default="true"/>
    <let name="use_rviz" value="false"/>  <!-- left from debugging -->
    <node pkg="rviz2" exec="rviz2" if="$(var use_rviz)"/>  <!-- use_rviz:=true: no rviz -->
    ```

    ## Fix
    Remove the condition, or write the one that was meant; remove the override, or
    scope it in a `<group>` around the actions it is for.
    """

    code = "LV206"
    slug = "constant-condition"
    severity = Severity.INFO
    message = "`{condition}` is always {value}{where}"
    every_context = True

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        varying = ctx.settled_for(self.code)
        for record in graph.conditions:
            if record.override is not None:
                yield self.overridden(record)
                continue
            if not record.symbolic:
                if record.verdict is True and record.literal:
                    yield self.finding(record.origin, condition=record.text, value="true",
                                       where="")
                continue
            if record.verdict is False or record.origin.span in varying:
                continue
            reasoner = reasoner_for(graph)
            if not reasoner.always(record.origin.path, record.guard):
                varying.add(record.origin.span)  # not constant here: cannot stand
                continue
            alone = reasoner.always((), record.guard)
            where = "" if alone else " under " + " and ".join(
                describe_placed(g) for g in record.origin.path)
            yield self.finding(record.origin, condition=record.text, value="true", where=where)

    def overridden(self, record: ConditionRecord) -> Finding:
        """Return the finding for a condition an override decides."""
        assert record.override is not None
        where = (f": the argument it reads is replaced at {record.override.span.short()}, "
                 "after its declaration, so the value the user gives no longer counts")
        return self.finding(record.origin, condition=record.text,
                            value="true" if record.verdict else "false", where=where,
                            related=(Related(record.override.span, "the value is set here"),))
