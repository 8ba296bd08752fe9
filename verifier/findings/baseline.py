"""Baselines: adopt launchverify on a large workspace and fail only on new findings.

``--write-baseline FILE`` records the fingerprints of today's findings (see
``fingerprint.py``: robust to lines moving); ``--baseline FILE`` drops findings whose
fingerprint is recorded, as many times as it is recorded. Paths are relative to the
baseline file's folder, so the file can be committed.

A committed baseline is the pull request's, like the launch files: it is read with their
bounded reader (a regular file, never a device or FIFO, at most ``MAX_BYTES``) and its
nesting is bounded before JSON decodes it (Python's decoder recurses), so a link to
``/dev/zero`` or a document nested 100,000 deep is a usage error at once. It is written
through ``process.outputs``: never through a link.
"""

from __future__ import annotations

import json
import os
import re
from collections import Counter
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from launchverify import __version__
from launchverify.findings.fingerprint import fingerprints
from launchverify.rule import Finding
from launchverify.workspace import reading
from launchverify.workspace.paths import relative_file, resolved

MAX_BYTES = 50 * 1000 * 1000  # about 250,000 findings; not --max-file-size (launch files')
MAX_DEPTH = 32  # the format nests 3 deep: document, list of findings, finding
_NOT_BRACKETS = bytes(byte for byte in range(256) if byte not in b"[]{}")
_PAIR = re.compile(rb"\[\]|\{\}")


class BaselineError(ValueError):
    """A baseline file that cannot be read (exit status 2)."""


def write_baseline(path: Path, findings: list[Finding], *,
                   inside: Iterable[str | os.PathLike[str]] = ()) -> None:
    """Record every finding's fingerprint in ``path`` (``inside``: see ``write_file``)."""
    from launchverify.process.outputs import write_file  # (only when writing: start-up)

    base = resolved(path).parent
    entries = [
        {"fingerprint": print_, "code": f.code, "file": relative_file(f.span.file, base),
         "message": f.message}
        for f, print_ in zip(findings, fingerprints(findings, base), strict=True)
    ]
    document = {"tool": "launchverify", "version": __version__, "findings": entries}
    write_file(path, json.dumps(document, indent=1) + "\n", inside=inside)


def apply_baseline(path: Path, findings: list[Finding]) -> tuple[list[Finding], int]:
    """Return the findings not recorded in the baseline, and how many were dropped."""
    recorded = _recorded(path)
    kept = []
    base = resolved(path).parent
    for finding, print_, old in zip(findings, fingerprints(findings, base),
                                    fingerprints(findings, base, legacy=True), strict=True):
        for candidate in (print_, old):  # an older baseline holds the legacy ones
            if recorded[candidate] > 0:
                recorded[candidate] -= 1
                break
        else:
            kept.append(finding)
    return kept, len(findings) - len(kept)


def _recorded(path: Path) -> Counter[str]:
    """Return how many times the baseline records each fingerprint."""
    try:
        data = reading.read_file(path, prefix=MAX_BYTES + 1, anywhere=True)
    except OSError as error:
        raise BaselineError(f"cannot read baseline {str(path)!r}: "
                            f"{error.strerror or error}") from None
    if len(data) > MAX_BYTES:
        raise BaselineError(f"{str(path)!r} is not a launchverify baseline: larger than "
                            f"{MAX_BYTES // 1000 // 1000} MB")
    if not _nested_at_most(data, MAX_DEPTH):
        raise BaselineError(f"{str(path)!r} is not a launchverify baseline: not JSON, or "
                            f"nested deeper than {MAX_DEPTH} levels")
    try:
        document: Any = json.loads(data.decode("utf-8"))
        return Counter(str(e["fingerprint"]) for e in document["findings"])
    except (ValueError, KeyError, TypeError, RecursionError) as error:
        raise BaselineError(f"{str(path)!r} is not a launchverify baseline") from error


def _nested_at_most(data: bytes, most: int) -> bool:
    """Return whether JSON ``data``'s brackets nest at most ``most`` deep, and match.

    Linear in C, never recursive: strings are taken out (their escaped backslashes and
    quotes first, so every quote left opens or closes one), then the innermost pairs of
    the brackets left are removed once per level. Brackets left over are too deep, or
    do not match (no JSON then either).
    """
    plain = data.replace(b"\\\\", b"").replace(b'\\"', b"")
    brackets = b"".join(plain.split(b'"')[::2]).translate(None, _NOT_BRACKETS)
    for _ in range(most):
        if not brackets:
            return True
        inner = _PAIR.sub(b"", brackets)
        if len(inner) == len(brackets):
            return False
        brackets = inner
    return not brackets
