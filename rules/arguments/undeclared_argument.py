"""LV201 undeclared-argument."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Rule, RuleContext, Severity
from launchverify.suggest import did_you_mean


class UndeclaredArgument(Rule):
    """A launch configuration is read but never declared or set.

    ## What it does
    Follows the launch in execution order and reports `$(var name)` (or
    `LaunchConfiguration('name')`) without a default where no `<arg>`, `<let>`, include
    argument or command-line value has set `name` before. Files that are only meant to be
    included are checked through their includers, which pass them their arguments.

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
            yield self.finding(read.origin, name=read.name, hint=did_you_mean(read.name, known))
