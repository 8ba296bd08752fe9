"""LV004 unused-suppression."""

from __future__ import annotations

from collections.abc import Iterator, Sequence

from launchverify.findings.suppressions import Suppression
from launchverify.graph import LaunchGraph
from launchverify.rule import Applicability, Edit, Finding, Fix, Rule, RuleContext, Severity


class UnusedSuppression(Rule):
    """A `launchverify: ignore` comment that silences nothing.

    ## What it does
    After every other rule has run and inline suppressions have been applied, reports
    each suppression comment that covered no finding, each code in one that names no
    rule, and the codes of a comment that silenced nothing when its other codes did. A
    suppression naming only rules that did not run (`--select`, `--ignore`) is not
    judged. In Python files only real comments count, not text in a string.

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

    Autofix: deletes the comment (its whole line when it stands alone), or only the codes
    that silence nothing, keeping the others and the rest of the line; safe, except when
    free text follows the directive (it would go too) or a code names no rule (a
    misspelt code may be meant): unsafe.
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
            return self.finding(suppression.span, text=f"suppression names no rule: {names}",
                                fix=_without(suppression, suppression.unknown,
                                             Applicability.UNSAFE))  # a misspelt code?
        if suppression.used:
            unused = [selector for selector in suppression.unused_selectors()
                      if suppression.resolved[selector] <= ran]
            if not unused:
                return None
            return self.finding(suppression.span, text=f"suppression of {', '.join(unused)} "
                                "silences nothing on the line it covers",
                                fix=_without(suppression, unused, Applicability.SAFE))
        if suppression.selectors:
            if not suppression.codes <= ran:
                return None
            what = ", ".join(suppression.selectors)
            return self.finding(suppression.span, text=f"suppression of {what} silences "
                                "nothing on the line it covers",
                                fix=_without(suppression, suppression.selectors,
                                             Applicability.SAFE))
        if not every_rule_ran:
            return None
        return self.finding(suppression.span,
                            text="suppression silences nothing on the line it covers",
                            fix=_without(suppression, (), Applicability.SAFE))


def _without(suppression: Suppression, selectors: Sequence[str],
             applicability: Applicability) -> Fix | None:
    """Return the fix that takes ``selectors`` out of a comment (all of them: the comment).

    The codes left keep their order and the comment's separator.
    """
    kept = [s for s in suppression.selectors if s not in selectors]
    if kept:
        if suppression.codes_at is None:
            return None
        inside = suppression.selectors
        separator = "," if len(inside) > 1 and not _spaced(suppression) else ", "
        listed = ", ".join(dict.fromkeys(selectors))
        return Fix(f"remove {listed} from the suppression",
                   (Edit(suppression.codes_at, separator.join(kept)),), applicability)
    if suppression.removal is None:
        return None
    if not suppression.removal_safe:
        applicability = Applicability.UNSAFE
    return Fix("remove the suppression comment", (Edit(suppression.removal, ""),),
               applicability)


def _spaced(suppression: Suppression) -> bool:
    """Return whether the codes in the comment's brackets are written ``A, B``."""
    at = suppression.codes_at
    width = 0 if at is None or at.end_column is None else at.end_column - at.column
    return width > len(",".join(suppression.selectors))
