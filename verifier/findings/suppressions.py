"""Inline suppressions: ``# launchverify: ignore[LV101]`` and ``<!-- launchverify: ignore -->``.

Python and YAML files use a ``#`` comment (in Python, a real one: not text in a string),
XML files an XML comment. A comment after code
covers its own line; a comment alone on its line covers the next line with content (as
the corpus markers do). Without ``[...]`` it covers every rule. Codes, slugs and prefixes
are accepted, as in ``--select``.
"""

from __future__ import annotations

import io
import re
import tokenize
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
    """One suppression comment and the findings it silenced.

    For a fix, ``removal`` is what to delete to take the comment out cleanly (its whole
    line when it stands alone; ``None`` when that cannot be said exactly, such as a ``#``
    inside a Python string), ``removal_safe`` whether that deletes nothing else (free
    text after the directive would go too), and ``codes_at`` where the text between its
    brackets is.
    """

    span: Span
    selectors: tuple[str, ...]  # empty: every rule
    lines: frozenset[int]
    used: int = 0
    codes: frozenset[str] = field(default_factory=frozenset)  # resolved; empty: every rule
    unknown: tuple[str, ...] = ()  # selectors that name no rule
    resolved: dict[str, frozenset[str]] = field(default_factory=dict)  # selector -> codes
    silenced: set[str] = field(default_factory=set)  # codes of the findings it silenced
    removal: Span | None = None
    removal_safe: bool = True
    codes_at: Span | None = None

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

    def unused_selectors(self) -> list[str]:
        """Return the known selectors that silenced none of the findings it covered."""
        return [selector for selector in self.selectors
                if selector in self.resolved and not self.resolved[selector] & self.silenced]


def comment_pattern(path: Path) -> re.Pattern[str]:
    """Return the pattern of a suppression comment in this file's format (``codes`` group)."""
    return _XML if path.suffix.lower() == ".xml" else _HASH


@dataclass(frozen=True)
class _Comment:
    """A suppression comment found in a file's text (see ``Suppression``)."""

    line: int
    column: int
    end_column: int
    codes: str | None
    alone: bool
    following: int
    removal: tuple[int, int, int, int] | None  # line, column, end line, end column
    removal_safe: bool
    codes_at: tuple[int, int] | None  # columns on ``line``


def _scan_text(path: Path) -> tuple[_Comment, ...]:
    """Return the suppression comments of a file, with what deleting each would take."""
    lines = source_lines(path)
    xml = path.suffix.lower() == ".xml"
    pattern = comment_pattern(path)
    python = path.suffix.lower() == ".py"
    comments = None  # where a Python file's comments are, once one line is a candidate
    tokenized = False
    found = []
    for index, text in enumerate(lines):
        if "launchverify" not in text:
            continue
        if python and not tokenized:
            comments, tokenized = _python_comments(path), True
        for match in pattern.finditer(text):
            if comments is not None and (index + 1, match.start()) not in comments:
                continue  # inside a Python string: not a comment
            alone = not text[: match.start()].strip()
            following = next((j + 1 for j in range(index + 1, len(lines)) if lines[j].strip()),
                             index + 1)
            # what is surely a comment can be deleted; a Python file that does not tokenize
            # has none that is sure
            removable = xml or (comments is not None if python
                                else _yaml_comment(text, match.start()))
            removal, safe = (_removal(text, match, index + 1, len(lines), xml) if removable
                             else (None, False))
            codes_at = ((match.start("codes") + 1, match.end("codes") + 1)
                        if match.group("codes") is not None else None)
            found.append(_Comment(index + 1, match.start() + 1, match.end() + 1,
                                  match.group("codes"), alone, following, removal, safe,
                                  codes_at))
    return tuple(found)


def _removal(text: str, match: re.Match[str], line: int, count: int, xml: bool
             ) -> tuple[tuple[int, int, int, int], bool]:
    """Return what to delete to take a comment out (columns 1-based, end exclusive).

    Alone on its line: the line. After code: the comment and the blanks before it. Before
    another comment: the directive and the blanks after it. A ``#`` directive followed by
    free text takes that text with it (not safe: it deletes the user's words).
    """
    before, rest = text[: match.start()], text[match.end():]
    if rest.strip() and (xml or rest.lstrip().startswith("#")):
        blanks = len(rest) - len(rest.lstrip())
        return (line, match.start() + 1, line, match.end() + blanks + 1), True
    safe = not rest.strip()
    if before.strip():
        return (line, len(before.rstrip()) + 1, line, len(text) + 1), safe
    if line < count:
        return (line, 1, line + 1, 1), safe
    return (line, 1, line, len(text) + 1), safe


def _yaml_comment(text: str, column: int) -> bool:
    """Return whether a YAML ``#`` surely starts a comment: after a blank, outside quotes."""
    before = text[:column]
    return (not before or before[-1].isspace()) and before.count('"') % 2 == 0 \
        and before.count("'") % 2 == 0


def _python_comments(path: Path) -> set[tuple[int, int]] | None:
    """Return where the comments of a Python file start (line, 0-based column in text)."""
    lines = source_lines(path)
    try:
        tokens = list(tokenize.generate_tokens(io.StringIO("\n".join(lines) + "\n").readline))
    except (tokenize.TokenError, SyntaxError):
        return None
    return {token.start for token in tokens if token.type == tokenize.COMMENT}


def scan(path: Path) -> list[Suppression]:
    """Return the suppression comments of one file."""
    out = []
    for comment in _scan_text(path):
        selectors = tuple(c.strip() for c in (comment.codes or "").split(",") if c.strip())
        resolved: dict[str, frozenset[str]] = {}
        unknown = []
        for selector in selectors:
            try:
                resolved[selector] = frozenset(rule.code for rule in resolve(selector))
            except RegistryError:
                unknown.append(selector)
        line = comment.line
        covered = {line, comment.following} if comment.alone else {line}
        removal = None if comment.removal is None else Span(path, *comment.removal)
        codes_at = None if comment.codes_at is None else Span(
            path, line, comment.codes_at[0], line, comment.codes_at[1])
        out.append(Suppression(
            Span(path, line, comment.column, line, comment.end_column), selectors,
            frozenset(covered), codes=frozenset().union(*resolved.values()),
            unknown=tuple(unknown), resolved=resolved, removal=removal,
            removal_safe=comment.removal_safe, codes_at=codes_at))
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
            suppression.silenced.add(finding.code)
        if not covering:
            kept.append(finding)
    return kept, [s for comments in by_file.values() for s in comments]
