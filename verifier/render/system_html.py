"""One root's part of the HTML report: picture, node table, bring-up, includes.

The legend of the pictures (``LEGEND``) is written once, before the first section.

Kept apart from the page skeleton so that a report with several roots simply repeats it;
what an earlier section wrote the same (a node's row, its parameters, the includes below
an include) is a reference to it (``html_shared``).
"""

from __future__ import annotations

from collections import defaultdict
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from launchverify.engine import Report
from launchverify.graph import IncludeRecord, LaunchGraph
from launchverify.render.html_shared import SHARE_ABOVE, First, Shared
from launchverify.render.html_text import clip, esc, short_place, where
from launchverify.render.system_model import (
    NAMED_BY_CODE,
    SystemModel,
    SystemNode,
    build_model,
)
from launchverify.render.system_svg import render_system_svg
from launchverify.span import Span

if TYPE_CHECKING:
    from launchverify.topology.compose import InterfaceSource

ARGUMENT_LIMIT = 60  # characters of an include argument's value shown in the tree

LEGEND = (
    '<ul class="legend">'
    '<li><span class="sw sw-node"></span>node</li>'
    '<li><span class="sw sw-managed"></span>lifecycle node</li>'
    '<li><span class="sw sw-manager"></span>lifecycle manager '
    '(<span class="dia dia-done"></span>brings up all its nodes, '
    '<span class="dia dia-blocked"></span>never completes)</li>'
    '<li><span class="sw sw-container"></span>container with its components</li>'
    '<li>best state reached: <span class="dot st-active"></span>active '
    '<span class="dot st-inactive"></span>inactive '
    '<span class="dot st-unconfigured"></span>unconfigured '
    '<span class="dot st-finalized"></span>finalized</li>'
    '<li><span class="sw sw-error"></span>node with a finding (code shown)</li>'
    "</ul>"
)


def roots_to_show(report: Report) -> list[LaunchGraph]:
    """Return the graphs that get a section: the roots no other checked file includes.

    When every file is included by another (an include cycle), all of them are shown.
    """
    tops = [g for g in report.graphs if not g.included_elsewhere]
    return tops or list(report.graphs)


def render_system_section(report: Report, graph: LaunchGraph, number: int,
                          anchors: dict[int, str],
                          interfaces: InterfaceSource | None = None,
                          shared: Shared | None = None) -> str:
    """Return the section of one root: summary line, pictures, tables, include tree.

    With ``interfaces`` (where node interfaces come from), the computation graph too.
    ``shared``: the blocks earlier sections wrote, which this one refers back to.
    """
    shared = Shared() if shared is None else shared
    composition = None
    if interfaces is not None:
        from launchverify.render.flow_html import compose_system

        composition = compose_system(graph, interfaces)
    model = build_model(report, graph, anchors,
                        composition.names() if composition is not None else None)
    anchor = f"sys{number}-node"
    root_name = report.display_path(graph.root)
    parts = [f'<section class="system-section" id="system-{number}">'
             f"<h2>System of <code>{esc(root_name)}</code></h2>",
             f'<p class="stats">{_stats(model)}</p>']
    if not graph.complete_as_given():
        parts.append('<p class="note">Part of this launch could not be seen into (a missing '
                     "file or package, or a construct launchverify does not model): the "
                     "picture may lack nodes.</p>")
    parts.append(f'<div class="picture">{render_system_svg(model, anchor)}</div>')
    if composition is not None:
        from launchverify.render.flow_html import computation_graph

        parts.append(computation_graph(model, composition, number, anchor, shared))
    parts.append(_lifecycle(model.lifecycle))
    parts.append(_node_table(model, anchor, number, shared))
    parts.append(render_include_tree(report, graph, number, shared))
    parts.append("</section>")
    return "".join(parts)


def _stats(model: SystemModel) -> str:
    nodes = model.nodes
    components = sum(1 for n in nodes if n.kind.startswith("composable"))
    managed = len({n.fqn for n in nodes if n.managed and n.manager is None})
    managers = [n for n in nodes if n.manager is not None]
    done = sum(1 for n in managers if n.manager and n.manager["completes"])
    containers = sum(1 for n in nodes if n.kind == "node_container")
    facts = [_count(len(nodes), "node")
             + (f" ({_count(components, 'component', bold=False)})" if components else ""),
             _count(model.namespaces(), "namespace")]
    if managed:
        facts.append(_count(managed, "lifecycle node"))
    if managers:
        facts.append(f"<b>{done}</b> of {_count(len(managers), 'lifecycle manager', False)}"
                     " complete")
    if containers:
        facts.append(_count(containers, "container"))
    if model.processes:
        facts.append(_count(len(model.processes), "process", plural="processes"))
    return " \u00b7 ".join(facts)


