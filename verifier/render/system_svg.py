"""The picture of a launched system as inline SVG, laid out without a graph library.

Namespaces are nested boxes; the top-level ones are packed into columns of equal width
(shortest column first, like a masonry wall), so a fleet of robots reads as one column per
robot. Inside a box come its nodes (a grid filling the width), then its containers (a
header row with their components below), then the namespaces under it. Every box links
to the node's row in the table below the picture and carries a ``<title>`` tooltip.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from typing import Any

from launchverify.render.html_text import clip, esc, num
from launchverify.render.system_model import NAMED_BY_CODE, Namespace, SystemModel, SystemNode

NODE_H = 19  # height of a node box
GAP = 3  # between node boxes
PAD = 6  # inside a namespace or container box
HEADER = 22  # namespace label band
COL_GAP = 10  # between top-level columns
TARGET_W = 1360  # width the columns are fitted to
UNIT_MIN = 200  # narrowest top-level column
MIN_NODE_W = 150  # narrowest node box when a grid decides its columns
MAX_ROWS = 30  # rows of nodes before a top-level box spreads over another column
BALANCE_ROWS = 10  # widen a box while it has more rows than this and columns are free
CHAR_W = 6.62  # advance of one character of the 11px monospace label font
SQUEEZE = 1.2  # how much a label may be condensed (textLength) before it is cut
BADGE_W = 38  # a finding code on a node
DOT_W = 14  # a lifecycle state marker on a node
TOOLTIP_PARAMETERS = 12


@dataclass
class Placed:
    """A top-level box and where it went."""

    namespace: Namespace
    label: str
    span: int = 1
    x: float = 0
    y: float = 0
    width: float = 0
    height: float = 0


@dataclass
class Canvas:
    """The SVG being written, with the prefix of the page's node anchors."""

    anchor: str
    parts: list[str] = field(default_factory=list)

    def add(self, text: str) -> None:
        """Append SVG markup (already escaped)."""
        self.parts.append(text)


