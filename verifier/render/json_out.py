r"""``check --format json``: the machine-readable contract documented in docs/output.md.

Values are exact but for what has no UTF-8 form, shown as text (``encodable``): a file
name's undecodable byte as ``\xff``, a lone surrogate as ``\ud800``.
"""

from __future__ import annotations

from typing import Any, TextIO

from launchverify import __version__
from launchverify.engine import Report
from launchverify.render.encodable import write_json
from launchverify.render.links import rule_url
from launchverify.rule import Finding, Fix, Severity
from launchverify.workspace.paths import display_path


def finding_dict(finding: Finding, report: Report) -> dict[str, Any]:
    """Return one finding as a JSON object."""
    span = finding.span
    return {
        "code": finding.code,
        "slug": finding.slug,
        "severity": finding.severity.value,
        "message": finding.message,
        "file": report.display_path(span.file),
        "line": span.line,
        "column": span.column,
        "end_line": span.end_line if span.end_line is not None else span.line,
        "end_column": span.end_column if span.end_column is not None else span.column,
        "related": [
            {"file": report.display_path(r.span.file), "line": r.span.line, "message": r.message}
            for r in finding.related
        ],
        "include_chain": [
            {"file": report.display_path(s.file), "line": s.line} for s in finding.chain
        ],
        "witness": dict(finding.witness) if finding.witness else None,
        "trace": [
            {"step": step.text,
             "file": report.display_path(step.span.file) if step.span else None,
             "line": step.span.line if step.span else None}
            for step in finding.trace
        ],
        "fix": fix_dict(finding.fix, report),
        "url": rule_url(finding.code),
    }


def fix_dict(fix: Fix | None, report: Report) -> dict[str, Any] | None:
    """Return a finding's fix as a JSON object (``None`` when it has none)."""
    if fix is None:
        return None
    return {
        "applicability": fix.applicability.value,
        "message": fix.message,
        "edits": [{"file": report.display_path(edit.span.file), "line": edit.span.line,
                   "column": edit.span.column, "end_line": edit.span.end_line,
                   "end_column": edit.span.end_column, "content": edit.content}
                  for edit in fix.edits],
    }


def not_judged(report: Report) -> list[dict[str, Any]]:
    """Return where evaluations were incomplete: absence claims are not made through these."""
    out = [{"file": report.display_path(span.file), "line": span.line, "reason": reason}
           for reason, span in report.not_judged()]
    return sorted(out, key=lambda item: (item["file"], item["line"], item["reason"]))


def render_json(report: Report, out: TextIO) -> None:
    """Write the report as one JSON object."""
    counts = {s: sum(1 for f in report.findings if f.severity is s) for s in Severity}
    coverage = report.coverage()
    found = report.workspace
    document = {
        "tool": {"name": "launchverify", "version": __version__},
        "workspace": None if found is None else {"path": display_path(found.folder),
                                                 "how": found.how},
        "findings": [finding_dict(f, report) for f in report.findings],
        "not_judged": not_judged(report),
        "summary": {
            "files": report.files,
            "errors": counts[Severity.ERROR],
            "warnings": counts[Severity.WARNING],
            "infos": counts[Severity.INFO],
            "seconds": round(report.seconds, 3),
            "cached": report.cached,
            "baselined": report.baselined,
            "not_followed": {
                "includes": coverage.includes,
                "packages": len(coverage.packages),
                "package_names": [name for name, _ in coverage.packages],
            },
        },
    }
    write_json(document, out)
