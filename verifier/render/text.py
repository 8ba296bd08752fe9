"""Human-readable output: ``file:line:col: severity CODE [slug] message`` and a code frame.

A finding ``--fix`` would mend has ``[*]`` after its code (``error LV304 [*] [slug] ...``,
where the concise format has it too), and the summary says how many are fixable.

Findings that say the same thing (one code, severity, message and argument values) at
several places, as one per node loading a file or one per parameter block, are grouped:
the first in full, the others as ``also at file:line:col`` lines under it, so each place
stays greppable while the frames and notes are read once. Machine formats keep every
finding on its own.
"""

from __future__ import annotations

import contextlib
import os
from pathlib import Path
from typing import TYPE_CHECKING, TextIO

from launchverify.engine import Report
from launchverify.findings.fixes import applicable, fixable, hidden
from launchverify.render import links
from launchverify.render.inert import inert
from launchverify.rule import Finding, Severity
from launchverify.workspace.paths import display_path
from launchverify.workspace.sources import source_line, source_lines

if TYPE_CHECKING:
    from rich.console import Console

STYLES = {Severity.ERROR: "bold red", Severity.WARNING: "bold yellow", Severity.INFO: "cyan"}


def _frame(finding: Finding) -> list[str]:
    span = finding.span
    lines = source_lines(span.file)
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


Piece = str | tuple[str, str]  # text, or text and its style


class Lines:
    """Writes lines of styled pieces: through rich when it styles them, else as plain text.

    Without colours rich only joins the pieces, at about 100 microseconds a line (a third
    of a cached run of navigation2); the plain path writes what rich would, directly:
    tabs expanded as rich does. Pieces are never markup, so a message's ``[brackets]`` or
    ``:emoji:`` codes print as they are, and every control character in them is shown
    visibly (``inert``): names and source lines come from the checked files.
    """

    def __init__(self, out: TextIO, color: bool | None) -> None:
        # --color always/never decide; auto follows the terminal and NO_COLOR (rich reads it)
        self.out = out
        self.styled: Console | None = None  # rich, when it styles the output
        self.tab_size = 8
        if color or (color is None and _may_style(out)):  # rich is imported only then
            from rich.console import Console

            console = Console(file=out, highlight=False, soft_wrap=True, force_terminal=color,
                              no_color=None if color is None else not color)
            self.tab_size = console.tab_size
            self.styled = console if console.color_system is not None else None

    def __call__(self, *pieces: Piece, style: str | None = None) -> None:
        """Write one line."""
        if self.styled is None:
            text = inert(
                "".join(piece if isinstance(piece, str) else piece[0] for piece in pieces))
            if "\t" in text:  # tab stops count terminal cells (wide, zero-width): rich's way
                from rich.text import Text

                cells = Text(text)
                cells.expand_tabs(self.tab_size)
                text = cells.plain
            self.out.write(text + "\n")
        else:
            from rich.text import Text

            safe = [inert(piece) if isinstance(piece, str) else (inert(piece[0]), piece[1])
                    for piece in pieces]
            self.styled.print(Text.assemble(*safe, style=style or ""))


def _may_style(out: TextIO) -> bool:
    """Return whether rich could choose colours for ``out`` (else it surely would not).

    rich styles a terminal, or any stream when ``FORCE_COLOR`` or ``TTY_COMPATIBLE`` asks.
    """
    if os.environ.get("FORCE_COLOR") or os.environ.get("TTY_COMPATIBLE"):
        return True
    try:
        return out.isatty()
    except (AttributeError, ValueError, OSError):
        return True  # rich decides


