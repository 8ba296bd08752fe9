"""LV403 param-type-conflict."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.parameters import Contribution, effective_parameters
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity


class ParamTypeConflict(Rule):
    """A node's parameter gets values of different types from different sources.

    ## What it does
    Resolves each node's parameters the way ROS 2 does (`set_parameter` and
    `set_parameters_from_file` in scope, then the node's own files and values; every
    matching block of every file, in the order rcl merges them) and reports a parameter
    that one source gives as, say, a double and a later one as an integer or a string. The
    finding is on the later value and names the earlier one. Values that depend on
    arguments are taken with the arguments as given.

    ## Why it matters
    The node receives the last value, with its type. A node that declares the parameter
    with the other type refuses to start (`Wrong parameter type, parameter max_vel is of
    type double, setting it to integer is not allowed`); one that reads it loosely gets a
    value its author did not expect. Typical causes: `1` instead of `1.0`, `"true"` in
    quotes, a launch file overriding a file's value with text.

    ## Example
    ```yaml
    /**:
      ros__parameters:
        max_vel: 0.5
    controller:
      ros__parameters:
        max_vel: 1        # an integer now
    ```

    ## Fix
    Write the value with the type the node declares (`1.0`, `true`), or remove the
    redundant source.
    """

    code = "LV403"
    slug = "param-type-conflict"
    severity = Severity.ERROR
    message = ("parameter {name!r} is {kind} here but {other_kind} at {other}: the node "
               "receives {winner_kind}, and one that declares it as {other_kind} refuses it")

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        for node in graph.nodes:
            if graph.runs(node.origin) is False:
                continue
            parameters = effective_parameters(graph, node)
            winners = {name: values[-1] for name, values in parameters.values.items()}
            for name, contributions in parameters.values.items():
                clash = first_clash(contributions)
                if clash is None:
                    continue
                earlier, later = clash
                label = parameters.fqn or node.executable_label()
                yield self.finding(
                    later.span,
                    related=(Related(earlier.span, f"{_article(earlier.kind)} here"),
                             Related(node.origin.span, f"for the node {label}")),
                    name=name, kind=_article(later.kind), other_kind=_article(earlier.kind),
                    other=earlier.span.short(), winner_kind=_article(winners[name].kind),
                )


def first_clash(contributions: list[Contribution]) -> tuple[Contribution, Contribution] | None:
    """Return the first (earlier, later) pair of known, different types."""
    known = [c for c in contributions if c.kind != "unknown" and not _substitution(c)]
    for index, later in enumerate(known):
        for earlier in known[:index]:
            if earlier.kind != later.kind:
                return earlier, later
    return None


def _substitution(contribution: Contribution) -> bool:
    """A file value written as ``$(var x)``: substituted at launch time, type unknown."""
    return isinstance(contribution.value, str) and "$(" in contribution.value


def _article(kind: str) -> str:
    words = kind.replace("_array", " list")
    return ("an " if words[0] in "aeiou" else "a ") + words
