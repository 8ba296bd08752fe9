"""LV208 missing-required-argument."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity


class MissingRequiredArgument(Rule):
    """An include does not pass an argument that the included file requires.

    ## What it does
    Reproduces launch's check when it includes a file: every argument declared without a
    default and outside any condition (in the file, or in files it includes by a path that
    needs no configuration) must be passed by name in the include's arguments, or by the
    nested include that declares it.

    ## Why it matters
    ros2 launch stops with `Included launch description missing required argument`, even
    when a configuration of that name is already set in the including scope.

    ## Example
    ```xml
    <!-- robot.launch.xml declares <arg name="robot_name"/> with no default -->
    <include file="$(dirname)/robot.launch.xml"/>
    ```

    ## Fix
    Pass the argument (`<arg name="robot_name" value="$(var robot_name)"/>`), or give it
    a default in the included file.
    """

    code = "LV208"
    slug = "missing-required-argument"
    severity = Severity.ERROR
    message = "{target} requires argument {name!r}, which this include does not pass"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        for include in graph.includes:
            if include.status != "loaded" or include.target is None:
                continue
            for argument in include.missing_required():
                yield self.finding(
                    include.origin,
                    related=(Related(argument.span, "declared here without a default"),),
                    target=include.target.name, name=argument.name,
                )
