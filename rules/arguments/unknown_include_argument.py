"""LV204 unknown-include-argument."""

from __future__ import annotations

import dataclasses
import functools
from collections.abc import Iterator
from typing import cast

from launchverify.graph import IncludeRecord, LaunchGraph, Origin
from launchverify.ir import actions as a
from launchverify.ir import subst as s
from launchverify.ir.subst import Sub
from launchverify.ir.walk import configuration_names, iter_subs
from launchverify.models.parameter_values import typed_parameter
from launchverify.parameters import effective_parameters
from launchverify.rule import Finding, Fix, Rule, RuleContext, Severity, rename
from launchverify.span import Span
from launchverify.suggest import closest, did_you_mean, sole_typo


class UnknownIncludeArgument(Rule):
    """An include passes an argument that the included launch never declares or reads.

    ## What it does
    For each `<include>` (`IncludeLaunchDescription`), compares the argument names it
    passes with what the included file (and the files it includes) declares or reads.
    Arguments given on the command line (`name:=value`) or in the configuration
    (`arguments = {...}`) are checked against the whole launch the same way. Includes
    into files launchverify cannot fully see are skipped.

    ## Why it matters
    launch sets undeclared arguments silently, so a misspelled name
    (`use_sim_tme:=true`) does nothing and the included file runs on its default.

    ## Severity
    An error when the name has exactly one close declared name (one or two edits away:
    `use_sim_tme` for `use_sim_time`), which is almost always a typo that silently does
    nothing; a warning when there is no such name, or several (an argument the includer
    passes on purpose to a file that does not use it, or one of many alike names), or
    when the two differ only in digits (`input/rois8` next to `input/rois7`: one more of
    a numbered family than the file takes); an info when the included nodes set the same
    parameter to the same value themselves.

    ## Example
    ```xml
    <include file="$(find-pkg-share my_robot)/launch/bringup.launch.xml">
      <arg name="use_sim_tme" value="true"/>
    </include>
    ```

    ## Fix
    Use the name the included file declares, or declare the argument there.

    Autofix: renames the argument to the declared name it most likely misspells, where
    the name is written as plain text; safe when that is its only close name (one or two
    edits away), unsafe otherwise.

    An argument that later arguments of the same include read (`$(var common_dir)/a.yaml`)
    is a helper the includer computes with, and is not reported. An argument named like a
    ROS parameter that the included nodes already set to the same value themselves
    (`use_sim_time:=true` into a file whose nodes hard-code `use_sim_time: true`) loses
    nothing: it is an info, and a warning again as soon as the values differ.
    """

    code = "LV204"
    slug = "unknown-include-argument"
    severity = Severity.WARNING
    message = "argument {name!r} is not declared by {target}{hint}"
    applied = "; its nodes already set {name} to {value!r} themselves"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        yield from self.command_line(graph, ctx)
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
            frozen = frozenset(known)  # the suggestions' memory knows it (1,500 names)
            helpers = helper_names(include.action)  # used, but no name the target takes
            for name, value, span in include.arguments:
                if name is None or name in known or name in helpers:
                    continue
                call = include.origin.span if span != include.origin.span else None
                origin = Origin(span, include.origin.chain, include.origin.path, call=call)
                same = applied_inside(graph, include, name, value)
                hint = (self.applied.format(name=name, value=same) if same is not None
                        else did_you_mean(name, frozen))
                fix = None if same is not None else _fix(include, name, span, frozen)
                finding = self.finding(origin, name=name, target=include.target.name,
                                       hint=hint, fix=fix)
                if same is not None:
                    yield dataclasses.replace(finding, severity=Severity.INFO)
                else:
                    yield _as_typo(finding, name, frozen)

    def command_line(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        """Arguments given as name:=value that the launch never declares nor reads.

        They come from the command line or the configuration; the message says which.
        """
        if not graph.pinned or not graph.complete or graph.stopped_early:
            return
        known = frozenset(graph.declared_names() | graph.read_names()
                          | graph.mentioned_names())
        sources = cast(dict[str, str], ctx.options.get("argument-sources", {}))
        for name in sorted(set(graph.pinned) - known):
            given = sources.get(name, "on the command line")
            finding = self.finding(Span.of_file(graph.root),
                                   name=f"{name}:={graph.pinned[name]}",
                                   target=f"{graph.root.name} (given {given})",
                                   hint=did_you_mean(name, known))
            yield _as_typo(finding, name, known)


def _as_typo(finding: Finding, name: str, known: frozenset[str]) -> Finding:
    """Make the finding an error when ``name`` misspells exactly one known name.

    Names that differ only in their digits (`input/rois8` next to `input/rois7`) are
    members of a numbered family, not a typo: the includer passes one more than the
    included file takes, which may be meant.
    """
    if sole_typo(name, known) is None:
        return finding
    return dataclasses.replace(finding, severity=Severity.ERROR)


def _fix(include: IncludeRecord, name: str, span: Span, known: frozenset[str]) -> Fix | None:
    """Return the rename of an argument to the declared name the hint suggests."""
    meant = closest(name, known)
    if meant is None:
        return None
    for argument in _arguments_at(include.action).get(span, ()):
        written = argument.name
        if isinstance(written, s.Text) and written.text == name:
            return rename(written.where, name, meant, unique=sole_typo(name, known) == meant)
    return None


@functools.lru_cache(maxsize=64)
def _arguments_at(include: a.Include) -> dict[Span, list[a.IncludeArg]]:
    """Return an include's arguments by where each is written (1,500 are read once)."""
    found: dict[Span, list[a.IncludeArg]] = {}
    for argument in include.arguments:
        found.setdefault(argument.span, []).append(argument)
    return found


def applied_inside(graph: LaunchGraph, include: IncludeRecord, name: str,
                   value: Sub) -> object | None:
    """Return the value passed for ``name`` when the included nodes set that parameter so.

    Every node of the include's subtree that receives a parameter ``name`` receives the
    value passed (typed as a parameter), and at least one does: the argument restates what
    the target does anyway. ``None`` otherwise, or when a value is not known.
    """
    text = graph.base(value)
    if text is None:
        return None
    wanted = typed_parameter(text)
    inside = (*include.origin.chain, include.origin.span)
    seen = False
    for node in graph.nodes:
        if node.origin.chain[:len(inside)] != inside:
            continue
        winner = effective_parameters(graph, node).winner(name)
        if winner is None:
            continue
        if type(winner.value) is not type(wanted) or winner.value != wanted:
            return None
        seen = True
    return wanted if seen else None


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
