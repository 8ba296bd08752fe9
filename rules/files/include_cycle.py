"""LV301 include-cycle."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Rule, RuleContext, Severity


class IncludeCycle(Rule):
    """A launch file includes itself, directly or through other files.

    ## What it does
    Follows includes and reports the include that re-enters a file already being included
    (or that nests deeper than 40 files).

    ## Why it matters
    launch has no cycle detection: it recurses until Python's `RecursionError`, then fails
    to load the file with an error that does not name the cycle.

    ## Example
    ```xml
    <!-- a.launch.xml -->
    <include file="$(dirname)/b.launch.xml"/>
    <!-- b.launch.xml -->
    <include file="$(dirname)/a.launch.xml"/>
    ```

    ## Fix
    Break the cycle: move what both files need into a third file that both include.
    """

    code = "LV301"
    slug = "include-cycle"
    severity = Severity.ERROR
    message = "include cycle: {cycle}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        for include in graph.includes:
            if include.status != "cycle" or include.target is None:
                continue
            files = [span.file.name for span in include.origin.chain]
            files = [graph.root.name, *files[1:]] if files else [graph.root.name]
            files = [*files, include.origin.span.file.name, include.target.name]
            deduped = [f for i, f in enumerate(files) if i == 0 or f != files[i - 1]]
            yield self.finding(include.origin, cycle=" -> ".join(deduped))