def _count(number: int, noun: str, bold: bool = True, plural: str = "") -> str:
    word = noun if number == 1 else plural or noun + "s"
    return f"<b>{number}</b> {word}" if bold else f"{number} {word}"


def _lifecycle(lifecycle: dict[str, Any] | None) -> str:
    if not lifecycle or (not lifecycle["managers"] and not lifecycle["nodes"]):
        return ""
    rows = []
    for manager in lifecycle["managers"]:
        verdict = ('<span class="ok">completes</span>' if manager["completes"]
                   else '<span class="bad">does not complete</span>')
        names = ", ".join(manager["node_names"])
        defined = short_place(f"{manager['file']}:{manager['line']}")
        autostart = manager["autostart"]
        autostart = "" if autostart is None else esc(
            str(autostart).lower() if isinstance(autostart, bool) else autostart)
        rows.append(f"<tr><td><code>{esc(manager['fqn'])}</code></td><td>{verdict}</td>"
                    f"<td>{autostart}</td><td>{esc(names)}</td>"
                    f"<td>{defined}</td></tr>")
    note = "" if lifecycle["complete"] else (
        '<p class="note">The search did not follow every trigger: some states may be '
        "missing.</p>")
    table = ("<table><thead><tr><th>Manager</th><th>Bring-up</th><th>autostart</th>"
             "<th>node_names</th><th>Defined at</th></tr></thead><tbody>"
             + "".join(rows) + "</tbody></table>") if rows else ""
    managed = len(lifecycle["nodes"])
    explored = _count(lifecycle["states_explored"], "state", False)
    return (f'<details class="lifecycle" open><summary>Lifecycle bring-up: '
            f"{_count(managed, 'managed node', False)}, {explored} explored</summary>"
            f"{note}{table}</details>")


def _node_table(model: SystemModel, anchor: str, number: int, shared: Shared) -> str:
    rows = [_node_row(node, anchor, number, shared) for node in model.nodes]
    return (f'<details class="nodes"><summary>All {len(model.nodes)} nodes: parameters, '
            'remaps, lifecycle states</summary><table class="nodes"><thead><tr><th>Node</th>'
            "<th>Kind</th>"
            "<th>Executable</th><th>Lifecycle</th><th>Remaps</th><th>Parameters</th>"
            "<th>Defined at</th></tr></thead><tbody>" + "".join(rows)
            + "</tbody></table></details>")


def _parameters(parameters: list[tuple[str, str, str]]) -> str:
    """Return a node's parameters, under the file each comes from (named once).

    A node's parameters mostly come from one or two files: the file is written once,
    then each parameter with its line only.
    """
    by_file: dict[str, list[tuple[str, str, str]]] = defaultdict(list)
    for name, value, source in parameters:
        file, _, line = source.rpartition(":")
        if not line.isdigit():
            file, line = source, ""
        by_file[file].append((name, value, line))
    parts = []
    for file, entries in by_file.items():
        items = "".join(f"<li><code>{esc(n)}</code> = <code>{esc(v)}</code>"
                        + (f' <small class="at">:{line}</small>' if line else "") + "</li>"
                        for n, v, line in entries)
        head = f'<li class="from">{short_place(file)}</li>' if file else ""
        parts.append(f'<ul class="plain">{head}{items}</ul>')
    return "".join(parts)


