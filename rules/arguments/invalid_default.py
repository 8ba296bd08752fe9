"""LV203 invalid-default."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import replace

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Rule, RuleContext, Severity


class InvalidDefault(Rule):
    """An argument's default value is not one of its declared choices.

    ## What it does
    Compares each argument's default (evaluated) with its `<choice>` values, exactly and
    case-sensitively, as launch does.

    ## Why it matters
    Launched without that argument, ros2 launch stops with `Argument "<name>" provided value
    "<default>" is not valid`.

    ## Example
    ```xml
    <arg name="robot" default="Burger">
      <choice value="burger"/><choice value="waffle"/>
    </arg>
    ```

    ## Fix
    Make the default one of the choices, or add it to them.
    """

    code = "LV203"
    slug = "invalid-default"
    severity = Severity.ERROR
    message = "default {default!r} of argument {name!r} is not one of its choices {choices}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        reported: set[object] = set()
        for argument in graph.arguments:
            if argument.choices is None or argument.action.span in reported:
                continue
            default = graph.base(argument.default)
            if default is None or default in argument.choices:
                continue
            reported.add(argument.action.span)
            origin = replace(argument.origin, span=argument.action.at("default"))
            yield self.finding(origin, default=default, name=argument.name,
                               choices=list(argument.choices))
