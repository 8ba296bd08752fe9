"""LV201 undeclared-argument."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Rule, RuleContext, Severity
from launchverify.suggest import typo_of


class UndeclaredArgument(Rule):
    """A launch configuration is read but never declared or set.

    ## What it does
    Follows the launch in execution order and reports `$(var name)` (or
    `LaunchConfiguration('name')`) without a default where no `<arg>`, `<let>`, include
    argument or command-line value has set `name` before. A file that reads
    configurations it never declares is meant to be included: it is checked through its
    includers, which must set them; on its own only a read one or two edits away from a
    declared name (a typo) is reported.

    ## Why it matters
    ros2 launch stops with `launch configuration 'name' does not exist`. Usually the name
    is misspelled, or the argument is declared in a file that is included later.

    ## Example
    ```xml
    <arg name="use_sim_time" default="false"/>
    <node pkg="demo_nodes_cpp" exec="talker" if="$(var use_sim)"/>
    ```

    ## Fix
    Correct the name, declare the argument before its first use, or give the read a
    default: `$(var use_sim false)`.
    """

    code = "LV201"
    slug = "undeclared-argument"
    severity = Severity.ERROR
    message = "launch configuration {name!r} is read but never declared or set{hint}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        if graph.included_elsewhere or any(not inc.complete for inc in graph.includes):
            return
        if graph.opaque_files:
            return
        known = graph.declared_names() | set(graph.pinned)
        seen: set[tuple[object, ...]] = set()
        for read in graph.reads:
            if read.found or read.has_default or graph.runs(read.origin) is False:
                continue
            key = (read.name, read.origin.span)
            if key in seen:
                continue
            seen.add(key)
            typo = typo_of(read.name, known)
            if not read.origin.chain and typo is None:
                continue  # the root reads it undeclared: meant to be set by an includer
            hint = f" (did you mean {typo!r}?)" if typo else ""
            yield self.finding(read.origin, name=read.name, hint=hint)
