"""Inline suppressions: ``# launchverify: ignore[LV101]`` and ``<!-- launchverify: ignore -->``.

Python and YAML files use a ``#`` comment, XML files an XML comment. A comment after code
covers its own line; a comment alone on its line covers the next line with content (as
the corpus markers do). Without ``[...]`` it covers every rule. Codes, slugs and prefixes
are accepted, as in ``--select``.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from launchverify.registry import RegistryError, resolve
from launchverify.rule import IN_CALL, Finding
from launchverify.span import Span
from launchverify.workspace.sources import source_lines

_HASH = re.compile(r"#\s*launchverify:\s*ignore\b(?:\[(?P<codes>[^\]]*)\])?")
_XML = re.compile(r"<!--\s*launchverify:\s*ignore\b(?:\[(?P<codes>[^\]]*)\])?\s*-->")


@dataclass
class Suppression:
    """One suppression comment and the findings it silenced."""

    span: Span
    selectors: tuple[str, ...]  # empty: every rule
    lines: frozenset[int]
    used: int = 0
    codes: frozenset[str] = field(default_factory=frozenset)  # resolved; empty: every rule
    unknown: tuple[str, ...] = ()  # selectors that name no rule

    def covers(self, finding: Finding) -> bool:
        """Return whether this comment silences a finding.

        A finding inside a call (a ``LaunchConfiguration`` in ``Node(...)``'s parameters) is
        also covered by a comment on the call's first line, where it used to point.
        """
        lines = {finding.span.line}
        lines.update(r.span.line for r in finding.related
                     if r.message == IN_CALL and r.span.file == finding.span.file)
        return not self.lines.isdisjoint(lines) and (
            not self.selectors or finding.code in self.codes)


def comment_pattern(path: Path) -> re.Pattern[str]:
    """Return the pattern of a suppression comment in this file's format (``codes`` group)."""
    return _XML if path.suffix.lower() == ".xml" else _HASH


def _scan_text(path: Path) -> tuple[tuple[int, int, str | None, bool, int], ...]:
    """Return (line, column, codes text, alone on its line, covered next line) per comment."""
    lines = source_lines(path)
    pattern = comment_pattern(path)
    found = []
    for index, text in enumerate(lines):
        if "launchverify" not in text:
            continue
        for match in pattern.finditer(text):
            alone = not text[: match.start()].strip()
            following = next((j + 1 for j in range(index + 1, len(lines)) if lines[j].strip()),
                             index + 1)
            found.append((index + 1, match.start() + 1, match.group("codes"), alone,
                          following))
    return tuple(found)


def scan(path: Path) -> list[Suppression]:
    """Return the suppression comments of one file."""
    out = []
    for line, column, codes, alone, following in _scan_text(path):
        selectors = tuple(c.strip() for c in (codes or "").split(",") if c.strip())
        resolved: set[str] = set()
        unknown = []
        for selector in selectors:
            try:
                resolved.update(rule.code for rule in resolve(selector))
            except RegistryError:
                unknown.append(selector)
        covered = {line, following} if alone else {line}
        out.append(Suppression(Span(path, line, column), selectors, frozenset(covered),
                               codes=frozenset(resolved), unknown=tuple(unknown)))
    return out


def apply_suppressions(findings: list[Finding], files: Iterable[Path]
                       ) -> tuple[list[Finding], list[Suppression]]:
    """Drop the findings a comment covers; return the rest and every comment seen."""
    by_file: dict[Path, list[Suppression]] = {}
    for path in sorted(set(files) | {f.span.file for f in findings}):
        comments = scan(path)
        if comments:
            by_file[path] = comments
    kept = []
    for finding in findings:
        covering = [s for s in by_file.get(finding.span.file, ()) if s.covers(finding)]
        for suppression in covering:
            suppression.used += 1
        if not covering:
            kept.append(finding)
    return kept, [s for comments in by_file.values() for s in comments]
