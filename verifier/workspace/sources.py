"""Source text of checked files for reporters: code frames, fingerprints, suppressions.

Cached per file version (path, size, modification time), so a long-lived process (a
pytest session running ``main_with_errors``) never shows a stale line.
"""

from __future__ import annotations

from functools import lru_cache
from pathlib import Path

from launchverify.workspace.reading import limit, read_text, unsaved


def source_lines(path: Path) -> tuple[str, ...]:
    """Return a file's lines (undecodable bytes replaced; empty when unreadable)."""
    buffered = unsaved(path)
    if buffered is not None:  # an editor's buffer: what the findings point into
        return tuple(buffered.decode("utf-8", "replace").splitlines())
    try:
        stat = path.stat()
    except OSError:
        return ()
    return _read(path, stat.st_size, stat.st_mtime_ns)


def source_line(path: Path, number: int) -> str:
    """Return line ``number`` of a file, stripped ('' when there is no such line)."""
    lines = source_lines(path)
    return lines[number - 1].strip() if 0 < number <= len(lines) else ""


@lru_cache(maxsize=512)
def _read(path: Path, size: int, modified: int) -> tuple[str, ...]:
    try:
        text = read_text(path, prefix=limit())
    except OSError:
        return ()
    return () if "\x00" in text else tuple(text.splitlines())  # no frame from a binary
