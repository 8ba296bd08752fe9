"""The findings of the HTML report: an index by rule and full entries by file.

Each entry carries what the text output prints with ``--explain``: the code frame, related
places, the include chain, the witness, the trace and the fix, and, folded, why the rule
matters and how to fix what it finds, with a link to the rule's documentation, so the
page stands on its own.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Iterable
from functools import cache

from launchverify.engine import Report
from launchverify.findings.fixes import fix_note
from launchverify.render import links
from launchverify.render.html_text import clip, distinct_tails, esc, place
from launchverify.rule import Finding, Severity
from launchverify.span import Span
from launchverify.workspace.sources import source_line, source_lines

FRAME_CONTEXT = 2  # source lines shown above and below a finding
LINE_LIMIT = 240  # characters of a source line shown


def finding_id(index: int) -> str:
    """Return the anchor of the ``index``-th finding (in report order)."""
    return f"finding-{index + 1}"


def severity_badge(severity: Severity) -> str:
    """Return a coloured label for a severity."""
    return f'<span class="sev sev-{severity.value}">{severity.value}</span>'


def render_rule_index(report: Report) -> str:
    """Return the findings grouped by rule: one compact row each, linked to its entry."""
    if not report.findings:
        return ""
    by_rule: dict[str, list[int]] = defaultdict(list)
    for index, finding in enumerate(report.findings):
        by_rule[finding.code].append(index)
    # each file as briefly as tells it from the others (two packages' files of one name)
    tails = distinct_tails(report.display_path(f.span.file) for f in report.findings)
    parts = ['<section id="by-rule"><h2>Findings by rule</h2><table class="index">'
             "<thead><tr><th>Rule</th><th>Where</th><th>Message</th></tr></thead>"]
    for code in sorted(by_rule):
        indexes = by_rule[code]
        first = report.findings[indexes[0]]
        rule = (f'<td class="rule" rowspan="{len(indexes)}">{severity_badge(first.severity)} '
                f'<code class="code">{esc(code)}</code> <span class="slug">{esc(first.slug)}'
                "</span></td>")
        parts.append(f'<tbody id="rule-{esc(code)}">')
        for index in indexes:
            finding = report.findings[index]
            span = finding.span
            path = report.display_path(span.file)
            parts.append(
                f'<tr>{rule}<td class="where"><a href="#{finding_id(index)}" '
                f'title="{esc(path)}:{span.line}"><span class="loc">'
                f"{esc(tails[path])}:{span.line}</span></a></td>"
                f"<td>{esc(finding.message)}</td></tr>")
            rule = ""
        parts.append("</tbody>")
    parts.append("</table></section>")
    return "".join(parts)


def render_file_findings(report: Report) -> str:
    """Return every finding in full, grouped by the file it points at."""
    if not report.findings:
        return ('<section id="by-file"><h2>Findings</h2>'
                '<p class="clean">No findings.</p></section>')
    by_file: dict[str, list[int]] = defaultdict(list)
    for index, finding in enumerate(report.findings):
        by_file[report.display_path(finding.span.file)].append(index)
    parts = ['<section id="by-file"><h2>Findings by file</h2>']
    for name, indexes in by_file.items():
        count = len(indexes)
        parts.append(f'<h3 class="file"><code>{esc(name)}</code> '
                     f'<span class="count">{count}</span></h3>')
        parts.extend(render_finding(report, report.findings[i], i) for i in indexes)
    parts.append("</section>")
    return "".join(parts)


def render_finding(report: Report, finding: Finding, index: int) -> str:
    """Return one finding as an article with everything known about it."""
    span = finding.span
    head = (f'<header>{severity_badge(finding.severity)} <code class="code">'
            f'{esc(finding.code)}</code> <span class="slug">[{esc(finding.slug)}]</span> '
            f'{place(report, span.file, span.line)}<span class="col">:{span.column}</span>'
            f'</header><p class="msg">{esc(finding.message)}</p>')
    body = [head, code_frame(span)]
    if finding.chain:
        body.append(_chain(report, finding.chain, span))
    if finding.related:
        items = "".join(
            f"<li>{esc(r.message)} at {place(report, r.span.file, r.span.line)}"
            f"{_source_line(r.span)}</li>" for r in finding.related)
        body.append(f'<div class="part"><h4>Related</h4><ul class="related">{items}</ul></div>')
    if finding.witness:
        values = "".join(f"<li><code>{esc(k)}:={esc(v)}</code></li>"
                         for k, v in sorted(finding.witness.items()))
        body.append('<div class="part"><h4>When launched with</h4>'
                    f'<ul class="witness">{values}</ul></div>')
    if finding.trace:
        steps = "".join(
            f"<li>{esc(step.text)}"
            + (f" {place(report, step.span.file, step.span.line)}" if step.span else "")
            + "</li>" for step in finding.trace)
        body.append(f'<div class="part"><h4>Trace</h4><ol class="trace">{steps}</ol></div>')
    if finding.fix is not None:
        body.append(f'<div class="part"><h4>Fix</h4><p class="fix">{esc(finding.fix.message)}'
                    f'{esc(fix_note(finding.fix))}</p></div>')
    body.append(_about(finding.code))
    return (f'<article class="finding sev-{finding.severity.value}" id="{finding_id(index)}">'
            + "".join(body) + "</article>")


@cache
def _about(code: str) -> str:
    """Return why the rule matters and how to fix it, folded, with its documentation."""
    from launchverify.registry import rule_of

    rule = rule_of(code)
    if rule is None:
        return ""
    parts = []
    for label, heading in (("Why it matters", "Why it matters"), ("How to fix it", "Fix")):
        text = rule.lead(heading)
        if text:
            parts.append(f"<p><b>{label}:</b> {esc(text)}</p>")
    url = links.rule_url(code)
    if url is not None:
        parts.append(f'<p><a href="{esc(url)}" rel="noopener noreferrer">{esc(code)} '
                     f"{esc(rule.slug)} in the documentation</a></p>")
    if not parts:
        return ""
    return ('<details class="part about"><summary>Why it matters and how to fix it'
            f"</summary>{''.join(parts)}</details>")


def _chain(report: Report, chain: Iterable[Span], span: Span) -> str:
    items = "".join(f"<li>include at {place(report, s.file, s.line)}</li>" for s in chain)
    items += f"<li>this finding in {place(report, span.file, None)}</li>"
    return f'<div class="part"><h4>Include chain</h4><ol class="chain">{items}</ol></div>'


def _source_line(span: Span) -> str:
    text = source_line(span.file, span.line)
    return f' <code class="snippet">{esc(clip(text, LINE_LIMIT))}</code>' if text else ""


def code_frame(span: Span) -> str:
    """Return the source lines around a span, numbered, with the span highlighted."""
    lines = source_lines(span.file)
    if not 0 < span.line <= len(lines):
        return ""
    last = span.end_line if span.end_line is not None and span.end_line >= span.line \
        else span.line
    first_shown = max(1, span.line - FRAME_CONTEXT)
    last_shown = min(len(lines), last + FRAME_CONTEXT)
    width = len(str(last_shown))
    rows = []
    for number in range(first_shown, last_shown + 1):
        text = lines[number - 1]
        marked = span.line <= number <= last
        start = max(span.column - 1, 0) if number == span.line else 0
        end = len(text)
        if number == last and span.end_line is not None and span.end_column \
                and span.end_column - 1 > start:
            end = span.end_column - 1
        rows.append(_frame_row(number, width, text, marked, start, end))
    return f'<pre class="frame">{"".join(rows)}</pre>'


def _frame_row(number: int, width: int, text: str, marked: bool, start: int, end: int) -> str:
    gutter = f'<span class="ln">{str(number).rjust(width)}</span>'
    if not marked:
        return f'<span class="row">{gutter}{esc(clip(text, LINE_LIMIT))}</span>\n'
    start = min(start, len(text))
    end = max(min(end, len(text)), start)
    before, middle, after = text[:start], text[start:end], text[end:]
    if not middle:  # a zero-width span (end of line): mark one blank
        middle = " "
    body = (f"{esc(clip(before, LINE_LIMIT))}<mark>{esc(clip(middle, LINE_LIMIT))}</mark>"
            f"{esc(clip(after, LINE_LIMIT))}")
    return f'<span class="row hit">{gutter}{body}</span>\n'
