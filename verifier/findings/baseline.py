"""Baselines: adopt launchverify on a large workspace and fail only on new findings.

``--write-baseline FILE`` records the fingerprints of today's findings (see
``fingerprint.py``: robust to lines moving); ``--baseline FILE`` drops findings whose
fingerprint is recorded, as many times as it is recorded. Paths are relative to the
baseline file's folder, so the file can be committed.
"""

from __future__ import annotations

import json
import os
from collections import Counter
from collections.abc import Iterable
from pathlib import Path

from launchverify import __version__
from launchverify.findings.fingerprint import fingerprints
from launchverify.process.outputs import write_file
from launchverify.rule import Finding
from launchverify.workspace.paths import relative_file, resolved


class BaselineError(ValueError):
    """A baseline file that cannot be read (exit status 2)."""


def write_baseline(path: Path, findings: list[Finding], *,
                   inside: Iterable[str | os.PathLike[str]] = ()) -> None:
    """Record every finding's fingerprint in ``path`` (``inside``: see ``write_file``)."""
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
    try:
        document = json.loads(path.read_text(encoding="utf-8"))
        recorded = Counter(str(e["fingerprint"]) for e in document["findings"])
    except OSError as error:
        raise BaselineError(f"cannot read baseline {str(path)!r}: {error.strerror}") from error
    except (ValueError, KeyError, TypeError) as error:
        raise BaselineError(f"{str(path)!r} is not a launchverify baseline") from error
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
