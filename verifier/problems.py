"""Diagnostics produced before rules run: frontends and the evaluator record, rules report.

A frontend never reports; it records a ``Problem`` and carries on. The health rules
(LV001 parse-error, LV002 evaluation-error, LV003 unmodeled-construct) turn them into
findings, so every finding still comes from a rule module.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass

from launchverify.span import Span
from launchverify.workspace.reading import Outside


class ProblemKind(enum.Enum):
    """What went wrong, which decides the rule that reports it."""

    PARSE = "parse"
    EVALUATION = "evaluation"
    UNMODELED = "unmodeled"
    # Evaluating an action fails, on a path the arguments as given do not take (under a
    # condition false with them) or may not take (a condition on the machine): a failure
    # only with arguments that take that path, which LV002 names (a witness); none when
    # no values do (launch never evaluates it), an info (LV003) when it cannot tell.
    CONDITIONAL = "conditional"
    INTERNAL = "internal"  # launchverify failed (LV005), not the file


@dataclass(frozen=True, slots=True)
class Problem:
    """One diagnostic with where it happened."""

    kind: ProblemKind
    message: str
    span: Span
    contextual: bool = False  # may be caused by what an includer would provide
    # The rule that names this failure (LV207 for a condition launch rejects): it reports
    # it, with its explanation and severity; LV002 takes only failures no rule names.
    rule: str | None = None


@dataclass(frozen=True, slots=True)
class NotFollowed:
    """What a check could not follow, found neither in the workspace nor in an underlay.

    ``kind``: ``"include"`` (a file not read: the package its path names is found
    nowhere) or ``"package"`` (a reference to a package found nowhere: its files,
    executables and sources are not read).
    """

    kind: str
    package: str
    span: Span


class ProblemSink:
    """Collects problems while a file is parsed or evaluated."""

    def __init__(self) -> None:
        self.problems: list[Problem] = []

    def parse(self, message: str, span: Span) -> None:
        """Record that the file cannot be loaded as written (ros2 launch would fail)."""
        self.problems.append(Problem(ProblemKind.PARSE, message, span))

    def evaluation(self, message: str, span: Span, *, contextual: bool = False) -> None:
        """Record that evaluating a construct fails (ros2 launch would fail at run time).

        ``contextual``: it fails only if no includer provides what is missing.
        """
        self.problems.append(Problem(ProblemKind.EVALUATION, message, span, contextual))

    def cannot_read(self, error: OSError, span: Span, what: str = "file") -> None:
        """Record why a file was not read.

        A file outside what launchverify reads (``reading.Outside``: a link out of the
        workspace, ``/etc/passwd``) is unknown, not broken: ros2 launch may read it fine.
        """
        if isinstance(error, Outside):
            self.unmodeled(str(error), span)
        else:
            self.parse(f"cannot read {what}: {error}", span)

    def unmodeled(self, message: str, span: Span) -> None:
        """Record that launchverify does not understand a construct (analysis incomplete)."""
        self.problems.append(Problem(ProblemKind.UNMODELED, message, span))
