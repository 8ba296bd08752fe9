"""Stable identities of findings, robust to lines moving: baselines and SARIF use them.

A finding is identified by the SHA-256 (hex) of, each followed by a NUL byte: its code;
its file relative to a base folder (posix; absolute when outside it); the text of the line
it points at, stripped (empty when unreadable); its message with line numbers blanked
(``file.xml:12`` and ``line 12`` become ``file.xml:#`` and ``line #``, since messages point
at other places by line); and the occurrence number (0, 1, ...) of those fields among the
findings, in report order, so identical findings on identical lines stay apart. No line
or column number takes part: inserting lines above a finding keeps its fingerprint.
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


def fingerprint_fields(finding: Finding, base: Path) -> tuple[str, ...]:
    """Return what a fingerprint hashes, but for the occurrence number."""
    message = _LINE_WORD.sub(r"\1 #", _LINE_REFERENCE.sub(":#", finding.message))
    return (finding.code, relative_file(finding.span.file, base),
            source_line(finding.span.file, finding.span.line),
            message)


def fingerprints(findings: Iterable[Finding], base: Path) -> list[str]:
    """Return each finding's fingerprint (hex sha256), in the order given."""
    seen: Counter[tuple[str, ...]] = Counter()
    out = []
    for finding in findings:
        fields = fingerprint_fields(finding, base)
        digest = hashlib.sha256()
        for field in (*fields, str(seen[fields])):
            digest.update(field.encode("utf-8", errors="surrogateescape"))
            digest.update(b"\0")
        seen[fields] += 1
        out.append(digest.hexdigest())
    return out
