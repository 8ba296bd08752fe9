r"""``check --format sarif``: SARIF 2.1.0, the format GitHub code scanning uploads.

One run; its driver lists every registered rule (so a viewer can show a rule's help even
for findings from an older run), and each finding becomes a result with its location,
its related places, the include chain ("included from here") and, for lifecycle findings,
the trace as a code flow. Paths below ``root`` (the working directory unless given) are
relative URIs against ``%SRCROOT%``, which is what code scanning maps onto the checkout;
other files get absolute ``file://`` URIs.

A finding with a fix has ``fixes``: one ``artifactChange`` per file it edits, each edit a
``replacement`` (the region deleted, end exclusive as ours; the text inserted), and
``properties.applicability`` (``safe``, or ``unsafe``: applied only with
``--unsafe-fixes``).

Fingerprints: ``partialFingerprints["launchverify/v1"]`` lets a viewer recognise a
finding again after edits elsewhere in the file moved it; the recipe (shared with
baselines) is in ``launchverify.findings.fingerprint``, with paths relative to the root.

What has no UTF-8 form is shown as text (``encodable``): an undecodable file-name byte as
``\xff`` and a lone surrogate as ``\ud800`` in messages; in a URI, such a byte is
percent-encoded as itself (``%FF``), so the URI still names the file.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any, TextIO
from urllib.parse import quote_from_bytes

from launchverify import __version__
from launchverify.engine import Report
from launchverify.findings.fingerprint import fingerprints
from launchverify.registry import all_rules
from launchverify.render import links
from launchverify.render.encodable import path_bytes, write_json
from launchverify.rule import Finding, Fix, Rule, Severity
from launchverify.span import Span

SCHEMA_URI = (
    "https://docs.oasis-open.org/sarif/sarif/v2.1.0/errata01/os/schemas/sarif-schema-2.1.0.json"
)
HOME_URI = "https://github.com/launchverify/launchverify"
SRCROOT = "%SRCROOT%"
FINGERPRINT = "launchverify/v1"
LEVELS = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "note"}



def pascal(slug: str) -> str:
    """Return ``DuplicateNodeName`` for ``duplicate-node-name`` (SARIF's rule ``name``)."""
    return "".join(part.capitalize() for part in slug.split("-"))


def section(documentation: str, heading: str) -> str:
    """Return one ``## heading`` section of a rule's documentation, paragraphs reflowed."""
    lines = documentation.splitlines()
    try:
        start = lines.index(f"## {heading}") + 1
    except ValueError:
        return ""
    body: list[str] = []
    for line in lines[start:]:
        if line.startswith("## "):
            break
        body.append(line)
    paragraphs = "\n".join(body).strip().split("\n\n")
    return "\n\n".join(" ".join(p.split()) for p in paragraphs if p.strip())


def rule_tags(rule: type[Rule]) -> list[str]:
    """Return the tags of a rule: its family (the ``rules/`` folder) when it is built in."""
    parts = rule.__module__.split(".")
    family = parts[2] if parts[:2] == ["launchverify", "rules"] and len(parts) > 3 else None
    return ["ros2-launch", family] if family else ["ros2-launch"]


def rule_descriptor(rule: type[Rule], base: str | None) -> dict[str, Any]:
    """Return the ``reportingDescriptor`` of one rule."""
    documentation = rule.documentation() or rule.slug
    summary = documentation.splitlines()[0]
    descriptor: dict[str, Any] = {
        "id": rule.code,
        "name": pascal(rule.slug),
        "shortDescription": {"text": summary},
        "fullDescription": {"text": section(documentation, "What it does") or summary},
        "help": {"text": documentation, "markdown": documentation},
    }
    uri = links.help_uri(rule, base)
    if uri is not None:
        descriptor["helpUri"] = uri
    descriptor["defaultConfiguration"] = {"level": LEVELS[rule.severity]}
    descriptor["properties"] = {"tags": rule_tags(rule)}
    return descriptor


def message_text(finding: Finding) -> str:
    """Return the message, with the argument values that make it happen when known."""
    if not finding.witness:
        return finding.message
    values = " ".join(f"{k}:={v}" for k, v in sorted(finding.witness.items()))
    return f"{finding.message} (when: {values})"


def region(span: Span) -> dict[str, int]:
    """Return a SARIF region; SARIF columns, like ours, end after the last character."""
    start_line, start_column = max(span.line, 1), max(span.column, 1)
    area = {"startLine": start_line, "startColumn": start_column}
    end_line = max(span.end_line or start_line, start_line)
    if end_line > start_line:
        area["endLine"] = end_line
    if span.end_column is not None and (end_line > start_line
                                        or span.end_column >= start_column):
        area["endLine"] = end_line
        area["endColumn"] = max(span.end_column, 1)
    return area


def file_uri(absolute: Path) -> str:
    """Return the ``file://`` URI of an absolute path (``Path.as_uri``, for any name)."""
    return "file://" + quote_from_bytes(path_bytes(absolute.as_posix()))


class Places:
    """Turns spans into SARIF locations relative to the root; reads source lines once."""

    def __init__(self, root: Path) -> None:
        self.root = Path(os.path.realpath(root))

    def path(self, file: Path) -> tuple[str, bool]:
        """Return the file's POSIX path and whether it is relative to the root."""
        absolute = Path(os.path.realpath(file))
        try:
            return absolute.relative_to(self.root).as_posix(), True
        except ValueError:
            return absolute.as_posix(), False

    def artifact(self, file: Path) -> dict[str, str]:
        """Return an ``artifactLocation``."""
        path, relative = self.path(file)
        if relative:
            return {"uri": quote_from_bytes(path_bytes(path)), "uriBaseId": SRCROOT}
        return {"uri": file_uri(Path(os.path.realpath(file)))}

    def location(self, span: Span, message: str | None = None,
                 number: int | None = None) -> dict[str, Any]:
        """Return a ``location`` for a span, with an id and a message when given."""
        location: dict[str, Any] = {}
        if number is not None:
            location["id"] = number
        location["physicalLocation"] = {
            "artifactLocation": self.artifact(span.file), "region": region(span),
        }
        if message is not None:
            location["message"] = {"text": message}
        return location


def code_flow(finding: Finding, places: Places) -> dict[str, Any]:
    """Return the trace as one thread flow; a step written nowhere has only a message."""
    steps = [
        {"location": places.location(step.span, step.text) if step.span is not None
         else {"message": {"text": step.text}}}
        for step in finding.trace
    ]
    return {"message": {"text": "how the launch gets there"},
            "threadFlows": [{"locations": steps}]}


def sarif_fix(fix: Fix, places: Places) -> dict[str, Any]:
    """Return the SARIF ``fix`` of a finding: its edits grouped by file."""
    changes: dict[Path, list[dict[str, Any]]] = {}
    for edit in fix.edits:
        span = edit.span
        replacement: dict[str, Any] = {"deletedRegion": {
            "startLine": span.line, "startColumn": span.column,
            "endLine": span.end_line or span.line,
            "endColumn": span.end_column or span.column}}
        if edit.content:
            replacement["insertedContent"] = {"text": edit.content}
        changes.setdefault(span.file, []).append(replacement)
    return {
        "description": {"text": fix.message},
        "artifactChanges": [{"artifactLocation": places.artifact(file), "replacements": edits}
                            for file, edits in changes.items()],
        "properties": {"applicability": fix.applicability.value},
    }


def result(finding: Finding, index: dict[str, int], places: Places,
           fingerprint_value: str) -> dict[str, Any]:
    """Return the SARIF ``result`` of one finding."""
    entry: dict[str, Any] = {"ruleId": finding.code}
    if finding.code in index:
        entry["ruleIndex"] = index[finding.code]
    entry["level"] = LEVELS[finding.severity]
    entry["message"] = {"text": message_text(finding)}
    entry["locations"] = [places.location(finding.span)]
    related = [(r.span, r.message) for r in finding.related]
    related += [(span, "included from here") for span in finding.chain]
    if related:
        entry["relatedLocations"] = [
            places.location(span, message, number)
            for number, (span, message) in enumerate(related, 1)
        ]
    if finding.trace:
        entry["codeFlows"] = [code_flow(finding, places)]
    if finding.fix is not None and finding.fix.edits:
        entry["fixes"] = [sarif_fix(finding.fix, places)]
    entry["partialFingerprints"] = {FINGERPRINT: fingerprint_value}
    if finding.witness:
        entry["properties"] = {"witness": dict(sorted(finding.witness.items()))}
    return entry


def sarif_log(report: Report, *, root: Path | None = None) -> dict[str, Any]:
    """Return the SARIF log of a report as a JSON-ready dict."""
    places = Places(root if root is not None else Path.cwd())
    rules = all_rules()
    base = links.documentation_base()
    index = {rule.code: number for number, rule in enumerate(rules)}
    results = [result(finding, index, places, value) for finding, value in
               zip(report.findings, fingerprints(report.findings, places.root), strict=True)]
    urls = links.project_urls()
    driver = {
        "name": "launchverify",
        "version": __version__,
        "informationUri": urls.get("homepage") or urls.get("repository") or HOME_URI,
        "rules": [rule_descriptor(rule, base) for rule in rules],
    }
    run = {
        "tool": {"driver": driver},
        "originalUriBaseIds": {SRCROOT: {"uri": file_uri(places.root).rstrip("/") + "/"}},
        "columnKind": "unicodeCodePoints",
        "results": results,
    }
    return {"$schema": SCHEMA_URI, "version": "2.1.0", "runs": [run]}


def render_sarif(report: Report, out: TextIO, *, root: Path | None = None) -> None:
    """Write the report as a SARIF 2.1.0 log (paths relative to ``root``, default cwd)."""
    write_json(sarif_log(report, root=root), out)