def render_text(report: Report, out: TextIO, *, color: bool | None = None,
                explain: bool = False, quiet: bool = False,
                unsafe_fixes: bool = False) -> None:
    """Write findings with code frames and a summary line.

    ``explain`` adds, under each finding, the related source lines, the trace, why the
    rule matters and how to fix it; ``quiet`` leaves out the summary. ``unsafe_fixes``:
    unsafe fixes count as fixable (``--unsafe-fixes``).
    """
    line = Lines(out, color)
    shown = workspace_line(report)
    if shown and not quiet:
        line(shown, style="dim")
    groups = _groups(report.findings)
    for finding in report.findings:
        same = groups[_sameness(finding)]
        if same[0] is not finding:
            continue  # printed under the first of its group
        span = finding.span
        where = f"{report.display_path(span.file)}:{span.line}:{span.column}"
        marker = " [*]" if applicable(finding.fix, unsafe_fixes) else ""
        line((where, "bold"), ": ", (finding.severity.value, STYLES[finding.severity]), " ",
             (finding.code, "bold"), marker, f" [{finding.slug}] {finding.message}")
        for frame in _frame(finding):
            line(frame, style="dim" if "|" in frame[:8] else None)
        for other in same[1:]:
            line(f"    also at {report.display_path(other.span.file)}:{other.span.line}:"
                 f"{other.span.column}", style="dim")
        for include in reversed(finding.chain):
            line(f"    included from {report.display_path(include.file)}:{include.line}",
                 style="dim")
        for related in finding.related:
            line(f"    note: {related.message} at "
                 f"{report.display_path(related.span.file)}:{related.span.line}", style="dim")
            if explain:
                text = source_line(related.span.file, related.span.line)[:200]
                if text:
                    line(f"      {related.span.line} | {text}", style="dim")
        if finding.witness:
            values = " ".join(f"{k}:={v}" for k, v in sorted(finding.witness.items()))
            line(f"    when: {values}", style="dim")
        if finding.trace and explain:
            line("    trace:", style="dim")
            for number, step in enumerate(finding.trace, 1):
                where = (f" ({report.display_path(step.span.file)}:{step.span.line})"
                         if step.span is not None else "")
                line(f"      {number}. {step.text}{where}", style="dim")
        elif finding.trace:
            line("    (--explain prints the trace)", style="dim")
        if explain:
            _explanation(line, finding)
            if finding.fix is not None:
                line(f"    fix ({finding.fix.applicability.value}): {finding.fix.message}",
                     style="dim")
    if explain:
        _unjudged(line, report)
    if not quiet:
        if report.findings and not explain:
            line(docs_line(report), style="dim")
        line(summary_line(report))
        coverage = coverage_line(report)
        if coverage:
            line(coverage, style="dim")
        footer = fixes_line(report, unsafe_fixes)
        if footer:
            line(footer)


def _explanation(line: Lines, finding: Finding) -> None:
    """Print why the rule matters and how to fix it (first paragraphs of its docs)."""
    from launchverify.registry import rule_of

    rule = rule_of(finding.code)
    if rule is None:
        return
    for label, heading in (("why", "Why it matters"), ("fix", "Fix")):
        text = rule.lead(heading)
        if text:
            line(f"    {label}: {text}", style="dim")
    url = links.rule_url(finding.code)
    line(f"    (launchverify explain {finding.code} prints the whole rule"
         f"{'; ' + url if url else ''})", style="dim")


def _sameness(finding: Finding) -> tuple[object, ...]:
    """Return what two findings share when they say the same thing at different places."""
    witness = tuple(sorted(finding.witness.items())) if finding.witness else ()
    return (finding.code, finding.severity, finding.message, witness,
            finding.fix is None, tuple(r.message for r in finding.related), finding.trace)


def _groups(findings: list[Finding]) -> dict[tuple[object, ...], list[Finding]]:
    """Return the findings by what they say, each group in report order."""
    groups: dict[tuple[object, ...], list[Finding]] = {}
    for finding in findings:
        groups.setdefault(_sameness(finding), []).append(finding)
    return groups


def _unjudged(line: Lines, report: Report) -> None:
    """Say which launch files were too incomplete for claims that something is absent."""
    lines = [f"  {report.display_path(span.file)}:{span.line}: {reason}"
             for reason, span in report.not_judged()]
    if not lines:
        return
    line("Not judged where the evaluation is incomplete: claims that something is "
         "absent (unused arguments, parameter blocks for no node, nodes a manager "
         "waits for) are not made on a launch that reaches these:", style="dim")
    for text in lines:
        line(text, style="dim")


