"""LV201 undeclared-argument."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Rule, RuleContext, Severity, rename
from launchverify.smt import reasoner_for
from launchverify.suggest import typos


class UndeclaredArgument(Rule):
    """A launch configuration is read but never declared or set.

    ## What it does
    Follows the launch in execution order and reports `$(var name)` (or
    `LaunchConfiguration('name')`) without a default where no `<arg>`, `<let>`, include
    argument or command-line value has set `name` before. A file that others include,
    that declares arguments without defaults, or that reads configurations it never
    declares is meant to be included: its includers must set them, so on its own only a
    read one or two edits away from a declared name (a typo) is reported.

    A read under a condition false with the default arguments is reported with arguments
    that make it true, as launch reads it only then.

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

    Autofix: renames the read to the declared name it misspells, where the name is written
    as plain text; safe when exactly one declared name is that close, unsafe otherwise.
    """

    code = "LV201"
    slug = "undeclared-argument"
    severity = Severity.ERROR
    message = "launch configuration {name!r} is read but never declared or set{hint}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        if not graph.complete:
            return  # a part we cannot see may set it
        known = frozenset(graph.declared_names() | set(graph.pinned))
        declared_in = {(arg.name, arg.action.span.file) for arg in graph.arguments}
        unset = [r for r in graph.reads if not r.found and not r.has_default]
        alone = graph.launchable_alone()
        seen: set[tuple[object, ...]] = set()
        for read in unset:
            key = (read.name, read.origin.span)
            if key in seen:
                continue
            witness = None
            if graph.runs(read.origin) is False:  # read only under a condition false now
                witness = reasoner_for(graph).reachable(read.origin.path)
                if witness is None or not witness.values:
                    continue  # launch never reads it: no argument values make it true
            seen.add(key)
            close = typos(read.name, known)
            typo = close[0] if close else None
            # read before its declaration in the same file, or out of that declaration's scope
            declared = (read.name, read.origin.span.file) in declared_in
            if typo is None and not declared and not alone:
                continue  # meant to be included: the includer sets it
            hint = f" (did you mean {typo!r}?)" if typo else (
                " here (it is declared elsewhere, not in scope before this read)"
                if declared else "")
            fix = (None if typo is None
                   else rename(read.written, read.name, typo, unique=len(close) == 1))
            yield self.finding(read.origin, name=read.name, hint=hint, fix=fix,
                               witness=None if witness is None else witness.values)

