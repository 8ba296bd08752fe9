"""LV207 invalid-condition-value."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.ir.symbolic import Truthy
from launchverify.models.booleans import InvalidBoolean, condition_truth
from launchverify.problems import ProblemKind
from launchverify.rule import Finding, Rule, RuleContext, Severity
from launchverify.rules.health.evaluation_error import conditional_witness
from launchverify.smt import reasoner_for


class InvalidConditionValue(Rule):
    """A condition that some argument values turn into something launch rejects.

    ## What it does
    `if`/`unless` accept only `true`, `false`, `1` and `0` (any case, surrounding blanks
    ignored); any other value makes `ros2 launch` raise. This rule tries every
    combination of the launch's switches (arguments with `choices` or a boolean default;
    other arguments keep their defaults) and reports a condition that one of them makes
    invalid, with that value and those arguments. It reports too a condition invalid
    under the arguments as given: a literal where a `LaunchConfiguration` was meant
    (`IfCondition('use_rviz')`), a ROS 1 habit such as `default="yes"` for a switch.

    ## Why it matters
    The launch works with the defaults and crashes the day someone picks another choice:
    `Caught exception in launch: invalid condition expression`.

    ## Example
    ```xml
    <arg name="robot" default="mobile"><choice value="mobile"/><choice value="arm"/></arg>
    <node pkg="demo_nodes_cpp" exec="talker" if="$(var robot)"/>
    ```

    ## Fix
    Compare instead of using the value itself: `if="$(equals $(var robot) arm)"`.
    """

    code = "LV207"
    slug = "invalid-condition-value"
    severity = Severity.ERROR
    message = "`{condition}` is {value!r}{arguments}, which is not a boolean: launch raises"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        yield from self.rejected(graph)
        for record in graph.conditions:
            if record.verdict is not None or not isinstance(record.guard, Truthy):
                continue
            base = graph.base(record.guard.expression)
            if base is not None and not is_boolean(base) and graph.runs(record.origin):
                continue  # invalid under the arguments as given: LV002 says so
            found = reasoner_for(graph).invalid_value(record.origin.path, record.guard)
            if found is None:
                continue
            value, witness = found
            if not witness.values:
                continue  # under the arguments as given: LV002 says so
            yield self.finding(record.origin, witness=witness.values, condition=record.text,
                               value=value, arguments=f" with {witness.describe()}")

    def rejected(self, graph: LaunchGraph) -> Iterator[Finding]:
        """Yield the conditions that evaluation found invalid under the arguments as given."""
        conditions = {record.origin.span: record for record in graph.conditions}
        for record in graph.problems:
            problem = record.problem
            if problem.rule != self.code or problem.kind not in (ProblemKind.EVALUATION,
                                                                 ProblemKind.CONDITIONAL):
                continue
            witness = None
            if problem.kind is ProblemKind.CONDITIONAL:  # inside a part off by default
                witness = conditional_witness(graph, record)
                if witness is None:
                    continue  # no values found under which launch evaluates it
            if problem.contextual and not graph.launchable_alone():
                continue  # an includer of this root may pass a valid value
            condition = conditions.get(problem.span)
            if condition is None or not isinstance(condition.guard, Truthy):
                continue
            value = graph.base(condition.guard.expression)
            if value is None:  # known only where it was evaluated: the failure says it
                said = problem.message.rpartition(" but got ")[2]
                value = said[1:-1] if said[:1] in "'\"" and len(said) > 1 else said
            arguments = ("" if condition.literal else " with the default arguments"
                         if problem.contextual else " with the arguments as given")
            yield self.finding(record.origin, condition=condition.text, value=value,
                               arguments=arguments,
                               witness=None if witness is None else witness.values)


def is_boolean(value: str) -> bool:
    """Return whether the condition rule accepts ``value``."""
    try:
        condition_truth(value)
    except InvalidBoolean:
        return False
    return True