def _node_row(node: SystemNode, anchor: str, number: int, shared: Shared) -> str:
    kind = node.kind.replace("_", " ")
    if node.container:
        kind += f"<br><small>in {esc(node.container)}</small>"
    if node.manager is not None:
        state = ('<span class="ok">manager, completes</span>' if node.manager["completes"]
                 else '<span class="bad">manager, does not complete</span>')
    elif node.managed:
        state = " ".join(f'<span class="chip st-{esc(s)}">{esc(s)}</span>'
                         for s in node.states) or "never started"
    else:
        state = ""
    remaps = "".join(f"<li><code>{esc(s)}</code> \u2192 <code>{esc(d)}</code></li>"
                     for s, d in node.remappings)
    marks = "".join(f' <a class="sev sev-{m.severity.value}" href="#{esc(m.anchor)}">'
                    f"{esc(m.code)}</a>" for m in node.marks)
    condition = f"<br><small>when {esc(node.condition)}</small>" if node.condition else ""
    if node.named_by_code:
        condition = f"<br><small>{NAMED_BY_CODE}</small>{condition}"
    row = f"{anchor}-{node.index}"
    head = (f'<tr id="{esc(row)}"><td><code>{esc(node.fqn)}</code>{marks}{condition}</td>')
    params = _parameters(node.parameters)
    before = (f"<td>{kind}</td><td>{esc(node.executable)}</td><td>{state}</td>"
              f'<td><ul class="plain">{remaps}</ul></td><td>')
    after = f"</td><td>{short_place(node.where)}</td></tr>"
    label = f"<code>{esc(node.fqn)}</code>"
    if len(before) + len(params) + len(after) > SHARE_ABOVE:  # the same node elsewhere
        seen = shared.earlier("row:" + before + params + after, First(row, row, label, number))
        if seen is not None:
            return (f'{head}<td colspan="6" class="same" data-same="{esc(seen.href)}">'
                    f'the same as <a href="#{esc(seen.href)}">{seen.label}'
                    f"{shared.where(seen, number)}</a></td></tr>")
    if params:
        count = len(node.parameters)
        params = shared.block(
            params, ident=f"{row}-p", href=row, label=label, system=number,
            what=f"the same {count} parameter{'s' if count != 1 else ''} as",
            classes="params")
    return head + before + params + after


# ------------------------------------------------------------------ include tree


def render_include_tree(report: Report, graph: LaunchGraph, number: int = 1,
                        shared: Shared | None = None) -> str:
    """Return the includes of one root as a nested list, in the order they run.

    The includes below an include that an earlier tree (``shared``) listed the same are
    a link to those (most roots of a workspace include the same bring-up).
    """
    children: dict[tuple[Span, ...], list[IncludeRecord]] = defaultdict(list)
    for record in graph.includes:
        children[record.origin.chain].append(record)
    root = report.display_path(graph.root)
    tree = _Tree(report, graph, children, number, Shared() if shared is None else shared)
    body = tree.items(())
    count = len(graph.includes)
    return (f'<details class="includes" open><summary>Include tree '
            f'({count or "no"} include{"" if count == 1 else "s"})</summary>'
            f'<ul class="tree"><li><code>{esc(root)}</code>{body}</li>'
            "</ul></details>")


@dataclass
class _Tree:
    """One root's include tree being written."""

    report: Report
    graph: LaunchGraph
    children: dict[tuple[Span, ...], list[IncludeRecord]]
    number: int
    shared: Shared
    blocks: int = 0

    def items(self, chain: tuple[Span, ...]) -> str:
        """Return the includes made at the end of ``chain``, with theirs below them."""
        records = self.children.get(chain, [])
        if not records:
            return ""
        report, graph = self.report, self.graph
        items = []
        for record in records:
            target = (report.display_path(record.target) if record.target is not None
                      else graph.display(record.location) or "?")
            status = "" if record.status == "loaded" else \
                f' <span class="status bad">{esc(record.status)}</span>'
            runs = graph.runs(record.origin)
            skipped = ' <span class="status off">not under these arguments</span>' \
                if runs is False else ""
            condition = record.origin.condition_text()
            when = f' <small>when {esc(condition)}</small>' if condition else ""
            arguments = " ".join(
                f"<code>{esc(name)}:={esc(clip(graph.display(value) or '', ARGUMENT_LIMIT))}"
                "</code>" for name, value, _span in record.arguments if name is not None)
            below = (*chain, record.origin.span)
            nested = self.items(below)
            if nested:
                self.blocks += 1
                count = sum(len(v) for k, v in self.children.items() if k[:len(below)] == below)
                nested = self.shared.block(
                    nested, ident=f"sys{self.number}-inc-{self.blocks}",
                    href=f"sys{self.number}-inc-{self.blocks}",
                    label=f"<code>{esc(target)}</code>", system=self.number,
                    what=f"the same {count} include{'s' if count != 1 else ''} as under")
            at = short_place(where(report, record.origin.span))
            items.append(f"<li><code>{esc(target)}</code>{status}{skipped} <small>at {at}"
                         f"</small>{when}"
                         + (f'<div class="args">{arguments}</div>' if arguments else "")
                         + f"{nested}</li>")
        return "<ul>" + "".join(items) + "</ul>"
