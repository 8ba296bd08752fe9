"""LV202 unused-argument."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator
from pathlib import Path

from launchverify.graph import LaunchGraph
from launchverify.problems import ProblemKind
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity
from launchverify.rules.arguments.undeclared_argument import misspelt_reads
from launchverify.suggest import numbered_alike

# Configurations launch and launch_ros read by themselves, without a $(var).
IMPLICIT_READS = frozenset({
    "launch-prefix", "launch-prefix-filter", "emulate_tty", "sigterm_timeout",
    "sigkill_timeout", "ros_namespace", "ros_remaps", "global_params",
})


class UnusedArgument(Rule):
    """A declared launch argument is never read.

    ## What it does
    Reports an `<arg>` (`DeclareLaunchArgument`) whose name is read nowhere: not by
    `$(var)` in the file, nor in any file it includes or that includes it, nor implicitly
    by launch (`launch-prefix`, `emulate_tty`, ...). A file that is included from several
    places is reported only when no includer reads the argument either. An argument a read
    misspells (`$(var gu1)` for `gui`) is meant to be used: LV201 reports the read, with
    the name it misspells, and LV202 stays quiet; a misspelt read with a default (which
    LV201 does not report) is named here.

    ## Why it matters
    Users pass `name:=value` and nothing changes: the argument is a leftover, or the place
    meant to use it reads a different name.

    ## Example
    ```xml
    <arg name="use_sim_time" default="false"/>
    <node pkg="demo_nodes_cpp" exec="talker"/>
    ```

    ## Fix
    Use the argument where it was meant to apply (`<param name="use_sim_time"
    value="$(var use_sim_time)"/>`), or delete the declaration.

    `use_sim_time` in a file that starts no ROS node (a world launch file running only the
    simulator) is the usual interface kept for includers, with nothing to give it to: an
    info. A file that mirrors the interface of another of its family (a stand-in in the same
    folder, or the same file name in another package, sharing most of its declared
    arguments) declares that family's arguments on purpose: an argument the other file
    uses is an info there. So is an argument passed by an includer that picks the file by an
    argument's value (`$(var sensor_model)_launch/launch/sensing.launch.xml`): every
    implementation of that interface declares what the includer passes.
    """

    code = "LV202"
    slug = "unused-argument"
    severity = Severity.WARNING
    message = "argument {name!r} is declared but never used{note}"
    mirror = "; it keeps the interface of {other}, which uses it"
    picked = ("; {includer} picks this file by an argument's value and passes it: every "
              "file it may pick declares it")
    no_node = "; no ROS node starts here to take it"
    misspelt = "; {read!r}, read with a default, may misspell it"
    every_context = True

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        if not graph.complete or graph.stopped_early:
            return  # a part we cannot see may read it
        if any(r.problem.kind is ProblemKind.PARSE for r in graph.problems):
            return  # reads may sit in what could not be parsed
        used = set(IMPLICIT_READS) | graph.read_names() | graph.mentioned_names()
        used |= misspelt_reads(graph).keys()  # LV201 names them: the read is what is wrong
        defaulted = misspelt_reads(graph, with_default=True)
        reported: set[object] = set()
        for argument in graph.arguments:
            span = argument.action.span
            if argument.name in used or span in reported:
                continue
            reported.add(span)
            if argument.name == "use_sim_time" and not starts_nodes(graph, span.file):
                finding = self.finding(argument.origin, name=argument.name, note=self.no_node)
                yield dataclasses.replace(finding, severity=Severity.INFO)
                continue
            other = ctx.interfaces.mirrored(span.file, argument.name)
            if other is None and (passed := ctx.interfaces.picked_by_name(
                    span.file, argument.name)) is not None:
                finding = self.finding(argument.origin, name=argument.name,
                                       note=self.picked.format(includer=passed.file.name),
                                       related=(Related(passed, "passed here"),))
                yield dataclasses.replace(finding, severity=Severity.INFO)
                continue
            read = defaulted.get(argument.name)
            if other is None and read is not None and not numbered_alike(read.name,
                                                                          argument.name):
                yield self.finding(argument.origin, name=argument.name,
                                   note=self.misspelt.format(read=read.name),
                                   related=(Related(read.origin.span, "read here"),))
                continue
            if other is None:
                yield self.finding(argument.origin, name=argument.name, note="")
                continue
            finding = self.finding(argument.origin, name=argument.name,
                                   note=self.mirror.format(other=other.file.name),
                                   related=(Related(other, "declared and used"),))
            yield dataclasses.replace(finding, severity=Severity.INFO)


def starts_nodes(graph: LaunchGraph, file: Path) -> bool:
    """Return whether a file starts a ROS node, itself or through what it includes."""
    return any(node.origin.span.file == file
               or any(span.file == file for span in node.origin.chain)
               for node in graph.nodes)
