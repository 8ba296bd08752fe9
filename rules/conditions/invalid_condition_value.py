"""LV207 invalid-condition-value."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.ir.symbolic import Truthy
from launchverify.models.booleans import InvalidBoolean, condition_truth
from launchverify.rule import Finding, Rule, RuleContext, Severity
from launchverify.smt import reasoner_for


class InvalidConditionValue(Rule):
    """A condition that some argument values turn into something launch rejects.

    ## What it does
    `if`/`unless` accept only `true`, `false`, `1` and `0` (any case, surrounding blanks
    ignored); any other value makes `ros2 launch` raise. This rule tries every
    combination of the launch's switches (arguments with `choices` or a boolean default;
    other arguments keep their defaults) and reports a condition that one of them makes
    invalid, with that value and those arguments. Under the arguments as given, the same
    mistake is LV002.

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
    message = ("`{condition}` is {value!r} with {arguments}, which is not a boolean: "
               "launch raises")

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
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
                               value=value, arguments=witness.describe())


def is_boolean(value: str) -> bool:
    """Return whether the condition rule accepts ``value``."""
    try:
        condition_truth(value)
    except InvalidBoolean:
        return False
    return True