def summary_line(report: Report) -> str:
    """Return the one-line summary.

    ``No findings in 12 files (0.30s); 4 hidden by the baseline.``: what a baseline
    drops is counted, so a clean run says how much it rests on.
    """
    counts = {s: sum(1 for f in report.findings if f.severity is s) for s in Severity}
    files = f"{report.files} file{'s' if report.files != 1 else ''}"
    took = f"{report.seconds:.2f}s{', unchanged since the cached run' if report.cached else ''}"
    hidden = f"; {report.baselined} hidden by the baseline" if report.baselined else ""
    if not report.findings:
        return f"No findings in {files} ({took}){hidden}."
    parts = [f"{counts[s]} {s.value}{'s' if counts[s] != 1 else ''}" for s in Severity
             if counts[s]]
    total = len(report.findings)
    return (f"Found {total} finding{'s' if total != 1 else ''} ({', '.join(parts)}) in "
            f"{files} ({took}){hidden}.")


def coverage_line(report: Report) -> str:
    """Return the line after the summary when includes or packages were not followed, or ''.

    ``Not followed: 15 includes and 2 packages (turtlebot3_gazebo, ...)``, and how to
    add them: the underlay's setup script, else ``--package-path``.
    """
    coverage = report.coverage()
    if not coverage:
        return ""
    counted = []
    if coverage.includes:
        counted.append(f"{coverage.includes} include{'s' if coverage.includes != 1 else ''}")
    names = [name for name, _ in coverage.packages]
    if names:
        counted.append(f"{len(names)} package{'s' if len(names) != 1 else ''}")
        more = f", {len(names) - 3} more" if len(names) > 3 else ""
        counted[-1] += f" ({', '.join(names[:3])}{more})"
    if report.sourced:
        how = "found in neither the workspace nor AMENT_PREFIX_PATH: --package-path DIR"
    else:
        how = ("found in neither the workspace nor an underlay: "
               f"`source /opt/ros/{report.distro or '<distro>'}/setup.bash` (then "
               "AMENT_PREFIX_PATH lists the underlay) or --package-path DIR")
    return f"Not followed: {' and '.join(counted)}, {how} adds them."


def workspace_line(report: Report) -> str:
    """Return ``workspace: DIR (why)`` when the workspace is not the working folder."""
    found = report.workspace
    if found is None:
        return ""
    with contextlib.suppress(OSError):
        if found.folder == Path(os.path.realpath(Path.cwd())):
            return ""
    return f"workspace: {display_path(found.folder)} ({found.how})"


def docs_line(report: Report) -> str:
    """Return where to read why a finding matters and how to fix it."""
    code = report.findings[0].code
    base = links.documentation_base()
    return (f"Why each matters and how to fix it: launchverify explain {code}, --explain"
            f"{', or ' + base if base else ''}.")


def fixes_line(report: Report, unsafe: bool) -> str:
    """Return ``[*] 2 fixable with --fix (1 hidden fix ...)``, or '' when none is."""
    count, more = fixable(report.findings, unsafe), hidden(report.findings, unsafe)
    if not count and not more:
        return ""
    flag = "--fix --unsafe-fixes" if unsafe else "--fix"
    text = f"[*] {count} fixable with {flag}"
    if more:
        text += (f" ({more} hidden fix{'es' if more != 1 else ''} can be enabled with "
                 "--unsafe-fixes)")
    return text + "."


def render_statistics(report: Report, out: TextIO, *, quiet: bool = False) -> None:
    """Write how many findings each rule has, most first (``--statistics``)."""
    counts: dict[tuple[str, str, str], int] = {}
    for finding in report.findings:
        key = (finding.code, finding.slug, finding.severity.value)
        counts[key] = counts.get(key, 0) + 1
    for (code, slug, severity), count in sorted(counts.items(),
                                                key=lambda item: (-item[1], item[0])):
        out.write(f"{count:>5}  {code}  {slug:<32} {severity}\n")
    if not quiet:
        out.write(f"solver: {report.solver_queries()} z3 queries (the rest settled "
                  "by concrete search)\n")
        out.write(summary_line(report) + "\n")
        coverage = coverage_line(report)
        if coverage:
            out.write(coverage + "\n")
