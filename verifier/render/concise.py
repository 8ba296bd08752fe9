"""``check --format concise``: one line per finding, as ruff's ``--output-format concise``.

``path:line:col: severity CODE [*] message``, with ``[*]`` when ``--fix`` would mend it,
then the summary the text format ends with. The severity stays (ruff has none) because
warnings do not fail a check and errors do. Nothing is grouped or framed: the line is what CI
logs, editors' problem matchers and ``grep`` read.
"""

from __future__ import annotations

from typing import TextIO

from launchverify.engine import Report
from launchverify.findings.fixes import applicable
from launchverify.render.text import STYLES, Lines, coverage_line, fixes_line, summary_line


def render_concise(report: Report, out: TextIO, *, color: bool | None = None,
                   quiet: bool = False, unsafe_fixes: bool = False) -> None:
    """Write one line per finding, then the summary (unless ``quiet``)."""
    line = Lines(out, color)
    for finding in report.findings:
        span = finding.span
        where = f"{report.display_path(span.file)}:{span.line}:{span.column}"
        marker = " [*]" if applicable(finding.fix, unsafe_fixes) else ""
        line((where, "bold"), ": ", (finding.severity.value, STYLES[finding.severity]), " ",
             (finding.code, "bold"), marker, f" {finding.message}")
    if not quiet:
        line(summary_line(report))
        coverage = coverage_line(report)
        if coverage:
            line(coverage, style="dim")
        footer = fixes_line(report, unsafe_fixes)
        if footer:
            line(footer)
