"""LV003 unmodeled-construct."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.problems import ProblemKind
from launchverify.rule import Finding, Rule, RuleContext, Severity
from launchverify.rules.health.evaluation_error import conditional_witness, never_evaluated


class UnmodeledConstruct(Rule):
    """launchverify met something it does not model; the analysis there is incomplete.

    ## What it does
    Names each construct launchverify cannot evaluate statically: a launch file format it
    does not read yet, an `$(eval ...)` outside the modelled subset of Python, a loop whose
    length depends on arguments, an opaque function, a module that is not installed here,
    a command the file runs while it loads. It also names a failure that rests only on
    what launchverify assumed for a value it cannot know ("cannot tell"): evaluated again
    with the other answers (an unknown list not empty, a robot file absent), the file did
    not fail there, so it is no error (LV002) until the value is known.

    ## Why it matters
    Other rules stay quiet about what they cannot see, so a clean report covers less than
    it seems. This finding says where the blind spots are.

    ## Example
    ```xml
    <let name="n" value="$(eval '[x for x in range(3)]')"/>
    ```

    ## Fix
    Nothing is wrong with the launch file. Prefer simple, declarative constructs where you
    can; report constructs you rely on so they can be modelled.
    """

    code = "LV003"
    slug = "unmodeled-construct"
    severity = Severity.INFO
    message = "{text}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        for record in graph.problems:
            if record.problem.kind is ProblemKind.UNMODELED:
                yield self.finding(record.origin, text=record.problem.message)
            elif (record.problem.kind is ProblemKind.CONDITIONAL and record.value is None
                  and conditional_witness(graph, record) is None
                  and not never_evaluated(graph, record)):
                # under a condition false by default, and no values were found that make
                # it true (nor shown that none do): whether launch gets there is unknown
                yield self.finding(record.origin, text=(
                    f"{record.problem.message}, under a condition no argument values were "
                    "found to make true: not judged"))
