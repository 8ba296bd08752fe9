"""LV001 parse-error."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.problems import ProblemKind
from launchverify.rule import Finding, Rule, RuleContext, Severity


class ParseError(Rule):
    """A launch file that ros2 launch cannot load as written.

    ## What it does
    Reports files that are not well-formed XML or YAML, unknown tags and attributes,
    missing required attributes, values of the wrong type (an unquoted YAML `false` where
    launch expects a string), and `$(...)` expressions that launch's grammar rejects
    (unknown substitution names, wrong argument counts, two spaces between arguments).

    ## Why it matters
    ros2 launch refuses the whole file (`InvalidLaunchFileError`), so nothing in it starts.
    Typos in attribute names are caught here too: launch rejects attributes it does not read
    rather than ignoring them.

    ## Example
    ```xml
    <node pkg="demo_nodes_cpp" exec="talker" nmae="talker"/>
    <node pkg="demo_nodes_cpp" exec="listener" name="$(arg robot)"/>
    ```

    ## Fix
    Correct the spelling (`name`, `$(var robot)`), quote YAML values that must be strings,
    and use one space between substitution arguments.
    """

    code = "LV001"
    slug = "parse-error"
    severity = Severity.ERROR
    message = "{text}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        for record in graph.problems:
            if record.problem.kind is ProblemKind.PARSE:
                yield self.finding(record.origin, text=record.problem.message)
