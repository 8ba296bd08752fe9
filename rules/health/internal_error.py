"""LV005 internal-error."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

from launchverify.graph import LaunchGraph
from launchverify.problems import ProblemKind
from launchverify.rule import Finding, Rule, RuleContext, Severity
from launchverify.span import Span


class InternalError(Rule):
    """launchverify itself failed on this file; the rest of the check went on.

    ## What it does
    Reports a failure of launchverify, not of your launch file: an exception while
    evaluating a file, or a rule that failed on one launch. The check completes for every
    other file and rule, and fails (exit status 1) so that the gap is not mistaken for a
    clean result.

    ## Why it matters
    What launchverify could not evaluate or check on this file is unknown: it may hide
    findings.

    ## Example
    A rule raising `RecursionError` on an unusually deep include tree.

    ## Fix
    Please report it with the launch file (and the message): it is a bug of launchverify.
    Until it is fixed, `--ignore LV005` or a per-file ignore lets the check pass.
    """

    code = "LV005"
    slug = "internal-error"
    severity = Severity.ERROR
    message = "{text}; this is a bug of launchverify, please report it"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        for record in graph.problems:
            if record.problem.kind is ProblemKind.INTERNAL:
                yield self.finding(record.origin, text=record.problem.message)

    def rule_failed(self, code: str, file: Path, error: BaseException) -> Finding:
        """Return the finding for a rule that raised while checking a launch of ``file``."""
        return self.finding(Span.of_file(file),
                            text=f"rule {code} failed on this launch ({describe(error)})")


def describe(error: BaseException) -> str:
    """Return an exception as one short line."""
    text = str(error).splitlines()[0][:200] if str(error) else ""
    return f"{type(error).__name__}: {text}" if text else type(error).__name__
