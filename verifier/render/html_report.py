"""``launchverify report``: one self-contained HTML file.

The page works offline and without JavaScript: styles are inline, the picture of the
launched system is SVG written here, and the only script (opening a collapsed table when
a link points into it, filling a reference to a block written earlier with a copy of it,
the computation graph's filter) is optional. Every piece of text from a launch file or a
path is escaped (``html_text.esc``), and a content security policy lets only that script
run.

What the page repeats it writes once (``html_shared``): the systems of a workspace mostly
start the same stacks, and writing them out again for each made most of the page.
"""

from __future__ import annotations

from collections import Counter
from typing import TYPE_CHECKING, TextIO

from launchverify import __version__
from launchverify.engine import Report
from launchverify.render.flow_svg import FLOW_LEGEND
from launchverify.render.html_findings import (
    finding_id,
    render_file_findings,
    render_rule_index,
    severity_badge,
)
from launchverify.render.html_shared import Shared
from launchverify.render.html_style import CONTENT_SECURITY_POLICY, SCRIPT, STYLE
from launchverify.render.html_text import esc
from launchverify.render.system_html import LEGEND, render_system_section, roots_to_show
from launchverify.rule import Severity

if TYPE_CHECKING:
    from launchverify.topology.compose import InterfaceSource

NAVIGATION_SYSTEMS = 6  # more systems than this are listed in the summary, not the header


def render_html(report: Report, out: TextIO, *, title: str = "launchverify report",
                interfaces: InterfaceSource | None = None) -> None:
    """Write the whole report as one HTML document.

    ``interfaces`` (node interfaces read from the workspace's sources) adds each
    system's computation graph: nodes and the topics, services and actions between them.
    """
    anchors = {id(f): finding_id(i) for i, f in enumerate(report.findings)}
    roots = roots_to_show(report)
    shared = Shared()  # what one section wrote, the next ones refer back to
    systems = [render_system_section(report, graph, number, anchors, interfaces, shared)
               for number, graph in enumerate(roots, 1)]
    out.write("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
              '<meta http-equiv="Content-Security-Policy" '
              f'content="{esc(CONTENT_SECURITY_POLICY)}">'
              '<meta name="viewport" content="width=device-width, initial-scale=1">'
              f'<meta name="generator" content="launchverify {esc(__version__)}">'
              f"<title>{esc(title)}</title><style>{STYLE}</style></head><body>")
    out.write(f'<header class="top"><h1>{esc(title)}</h1>{_navigation(report, len(roots))}'
              "</header><main>")
    out.write(_summary(report, [report.display_path(g.root) for g in roots]))
    out.write(render_rule_index(report))
    if systems:
        out.write(LEGEND)  # once for every picture below
    if any('class="flow-section"' in system for system in systems):
        out.write(FLOW_LEGEND)  # likewise for the computation graphs
    out.writelines(systems)
    out.write(render_file_findings(report))
    out.write(f'</main><footer>Written by launchverify {esc(__version__)}.</footer>'
              f"<script>{SCRIPT}</script></body></html>\n")


def _navigation(report: Report, systems: int) -> str:
    links = ['<a href="#summary">Summary</a>']
    if report.findings:
        links.append('<a href="#by-rule">Findings by rule</a>')
    if systems > NAVIGATION_SYSTEMS:  # the summary lists them all
        links.append(f'<a href="#roots">Systems ({systems})</a>')
    else:
        links += [f'<a href="#system-{n}">System{f" {n}" if systems > 1 else ""}</a>'
                  for n in range(1, systems + 1)]
    links.append('<a href="#by-file">Findings by file</a>')
    return '<nav>' + "".join(links) + "</nav>"


def _summary(report: Report, roots: list[str]) -> str:
    counts = Counter(f.severity for f in report.findings)
    cards = [_card("files read", str(report.files)),
             _card("findings", str(len(report.findings)),
                   "bad" if counts[Severity.ERROR] else "ok" if not report.findings else "")]
    cards += [_card(f"{s.value}s", str(counts[s]), f"sev-card-{s.value}" if counts[s] else "")
              for s in Severity]
    cards.append(_card("seconds", f"{report.seconds:.2f}"))
    if report.suppressed:
        cards.append(_card("suppressed", str(report.suppressed)))
    if report.baselined:
        cards.append(_card("in the baseline", str(report.baselined)))
    by_rule = Counter((f.code, f.slug, f.severity) for f in report.findings)
    rules = "".join(
        f'<li><a href="#rule-{esc(code)}">{severity_badge(severity)} <code>{esc(code)}</code>'
        f' {esc(slug)} <b>{count}</b></a></li>'
        for (code, slug, severity), count in sorted(  # one rule may report at two levels
            by_rule.items(), key=lambda item: (item[0][0], item[0][1], -item[0][2].rank)))
    return ('<section id="summary"><div class="cards">' + "".join(cards) + "</div>"
            + (f'<ul class="rules">{rules}</ul>' if rules else "") + _roots(roots)
            + "</section>")


def _roots(roots: list[str]) -> str:
    """Return the root files the systems below are launched from, linked to them."""
    if len(roots) <= 1:
        return "".join(f'<p class="roots" id="roots">Launched from <a href="#system-1">'
                       f"<code>{esc(r)}</code></a></p>" for r in roots)
    items = "".join(f'<li><a href="#system-{n}"><code>{esc(r)}</code></a></li>'
                    for n, r in enumerate(roots, 1))
    opened = " open" if len(roots) <= NAVIGATION_SYSTEMS else ""
    return (f'<details class="roots" id="roots"{opened}><summary>Launched from '
            f'{len(roots)} files</summary><ul class="roots">{items}</ul></details>')


def _card(label: str, value: str, tone: str = "") -> str:
    return (f'<div class="card {tone}"><span class="value">{esc(value)}</span>'
            f'<span class="label">{esc(label)}</span></div>')
