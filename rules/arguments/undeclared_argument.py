"""LV201 undeclared-argument."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.evaluate.values import performs_unset
from launchverify.graph import ConfigRead, LaunchGraph
from launchverify.ir.subst import Sub, walk
from launchverify.ir.symbolic import Select, rests_on_unknowns
from launchverify.rule import Finding, Rule, RuleContext, Severity, rename
from launchverify.smt import reasoner_for
from launchverify.suggest import typos


class UndeclaredArgument(Rule):
    """A launch configuration is read but never declared or set.

    ## What it does
    Follows the launch in execution order and reports `$(var name)` (or
    `LaunchConfiguration('name')`) without a default where no `<arg>`, `<let>`, include
    argument or command-line value has set `name` before. A file that others include,
    that declares arguments without defaults, or that declares no argument at all yet
    reads configurations (a building block, as nav2's old fragments are written) is meant
    to be included: its includers must set them, so on its own only a read one or two
    edits away from a declared name (a typo) is reported. A file that declares its
    arguments and is included by nothing is an entry point: every read it never declares
    is reported.

    A read under a condition false with the default arguments is reported with arguments
    that make it true, as launch reads it only then. A configuration set only on paths the
    arguments as given do not take (declared under a condition false with them) is
    reported where it is read with them.

    An include's arguments are read at the include: launch sets them as configurations
    before the included file runs, so a value that reads a configuration nothing sets
    fails there, and the included file runs only with arguments that set it (nothing in
    it is judged on a value it never gets).

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
        seen: set[tuple[object, ...]] = set()
        alone = graph.launchable_alone()
        # a part we cannot see may set it; off the path the arguments as given take, it does
        # not with them
        as_given = graph.complete or not graph.unseen_as_given
        if not as_given:
            return
        if alone:
            yield from self.unset_as_given(graph, seen)
        known = known_names(graph)
        declared_in = {(arg.name, arg.action.span.file) for arg in graph.arguments}
        unset = [r for r in graph.reads if not r.found and not r.has_default]
        for read in unset:
            key = (read.name, read.origin.span)
            if key in seen:
                continue
            witness = None
            runs = graph.runs(read.origin)
            if runs is not True and not graph.complete:
                continue  # other arguments may take it where launchverify does not see
            if runs is False:  # read only under a condition false now
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

    def unset_as_given(self, graph: LaunchGraph, seen: set[tuple[object, ...]]
                       ) -> Iterator[Finding]:
        """Reads of a configuration set on other paths only than the arguments as given take.

        (Declared under a condition false with them, say.) Only where the read runs with
        them and no guard that decides it rests on what launchverify cannot know.
        """
        for read in graph.reads:
            if read.value is None or read.has_default or (read.name, read.origin.span) in seen:
                continue
            if graph.runs(read.origin) is not True or decided_by_unknowns(read.value):
                continue
            if performs_unset(graph.as_facts(read.value)) is not True:
                continue
            seen.add((read.name, read.origin.span))
            yield self.finding(read.origin, name=read.name, hint=AS_GIVEN)


AS_GIVEN = (" with the arguments as given (it is set only where other argument values "
            "lead)")


def decided_by_unknowns(value: Sub) -> bool:
    """Return whether a guard of a path-dependent value rests on unknowns (the machine)."""
    return any(rests_on_unknowns(guard) for part in walk(value) if isinstance(part, Select)
               for guard in part.guards)


def known_names(graph: LaunchGraph) -> frozenset[str]:
    """Return the names a read may misspell: the declared arguments and the pinned ones."""
    return frozenset(graph.declared_names() | set(graph.pinned))


def misspelt_reads(graph: LaunchGraph, *, with_default: bool = False
                   ) -> dict[str, ConfigRead]:
    """Return the names LV201's did-you-mean points at, each with its first read.

    The reads of a configuration nothing sets, whose closest typo is a known name (what
    LV201 suggests); ``with_default``: those read with a default instead, which LV201
    does not report.
    """
    known = known_names(graph)
    meant: dict[str, ConfigRead] = {}
    for read in graph.reads:
        if read.found or read.has_default is not with_default:
            continue
        close = typos(read.name, known)
        if close:
            meant.setdefault(close[0], read)
    return meant
