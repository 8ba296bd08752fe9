"""Human-readable output: ``file:line:col: severity CODE [slug] message`` and a code frame."""

from __future__ import annotations

from functools import cache
from pathlib import Path
from typing import TextIO

from rich.console import Console
from rich.markup import escape

from launchverify.engine import Report
from launchverify.rule import Finding, Severity

STYLES = {Severity.ERROR: "bold red", Severity.WARNING: "bold yellow", Severity.INFO: "cyan"}


@cache
def _lines(path: Path) -> list[str]:
    try:
        return path.read_text(encoding="utf-8", errors="replace").splitlines()
    except OSError:
        return []


def _frame(finding: Finding) -> list[str]:
    span = finding.span
    lines = _lines(span.file)
    if not 0 < span.line <= len(lines):
        return []
    source = lines[span.line - 1].expandtabs(1)
    if len(source) > 200:
        source = source[:200] + " ..."
    width = len(str(span.line))
    start = max(span.column - 1, 0)
    end = span.end_column - 1 if span.end_line == span.line and span.end_column else len(source)
    marker = " " * start + "^" * max(min(end, len(source)) - start, 1)
    return [f" {span.line} | {source}", f" {' ' * width} | {marker}"]


def render_text(report: Report, out: TextIO, *, color: bool | None = None,
                explain: bool = False) -> None:
    """Write findings with code frames and a summary line (``explain``: with traces)."""
    console = Console(file=out, highlight=False, soft_wrap=True,
                      force_terminal=color, no_color=color is False)
    for finding in report.findings:
        span = finding.span
        where = f"{report.display_path(span.file)}:{span.line}:{span.column}"
        style = STYLES[finding.severity]
        console.print(
            f"[bold]{escape(where)}[/bold]: [{style}]{finding.severity.value}[/{style}] "
            f"[bold]{finding.code}[/bold] \\[{finding.slug}] {escape(finding.message)}"
        )
        for line in _frame(finding):
            console.print(escape(line), style="dim" if "|" in line[:8] else None)
        for include in reversed(finding.chain):
            console.print(f"    included from {escape(report.display_path(include.file))}:"
                          f"{include.line}", style="dim")
        for related in finding.related:
            console.print(f"    note: {escape(related.message)} at "
                          f"{escape(report.display_path(related.span.file))}:{related.span.line}",
                          style="dim")
        if finding.witness:
            values = " ".join(f"{k}:={v}" for k, v in sorted(finding.witness.items()))
            console.print(f"    when: {escape(values)}", style="dim")
        if finding.trace and explain:
            console.print("    trace:", style="dim")
            for number, step in enumerate(finding.trace, 1):
                where = (f" ({report.display_path(step.span.file)}:{step.span.line})"
                         if step.span is not None else "")
                console.print(f"      {number}. {escape(step.text)}{escape(where)}",
                              style="dim")
        elif finding.trace:
            console.print("    (--explain prints the trace)", style="dim")
    console.print(summary_line(report))


def summary_line(report: Report) -> str:
    """Return the one-line summary."""
    counts = {s: sum(1 for f in report.findings if f.severity is s) for s in Severity}
    files = f"{report.files} file{'s' if report.files != 1 else ''}"
    if not report.findings:
        return f"No findings in {files} ({report.seconds:.2f}s)."
    parts = [f"{counts[s]} {s.value}{'s' if counts[s] != 1 else ''}" for s in Severity
             if counts[s]]
    total = len(report.findings)
    return (f"Found {total} finding{'s' if total != 1 else ''} ({', '.join(parts)}) in "
            f"{files} ({report.seconds:.2f}s).")
