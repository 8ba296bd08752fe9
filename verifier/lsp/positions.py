"""Spans (1-based, end exclusive) to LSP positions (0-based, in the client's code units).

Columns of spans count characters, in every language (the Python frontend converts
Python's UTF-8 byte offsets where it reads them). LSP counts UTF-16 code units unless
the client negotiated UTF-8 or UTF-32. Everything is converted against the text the span was
computed from, so a line with ``é`` or an emoji still underlines the right characters.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from lsprotocol import types

from launchverify.span import Span

UTF8, UTF16, UTF32 = "utf-8", "utf-16", "utf-32"


def _units(text: str, encoding: str) -> int:
    """Return how many code units of ``encoding`` the text takes."""
    if encoding == UTF8:
        return len(text.encode("utf-8", "surrogatepass"))
    if encoding == UTF32:
        return len(text)
    return len(text) + sum(1 for char in text if ord(char) > 0xFFFF)


@dataclass(frozen=True)
class Lines:
    """One file's lines as a span was computed against, and how to count in them."""

    lines: Sequence[str]
    encoding: str = UTF16  # what the client counts

    def _line(self, number: int) -> str:
        return self.lines[number - 1] if 0 < number <= len(self.lines) else ""

    def _index(self, text: str, column: int) -> int:
        """Return the character index of a 1-based span column in a line."""
        return min(max(column - 1, 0), len(text))

    def position(self, line: int, column: int) -> types.Position:
        """Return the LSP position of a 1-based line and span column."""
        line = max(line, 1)
        if line > len(self.lines):  # past the text (it changed): its end
            return types.Position(line=len(self.lines), character=0)
        text = self._line(line)
        return types.Position(line=line - 1,
                              character=_units(text[: self._index(text, column)], self.encoding))

    def range(self, span: Span) -> types.Range:
        """Return a span's range; without an end, to the end of its first line's content."""
        start = self.position(span.line, span.column)
        if span.end_line is not None and span.end_column is not None and (
                (span.end_line, span.end_column) > (span.line, span.column)):
            return types.Range(start=start, end=self.position(span.end_line, span.end_column))
        text = self._line(span.line).rstrip()
        end = types.Position(line=start.line, character=_units(text, self.encoding))
        if end.character <= start.character:  # nothing after it: one character
            end = types.Position(line=start.line, character=start.character + 1)
        return types.Range(start=start, end=end)

    def column(self, position: types.Position) -> tuple[int, int]:
        """Return the 1-based line and span column of an LSP position."""
        text = self._line(position.line + 1)
        index, counted = 0, 0
        while index < len(text) and counted < position.character:
            counted += _units(text[index], self.encoding)
            index += 1
        return position.line + 1, index + 1

