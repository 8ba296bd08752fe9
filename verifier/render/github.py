"""``check --format github``: workflow commands that GitHub Actions shows as annotations.

One ``::error``/``::warning``/``::notice`` line per finding. Values are escaped as the
Actions runner unescapes them, so a message with a newline or a path with a comma
arrives intact instead of cutting the command short; other control characters (ESC,
bidi overrides) are shown visibly, never sent raw. Columns are sent only for a
finding on one line: GitHub rejects ``col`` when ``line`` and ``endLine`` differ.
"""

from __future__ import annotations

from typing import TextIO

from launchverify.engine import Report
from launchverify.findings.fixes import fix_note
from launchverify.render.inert import inert_block
from launchverify.rule import Finding, Severity

COMMANDS = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "notice"}


def escape_data(text: str) -> str:
    """Escape the message part of a workflow command (after ``::``).

    Line breaks are sent as the runner expects them; other control characters are shown
    visibly (``inert_block``): the runner prints the message to the log, a terminal of
    sorts.
    """
    return inert_block(text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A"))


def escape_property(text: str) -> str:
    """Escape a property value (``file=``, ``title=``): also ``:`` and ``,``."""
    return escape_data(text).replace(":", "%3A").replace(",", "%2C")


def annotation(finding: Finding, report: Report) -> str:
    """Return the workflow command of one finding."""
    span = finding.span
    end_line = span.end_line if span.end_line is not None else span.line
    properties = [("file", report.display_path(span.file)), ("line", str(span.line))]
    if end_line > span.line:
        properties.append(("endLine", str(end_line)))
    else:
        properties += [("col", str(span.column)), ("endLine", str(span.line))]
        if span.end_column is not None and span.end_column >= span.column:
            properties.append(("endColumn", str(span.end_column)))
    properties.append(("title", f"{finding.code} {finding.slug}{fix_note(finding.fix)}"))
    message = finding.message
    if finding.witness:
        values = " ".join(f"{k}:={v}" for k, v in sorted(finding.witness.items()))
        message += f" (when: {values})"
    fields = ",".join(f"{name}={escape_property(value)}" for name, value in properties)
    return f"::{COMMANDS[finding.severity]} {fields}::{escape_data(message)}"


def render_github(report: Report, out: TextIO) -> None:
    """Write one workflow command per finding."""
    for finding in report.findings:
        out.write(annotation(finding, report) + "\n")
