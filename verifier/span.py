"""Source locations: every IR record, problem and finding points back at the user's file."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path


@dataclass(frozen=True, slots=True)
class Span:
    """A region of a source file; lines and columns are 1-based.

    ``file`` is absolute; reporters turn it back into the path the user gave.
    """

    file: Path
    line: int
    column: int = 1
    end_line: int | None = None
    end_column: int | None = None

    def short(self) -> str:
        """Return ``name:line`` for messages that point at another place."""
        return f"{self.file.name}:{self.line}"

    @classmethod
    def of_file(cls, file: Path) -> Span:
        """Return a span for a whole file (its first line)."""
        return cls(file, 1, 1)


def character_column(line: bytes, offset: int) -> int:
    """Return the 1-based character column of a 0-based UTF-8 byte ``offset`` in ``line``.

    Python counts a line's bytes (``ast`` offsets, code positions, tracebacks); spans,
    code frames, fixes and editors count characters. ASCII lines are the same both ways.

    Examples:
        >>> character_column("x = 'é'; y".encode(), 9), character_column(b"abc", 2)
        (9, 3)
    """
    if line.isascii():
        return offset + 1
    return len(line[:offset].decode("utf-8", "ignore")) + 1

