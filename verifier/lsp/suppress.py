"""Where a "suppress on this line" comment goes, in each file format's own syntax.

``# launchverify: ignore[LV101]`` ends a Python or YAML line; ``<!-- launchverify:
ignore[LV101] -->`` ends an XML line, or stands alone on the line above a tag that goes
on over several lines (a comment alone covers the next line with content). A code is
added to a comment already on the line. No edit is offered where a comment would change
the file's meaning or break it: inside a multi-line string or scalar, after a backslash
continuation, inside an XML tag.
"""

from __future__ import annotations

import io
import tokenize
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import yaml

from launchverify.findings.suppressions import comment_pattern


@dataclass(frozen=True)
class Insertion:
    """Text to insert at a 1-based line and character column."""

    line: int
    column: int
    text: str


def suppression(path: Path, lines: Sequence[str], line: int, code: str) -> Insertion | None:
    """Return the insertion that silences ``code`` on ``line`` (``None`` where none fits)."""
    if not 0 < line <= len(lines):
        return None
    text = lines[line - 1]
    existing = next(iter(comment_pattern(path).finditer(text)), None)
    if existing is not None:
        codes = existing.group("codes")
        if codes is None or code in {c.strip() for c in codes.split(",")}:
            return None  # it already covers the code: nothing to add
        end = existing.end("codes")
        separator = ", " if codes.strip() else ""
        return Insertion(line, end + 1, f"{separator}{code}")
    end = len(text.rstrip()) + 1
    suffix = path.suffix.lower()
    if suffix == ".xml":
        return _xml(text, line, end, code)
    if suffix == ".py":
        return Insertion(line, end, f"  # launchverify: ignore[{code}]") \
            if _python_line_ends(lines, line) else None
    return Insertion(line, end, f"  # launchverify: ignore[{code}]") \
        if _yaml_line_ends(lines, line) else None


def _xml(text: str, line: int, end: int, code: str) -> Insertion | None:
    comment = f"<!-- launchverify: ignore[{code}] -->"
    stripped = text.strip()
    if not stripped.startswith("<"):
        return None  # an attribute of a tag written over several lines
    if stripped.endswith(">"):
        return Insertion(line, end, f" {comment}")
    indent = text[: len(text) - len(text.lstrip())]
    return Insertion(line, 1, f"{indent}{comment}\n")


def _python_line_ends(lines: Sequence[str], line: int) -> bool:
    """Return whether a comment can end this line: no string or backslash goes on after it."""
    if lines[line - 1].rstrip().endswith("\\"):
        return False
    source = "\n".join(lines) + "\n"
    try:
        for token in tokenize.generate_tokens(io.StringIO(source).readline):
            if token.start[0] <= line < token.end[0]:
                return False  # a string over several lines
            if token.start[0] > line:
                return True
    except (tokenize.TokenError, SyntaxError):
        return False  # the text cannot be read that far: do not guess
    return True


def _yaml_line_ends(lines: Sequence[str], line: int) -> bool:
    """Return whether a comment can end this line: no scalar goes on over its end."""
    try:
        for token in yaml.scan("\n".join(lines) + "\n", Loader=yaml.SafeLoader):
            start, end = token.start_mark.line + 1, token.end_mark.line + 1
            if isinstance(token, yaml.ScalarToken) and start <= line < end:
                return False
            if start > line:
                break
    except yaml.YAMLError:
        return False
    return True
