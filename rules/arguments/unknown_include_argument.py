"""LV204 unknown-include-argument."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph, Origin
from launchverify.ir import actions as a
from launchverify.ir import subst as s
from launchverify.ir.walk import configuration_names, iter_subs
from launchverify.rule import Finding, Rule, RuleContext, Severity
from launchverify.span import Span
from launchverify.suggest import did_you_mean


class UnknownIncludeArgument(Rule):
    """An include passes an argument that the included launch never declares or reads.

    ## What it does
    For each `<include>` (`IncludeLaunchDescription`), compares the argument names it
    passes with what the included file (and the files it includes) declares or reads.
    Arguments given on the command line (`name:=value`) are checked against the whole
    launch the same way. Includes into files launchverify cannot fully see are skipped.

    ## Why it matters
    launch sets undeclared arguments silently, so a misspelled name
    (`use_sim_tme:=true`) does nothing and the included file runs on its default.

    ## Example
    ```xml
    <include file="$(find-pkg-share my_robot)/launch/bringup.launch.xml">
      <arg name="use_sim_tme" value="true"/>
    </include>
    ```

    ## Fix
    Use the name the included file declares, or declare the argument there.

    An argument that later arguments of the same include read (`$(var common_dir)/a.yaml`)
    is a helper the includer computes with, and is not reported.
    """

    code = "LV204"
    slug = "unknown-include-argument"
    severity = Severity.WARNING
    message = "argument {name!r} is not declared by {target}{hint}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        yield from self.command_line(graph)
        for include in graph.includes:
            if include.status != "loaded" or not include.complete or include.target is None:
                continue
            known = include.declared | include.reads | include.mentioned | {
                a.name for a in include.static_arguments
            }
            for path in include.files:  # reads on branches this evaluation did not take
                launch = graph.files[path].launch if path in graph.files else None
                if launch is not None:
                    known |= configuration_names(launch)
            known |= helper_names(include.action)
            for name, _value, span in include.arguments:
                if name is None or name in known:
                    continue
                call = include.origin.span if span != include.origin.span else None
                origin = Origin(span, include.origin.chain, include.origin.path, call=call)
                yield self.finding(origin, name=name, target=include.target.name,
                                   hint=did_you_mean(name, known))

    def command_line(self, graph: LaunchGraph) -> Iterator[Finding]:
        """Arguments given as name:=value that the launch never declares nor reads."""
        if not graph.pinned or not graph.complete or graph.stopped_early:
            return
        known = graph.declared_names() | graph.read_names() | graph.mentioned
        for loaded in graph.files.values():
            if loaded.launch is not None:
                known |= configuration_names(loaded.launch)
        for name in sorted(set(graph.pinned) - known):
            yield self.finding(Span.of_file(graph.root), name=f"{name}:={graph.pinned[name]}",
                               target=graph.root.name + " (given on the command line)",
                               hint=did_you_mean(name, known))


def helper_names(include: a.Include) -> set[str]:
    """Return the names the include's own argument values read.

    launch sets an include's arguments one after another, so an argument may exist only to
    build the values of the ones after it.
    """
    return {
        sub.name.text
        for argument in include.arguments
        for sub in iter_subs(argument.value)
        if isinstance(sub, s.LaunchConfig) and isinstance(sub.name, s.Text)
    }
