"""A trace: the steps that lead to a finding, each with where it is written (if anywhere)."""

from __future__ import annotations

from dataclasses import dataclass

from launchverify.span import Span


@dataclass(frozen=True, slots=True)
class Step:
    """One step of a trace: what happens, and the place in a launch file that makes it."""

    text: str
    span: Span | None = None
