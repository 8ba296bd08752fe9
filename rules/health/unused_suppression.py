"""LV004 unused-suppression."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.findings.suppressions import Suppression
from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Rule, RuleContext, Severity


class UnusedSuppression(Rule):
    """A `launchverify: ignore` comment that silences nothing.

    ## What it does
    After every other rule has run and inline suppressions have been applied, reports
    each suppression comment that covered no finding, and each code in one that names no
    rule. A suppression naming only rules that did not run (`--select`, `--ignore`) is
    not judged.

    ## Why it matters
    A stale suppression hides the next real mistake on that line: the node name it was
    written for is gone, but a new duplicate there would be silenced too. A misspelt code
    never suppressed anything.

    ## Example
    ```xml
    <!-- launchverify: ignore[LV101] -->
    <node pkg="demo_nodes_cpp" exec="talker" name="talker_left"/>
    ```

    ## Fix
    Delete the comment, or correct the code it names.
    """

    code = "LV004"
    slug = "unused-suppression"
    severity = Severity.WARNING
    message = "{text}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        return iter(())  # judged after the other rules, from what suppressions silenced

    def judge(self, suppression: Suppression, ran: frozenset[str],
              every_rule_ran: bool) -> Finding | None:
        """Return the finding for a suppression that silenced nothing, if it is one."""
        if suppression.unknown:
            names = ", ".join(suppression.unknown)
            return self.finding(suppression.span,
                                text=f"suppression names no rule: {names}")
        if suppression.used:
            return None
        if suppression.selectors:
            if not suppression.codes <= ran:
                return None
            what = ", ".join(suppression.selectors)
            return self.finding(suppression.span, text=f"suppression of {what} silences "
                                "nothing on the line it covers")
        if not every_rule_ran:
            return None
        return self.finding(suppression.span,
                            text="suppression silences nothing on the line it covers")
