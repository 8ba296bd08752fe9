"""Stable identities of findings, robust to lines moving: baselines and SARIF use them.

A finding is identified by the SHA-256 (hex) of, each followed by a NUL byte: its code;
its file relative to a base folder (posix; absolute when outside it); the text of the line
it points at, stripped (empty when unreadable); its message with line numbers blanked
(``file.xml:12`` and ``line 12`` become ``file.xml:#`` and ``line #``, since messages point
at other places by line) and the files it names reduced to their names (a message shows
a path relative to the working directory, or absolute: a baseline written at the
workspace root must hold when checked from a package folder); and the occurrence number
(0, 1, ...) of those fields among the findings, in report order, so identical findings on
identical lines stay apart. No line or column number takes part: inserting lines above a
finding keeps its fingerprint.
"""

from __future__ import annotations

import hashlib
import re
from collections import Counter
from collections.abc import Iterable
from pathlib import Path

from launchverify.rule import Finding
from launchverify.workspace.paths import relative_file
from launchverify.workspace.sources import source_line

_LINE_REFERENCE = re.compile(r"(?<=\S):\d+\b")
_LINE_WORD = re.compile(r"\b(lines?) \d+\b")
# a path to a file (folders, then a name with an extension); ROS names have no extension
_FILE_PATH = re.compile(r"(?:[^\s'\"():,]*/)+(?P<name>[^\s/'\"():,]+\.[A-Za-z0-9]+)")


def fingerprint_fields(finding: Finding, base: Path, legacy: bool = False
                       ) -> tuple[str, ...]:
    """Return what a fingerprint hashes, but for the occurrence number.

    ``legacy``: as before file names in messages were reduced (baselines written by
    launchverify 0.1.0 still match).
    """
    message = _LINE_WORD.sub(r"\1 #", _LINE_REFERENCE.sub(":#", finding.message))
    if not legacy:
        message = _FILE_PATH.sub(r"\g<name>", message)
    return (finding.code, relative_file(finding.span.file, base),
            source_line(finding.span.file, finding.span.line),
            message)


def fingerprints(findings: Iterable[Finding], base: Path, legacy: bool = False) -> list[str]:
    """Return each finding's fingerprint (hex sha256), in the order given."""
    seen: Counter[tuple[str, ...]] = Counter()
    out = []
    for finding in findings:
        fields = fingerprint_fields(finding, base, legacy)
        digest = hashlib.sha256()
        for field in (*fields, str(seen[fields])):
            digest.update(_field_bytes(field))
            digest.update(b"\0")
        seen[fields] += 1
        out.append(digest.hexdigest())
    return out


def _field_bytes(field: str) -> bytes:
    """Return a field's bytes: a file name's undecodable byte as itself.

    A lone surrogate that no file name decodes to (a Python launch file built it) has
    no such byte: it is hashed by its code point (``surrogatepass``).
    """
    try:
        return field.encode("utf-8", errors="surrogateescape")
    except UnicodeEncodeError:
        return field.encode("utf-8", errors="surrogatepass")