def render_system_svg(model: SystemModel, anchor: str) -> str:
    """Return the picture of one system; node boxes link to ``#{anchor}-{index}``."""
    boxes = _top_level(model.root)
    if model.processes:
        boxes.append(Placed(Namespace("(processes)", "(processes)"), "processes"))
    if not boxes:
        return '<p class="empty">No node runs under the given arguments.</p>'
    columns = max(1, int((TARGET_W + COL_GAP) // (UNIT_MIN + COL_GAP)))
    unit = (TARGET_W - (columns - 1) * COL_GAP) / columns
    for box in boxes:
        box.span = min(columns, _span(box.namespace))
    _balance(boxes, columns)
    used = _pack(boxes, columns, unit, model)
    width = used * unit + (used - 1) * COL_GAP
    height = max(b.y + b.height for b in boxes)
    canvas = Canvas(anchor)
    canvas.add(f'<svg class="system" role="img" width="{width:.0f}" height="{height:.0f}" '
               f'viewBox="0 0 {width:.0f} {height:.0f}" aria-label="launched system: '
               f'{len(model.nodes)} nodes">')
    for box in boxes:
        if box.label == "processes":
            _draw_processes(canvas, model.processes, box)
        else:
            _draw_namespace(canvas, box.namespace, box.label, box.x, box.y, box.width, 0)
    canvas.add("</svg>")
    return "".join(canvas.parts)


# ------------------------------------------------------------------ top-level packing


def _natural(text: str) -> list[object]:
    """Return a sort key that puts robot2 before robot10."""
    return [int(part) if part.isdigit() else part for part in re.split(r"(\d+)", text)]


def _collapse(namespace: Namespace) -> Namespace:
    """Return the first namespace down a chain of empty single-child namespaces."""
    while not namespace.nodes and len(namespace.children) == 1 and not namespace.kept:
        namespace = next(iter(namespace.children.values()))
    return namespace


def _top_level(root: Namespace) -> list[Placed]:
    boxes = []
    if root.nodes:
        boxes.append(Placed(Namespace("/", "/", nodes=root.nodes), "/"))
    keys = list(root.children) if any(c.kept for c in root.children.values()) \
        else sorted(root.children, key=_natural)  # DDS domains come sorted by number
    for key in keys:
        child = _collapse(root.children[key])
        boxes.append(Placed(child, child.label if child.kept else child.path))
    return boxes


def _span(namespace: Namespace) -> int:
    """Return how many columns a box needs so that no grid is taller than MAX_ROWS."""
    plain = [n for n in namespace.nodes if not n.components]
    needs = [math.ceil(len(plain) / MAX_ROWS)]
    needs += [math.ceil(len(n.components) / MAX_ROWS) for n in namespace.nodes]
    needs += [_span(c) for c in namespace.children.values()]
    return max(1, *needs)


def _balance(boxes: list[Placed], columns: int) -> None:
    """Give free columns to the tallest boxes (a flat launch spreads over the width)."""
    while sum(b.span for b in boxes) < columns:
        tallest = max(boxes, key=lambda b: b.namespace.count() / b.span)
        if tallest.namespace.count() / tallest.span <= BALANCE_ROWS:
            return
        tallest.span += 1


def _pack(boxes: list[Placed], columns: int, unit: float, model: SystemModel) -> int:
    """Place each box where its columns are lowest; return how many columns are used."""
    heights = [0.0] * columns
    used = 0
    for box in boxes:
        start = min(range(columns - box.span + 1),
                    key=lambda j: (max(heights[j:j + box.span]), j))
        box.x = start * (unit + COL_GAP)
        box.y = max(heights[start:start + box.span])
        box.width = box.span * unit + (box.span - 1) * COL_GAP
        box.height = (_processes_height(len(model.processes)) if box.label == "processes"
                      else _namespace_height(box.namespace, box.width))
        for j in range(start, start + box.span):
            heights[j] = box.y + box.height + COL_GAP
        used = max(used, start + box.span)
    return used


# ------------------------------------------------------------------ measuring


def _grid_columns(count: int, width: float) -> int:
    fit = int((width + GAP) // (MIN_NODE_W + GAP))
    return max(1, min(fit, count))


def _grid_height(count: int, width: float) -> float:
    if count == 0:
        return 0
    rows = math.ceil(count / _grid_columns(count, width))
    return rows * (NODE_H + GAP) - GAP


def _container_height(node: SystemNode, width: float) -> float:
    return NODE_H + GAP + _grid_height(len(node.components), width - 2 * PAD) + PAD


def _parts(namespace: Namespace) -> tuple[list[SystemNode], list[SystemNode], list[Namespace]]:
    plain = [n for n in namespace.nodes if not n.components]
    hosts = [n for n in namespace.nodes if n.components]
    children = [_collapse(namespace.children[k])
                for k in sorted(namespace.children, key=_natural)]
    return plain, hosts, children


def _namespace_height(namespace: Namespace, width: float) -> float:
    inner = width - 2 * PAD
    plain, hosts, children = _parts(namespace)
    heights = [_grid_height(len(plain), inner)] if plain else []
    heights += [_container_height(h, inner) for h in hosts]
    heights += [_namespace_height(c, inner) for c in children]
    return HEADER + sum(heights) + GAP * max(len(heights) - 1, 0) + PAD


def _processes_height(count: int) -> float:
    return HEADER + count * (NODE_H + GAP) - GAP + PAD


# ------------------------------------------------------------------ drawing


def _draw_namespace(canvas: Canvas, namespace: Namespace, label: str, x: float, y: float,
                    width: float, depth: int) -> None:
    height = _namespace_height(namespace, width)
    title = namespace.label if namespace.kept else f"namespace {namespace.path}"
    canvas.add(f'<g class="ns d{min(depth, 3)}"><rect x="{num(x)}" y="{num(y)}" '
               f'width="{num(width)}" height="{num(height)}" rx="5"/>')
    count = f"{namespace.count()}"
    room = width - 2 * PAD - len(count) * 7 - 8
    canvas.add(f'<text class="nsl" x="{num(x + PAD)}" y="{num(y + 15)}">'
               f"{_fit(label, room, 7.2)}</text>"
               f'<text class="nsc" x="{num(x + width - PAD)}" y="{num(y + 15)}">{count}</text>'
               "<title>" + esc(f"{title}: {count} nodes") + "</title></g>")
    inner = width - 2 * PAD
    cursor = y + HEADER
    plain, hosts, children = _parts(namespace)
    if plain:
        _draw_grid(canvas, plain, x + PAD, cursor, inner, None)
        cursor += _grid_height(len(plain), inner) + GAP
    for host in hosts:
        _draw_container(canvas, host, x + PAD, cursor, inner)
        cursor += _container_height(host, inner) + GAP
    for child in children:
        relative = child.path[len(namespace.path.rstrip("/")) + 1:] \
            if child.path.startswith(namespace.path.rstrip("/") + "/") else child.path
        _draw_namespace(canvas, child, relative, x + PAD, cursor, inner, depth + 1)
        cursor += _namespace_height(child, inner) + GAP


def _draw_grid(canvas: Canvas, nodes: list[SystemNode], x: float, y: float, width: float,
               host: SystemNode | None) -> None:
    columns = _grid_columns(len(nodes), width)
    rows = math.ceil(len(nodes) / columns)
    cell = (width - (columns - 1) * GAP) / columns
    for index, node in enumerate(nodes):  # column-major: names read down, then across
        column, row = divmod(index, rows)
        _draw_node(canvas, node, x + column * (cell + GAP), y + row * (NODE_H + GAP), cell,
                   _label(node, host))


def _draw_container(canvas: Canvas, host: SystemNode, x: float, y: float,
                    width: float) -> None:
    height = _container_height(host, width)
    canvas.add(f'<rect class="ct" x="{num(x)}" y="{num(y)}" width="{num(width)}" '
               f'height="{num(height)}" rx="4"/>')
    _draw_node(canvas, host, x, y, width, host.name, extra=f"{len(host.components)} comp.")
    _draw_grid(canvas, host.components, x + PAD, y + NODE_H + GAP, width - 2 * PAD, host)


def _label(node: SystemNode, host: SystemNode | None) -> str:
    """Return a node's label: its name, or for a component its path below the container's."""
    if host is None:
        return node.name
    base = host.namespace.rstrip("/") + "/"
    return node.fqn[len(base):] if node.fqn.startswith(base) else node.fqn


def _node_classes(node: SystemNode) -> str:
    classes = ["node"]
    if node.is_container:
        classes.append("container")
    if node.manager is not None:
        classes.append("manager")
    elif node.managed:
        classes.append("managed")
    if node.worst is not None:
        classes.append(f"has-{node.worst.value}")
    return " ".join(classes)


def _draw_node(canvas: Canvas, node: SystemNode, x: float, y: float, width: float,
               label: str, extra: str = "") -> None:
    canvas.add(f'<a href="#{esc(canvas.anchor)}-{node.index}" class="{_node_classes(node)}" '
               f'data-fqn="{esc(node.fqn)}"><title>{esc(tooltip(node))}</title>'
               f'<rect x="{num(x)}" y="{num(y)}" width="{num(width)}" height="{NODE_H}" rx="3"/>')
    right = x + width - 4
    if node.manager is not None:
        state = "done" if node.manager["completes"] else "blocked"
        cx, cy = right - 5, y + NODE_H / 2
        canvas.add(f'<path class="mgr-{state}" d="M{num(cx)} {num(cy - 6)} l6 6 l-6 6 l-6 -6 z"/>')
        right -= DOT_W
    elif node.resting is not None:
        canvas.add(f'<circle class="st-{node.resting}" cx="{num(right - 5)}" '
                   f'cy="{num(y + NODE_H / 2)}" r="5"/>')
        right -= DOT_W
    for mark in node.marks[:2]:
        canvas.add(f'<rect class="badge b-{mark.severity.value}" x="{num(right - BADGE_W)}" '
                   f'y="{num(y + 3)}" width="{BADGE_W - 2}" height="{NODE_H - 6}" rx="2"/>'
                   f'<text class="bt" x="{num(right - BADGE_W / 2 - 1)}" y="{num(y + 13)}">'
                   f"{esc(mark.code)}</text>")
        right -= BADGE_W
    if extra:
        canvas.add(f'<text class="extra" x="{num(right - 2)}" y="{num(y + 13.5)}">'
                   f"{esc(extra)}</text>")
        right -= len(extra) * 6 + 6
    canvas.add(f'<text class="nl" x="{num(x + 6)}" y="{num(y + 13.5)}"'
               f"{_fit_attributes(label, right - x - 8)}>{esc(_fit_text(label, right - x - 8))}"
               "</text></a>")


def _fit_text(label: str, room: float, char_w: float = CHAR_W) -> str:
    limit = max(int(room * SQUEEZE / char_w), 2)
    return clip(label, limit)


def _fit_attributes(label: str, room: float, char_w: float = CHAR_W) -> str:
    """Return ``textLength`` for a label a little too long for its box (condensed)."""
    shown = _fit_text(label, room, char_w)
    if len(shown) * char_w <= room or room <= 0:
        return ""
    return f' textLength="{num(room)}" lengthAdjust="spacingAndGlyphs"'


def _fit(label: str, room: float, char_w: float) -> str:
    return esc(clip(label, max(int(room / char_w), 4)))


def _draw_processes(canvas: Canvas, processes: list[dict[str, Any]], box: Placed) -> None:
    canvas.add(f'<g class="ns procs"><rect x="{num(box.x)}" y="{num(box.y)}" '
               f'width="{num(box.width)}" height="{num(box.height)}" rx="5"/>'
               f'<text class="nsl" x="{num(box.x + PAD)}" y="{num(box.y + 15)}">processes</text>'
               "</g>")
    for index, process in enumerate(processes):
        command = " ".join(str(c) for c in process["cmd"])
        label = str(process["name"] or command)
        y = box.y + HEADER + index * (NODE_H + GAP)
        room = box.width - 2 * PAD - 8
        canvas.add(f'<g class="node process"><title>{esc(command)}\n'
                   f'{esc(process["file"])}:{process["line"]}</title>'
                   f'<rect x="{num(box.x + PAD)}" y="{num(y)}" width="{num(box.width - 2 * PAD)}" '
                   f'height="{NODE_H}" rx="3"/><text class="nl" x="{num(box.x + PAD + 6)}" '
                   f'y="{num(y + 13.5)}"{_fit_attributes(label, room)}>'
                   f"{esc(_fit_text(label, room))}</text></g>")


def tooltip(node: SystemNode) -> str:
    """Return the plain text shown when the pointer rests on a node (escaped by callers)."""
    lines = [node.fqn, f"{node.executable or '?'}  ({node.kind.replace('_', ' ')})"]
    if node.named_by_code:
        lines.append(NAMED_BY_CODE)
    if node.condition:
        lines.append(f"when {node.condition}")
    if node.manager is not None:
        verdict = "completes" if node.manager["completes"] else "does not complete"
        lines.append(f"lifecycle manager, bring-up {verdict}: "
                     + ", ".join(node.manager["node_names"]))
    elif node.managed:
        lines.append("lifecycle, can reach: " + (", ".join(node.states) or "no state"))
    if node.container:
        lines.append(f"in container {node.container}")
    if node.components:
        lines.append(f"hosts {len(node.components)} components")
    lines += [f"remap {src} -> {dst}" for src, dst in node.remappings]
    lines += [f"param {name} = {value}"
              for name, value, _ in node.parameters[:TOOLTIP_PARAMETERS]]
    if len(node.parameters) > TOOLTIP_PARAMETERS:
        lines.append(f"... {len(node.parameters) - TOOLTIP_PARAMETERS} more parameters")
    lines += [f"{m.code}: {m.message}" for m in node.marks]
    lines.append(node.where)
    return "\n".join(lines)
