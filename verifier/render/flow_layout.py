"""Where the computation graph's elements go: layered boxes per namespace, packed.

Each namespace is a box laid out on its own, left to right along the data: an element's
column is the longest chain of edges (inside the box) that leads to it, after the edges
closing a cycle are set aside; sources with a single use move next to it. Within a
column, elements are ordered by the mean position of their neighbours (a few sweeps each
way), which untangles most crossings. A column taller than ``MAX_ROWS`` wraps into more
columns. The boxes are then packed into a fixed width, each where it sits highest.

Everything is ordered by names and keys, never by hashing or timing: the same graph
gives the same picture, byte for byte.
"""

from __future__ import annotations

import math
from collections import defaultdict
from dataclasses import dataclass, field

from launchverify.render.flow_model import FlowGraph, natural

ROW = 24  # vertical pitch of elements in a column
NODE_H = 20
TOPIC_H = 16
COLUMN_GAP = 36  # room for the curves between columns
PAD = 8
HEADER = 20  # namespace label band
CLUSTER_GAP = 14
TARGET_W = 1360  # width boxes are packed into (a wider box widens the picture)
MIN_W = 56
MAX_W = 300  # a longer label is cut in the middle (its tooltip has it whole)
CHAR_W = 6.62  # advance of one character of the 11px monospace label font
TOPIC_CHAR_W = 6.02  # the 10px one of topics
MAX_ROWS = 24  # elements in a column before it wraps
GRID_GAP = 10  # between cells of the grid of unconnected elements
LOOSE_W = 560  # width a grid may take when the columns are narrower
SWEEPS = 4


@dataclass
class Box:
    """An element's place, in picture coordinates."""

    key: str
    x: float
    y: float
    width: float
    height: float

    @property
    def left(self) -> tuple[float, float]:
        """Return where arrows come in."""
        return self.x, self.y + self.height / 2

    @property
    def right(self) -> tuple[float, float]:
        """Return where arrows leave."""
        return self.x + self.width, self.y + self.height / 2


@dataclass
class Cluster:
    """A namespace's box and its elements' columns (relative to the box until placed)."""

    namespace: str
    columns: list[list[str]]
    widths: list[float]
    layered: float = 0  # height of the columns
    grid: list[str] = field(default_factory=list)  # elements without arrows, below
    grid_columns: int = 1
    cell: float = 0  # width of a grid cell
    x: float = 0
    y: float = 0
    width: float = 0
    height: float = 0

    def members(self) -> list[str]:
        """Return the box's elements, column by column, then its grid."""
        return [k for column in self.columns for k in column] + self.grid


@dataclass
class FlowLayout:
    """The placed picture: every element's box and every namespace's."""

    boxes: dict[str, Box] = field(default_factory=dict)
    clusters: list[Cluster] = field(default_factory=list)
    width: float = 0
    height: float = 0


def label_of(flow: FlowGraph, key: str, namespace: str) -> str:
    """Return an element's shown name: relative to its namespace box, whose label says it."""
    node = flow.nodes.get(key)
    name = node.fqn if node is not None else flow.topics[key].label
    if node is None and flow.topics[key].tf:
        return name
    if namespace != "/" and name.startswith(namespace + "/"):
        return name[len(namespace) + 1:]
    return name


def element_width(flow: FlowGraph, key: str, namespace: str) -> float:
    """Return the width an element's label asks for, within MIN_W and MAX_W."""
    text = label_of(flow, key, namespace)
    char = CHAR_W if key in flow.nodes else TOPIC_CHAR_W
    badges = 16 if key in flow.nodes and (flow.nodes[key].condition or not
                                          flow.nodes[key].known) else 0
    return min(MAX_W, max(MIN_W, len(text) * char + 14 + badges))


def layout(flow: FlowGraph) -> FlowLayout:
    """Return where every element and namespace box of ``flow`` goes."""
    members: dict[str, list[str]] = defaultdict(list)
    for key in [*flow.nodes, *flow.topics]:
        members[flow.namespace_of(key)].append(key)
    out = FlowLayout()
    for namespace in flow.namespaces():
        cluster = _cluster(flow, namespace, members[namespace])
        out.clusters.append(cluster)
    _pack(out.clusters)
    for cluster in out.clusters:
        _place(flow, cluster, out.boxes)
    out.width = max((c.x + c.width for c in out.clusters), default=0)
    out.height = max((c.y + c.height for c in out.clusters), default=0)
    return out


# ------------------------------------------------------------------ one namespace


def _order(flow: FlowGraph, key: str) -> tuple[int, list[tuple[int, int | str]], str]:
    """Return the reading order of elements: nodes first, then by label."""
    if key in flow.nodes:
        return (0, natural(flow.nodes[key].fqn), key)
    topic = flow.topics[key]
    return (1 if not topic.tf else 2, natural(topic.label), key)


def _cluster(flow: FlowGraph, namespace: str, keys: list[str]) -> Cluster:
    keys = sorted(keys, key=lambda k: _order(flow, k))
    inside = set(keys)
    successors: dict[str, list[str]] = {k: [] for k in keys}
    predecessors: dict[str, list[str]] = {k: [] for k in keys}
    for edge in flow.edges:  # tf edges are hidden: they must not shape the columns
        if edge.tf or edge.source not in inside or edge.target not in inside:
            continue
        successors[edge.source].append(edge.target)
        predecessors[edge.target].append(edge.source)
    linked = [k for k in keys if successors[k] or predecessors[k]]
    forward = _acyclic(linked, successors, predecessors)
    rank = _ranks(linked, forward)
    levels = sorted(set(rank.values()))
    columns: list[list[str]] = [[] for _ in levels]
    position = {level: i for i, level in enumerate(levels)}
    for key in linked:
        columns[position[rank[key]]].append(key)
    _sweep(columns, successors, predecessors)
    columns = [chunk for column in columns for chunk in _wrap(column)]
    widths = [max(element_width(flow, k, namespace) for k in column) for column in columns]
    width = sum(widths) + COLUMN_GAP * (len(columns) - 1) if columns else 0.0
    height = float(max((len(c) for c in columns), default=0) * ROW - (ROW - NODE_H))
    cluster = Cluster(namespace, columns, widths, layered=max(height, 0))
    loose = [k for k in keys if not successors[k] and not predecessors[k]]
    if loose:  # unconnected elements: a grid under the flow, as wide as it
        cluster.cell = max(element_width(flow, k, namespace) for k in loose)
        room = max(width, LOOSE_W)
        fit = max(1, int((room + GRID_GAP) // (cluster.cell + GRID_GAP)))
        cluster.grid_columns = min(fit, len(loose))
        cluster.grid = loose
        rows = math.ceil(len(loose) / cluster.grid_columns)
        width = max(width, cluster.grid_columns * (cluster.cell + GRID_GAP) - GRID_GAP)
        height = cluster.layered + (ROW if columns else 0) + rows * ROW - (ROW - NODE_H)
    label_w = len(namespace) * 7.2 + 60  # the header's text and count
    cluster.width = max(width, label_w) + 2 * PAD
    cluster.height = HEADER + height + PAD
    return cluster


def _acyclic(keys: list[str], successors: dict[str, list[str]],
             predecessors: dict[str, list[str]]) -> dict[str, list[str]]:
    """Return the edges without those closing a cycle (found by a depth-first walk).

    The walk starts from the elements nothing feeds (drivers, unpublished topics), so a
    loop is cut where it returns towards them: sensors -> ... -> base driver, and the
    odometry it publishes back to the localizer is the edge set aside.
    """
    forward: dict[str, list[str]] = {k: [] for k in keys}
    state: dict[str, int] = {}  # 1 on the walk's stack, 2 done
    starts = [k for k in keys if not predecessors[k]] + [k for k in keys if predecessors[k]]
    for start in starts:
        if start in state:
            continue
        state[start] = 1
        stack = [(start, iter(successors[start]))]
        while stack:
            key, pending = stack[-1]
            step = next(pending, None)
            if step is None:
                state[key] = 2
                stack.pop()
                continue
            if state.get(step) == 1:
                continue  # back to an element on the walk: this edge closes a cycle
            forward[key].append(step)
            if step not in state:
                state[step] = 1
                stack.append((step, iter(successors[step])))
    return forward


def _ranks(keys: list[str], forward: dict[str, list[str]]) -> dict[str, int]:
    """Return each element's column: the longest chain leading to it.

    An element nothing leads to (a topic nobody publishes, a driver) then moves right,
    next to the first element it feeds, so it does not sit alone in column 0.
    """
    incoming: dict[str, int] = dict.fromkeys(keys, 0)
    for targets in forward.values():
        for target in targets:
            incoming[target] += 1
    rank = dict.fromkeys(keys, 0)
    ready = [k for k in keys if incoming[k] == 0]
    order: list[str] = []
    while ready:
        key = ready.pop(0)
        order.append(key)
        for target in forward[key]:
            rank[target] = max(rank[target], rank[key] + 1)
            incoming[target] -= 1
            if incoming[target] == 0:
                ready.append(target)
    fed = {t for targets in forward.values() for t in targets}
    for key in reversed(order):
        if key not in fed and forward[key]:
            rank[key] = min(rank[t] for t in forward[key]) - 1
    return rank


def _sweep(columns: list[list[str]], successors: dict[str, list[str]],
           predecessors: dict[str, list[str]]) -> None:
    """Order each column by its elements' neighbours, sweeping right then left."""
    for sweep in range(SWEEPS):
        rightwards = sweep % 2 == 0
        indices = range(1, len(columns)) if rightwards else range(len(columns) - 2, -1, -1)
        for i in indices:
            reference = columns[i - 1] if rightwards else columns[i + 1]
            where = {k: p for p, k in enumerate(reference)}
            links = predecessors if rightwards else successors
            current = {k: p for p, k in enumerate(columns[i])}

            def centre(key: str, where: dict[str, int] = where,
                       links: dict[str, list[str]] = links,
                       current: dict[str, int] = current) -> tuple[float, int]:
                near = [where[n] for n in links[key] if n in where]
                return (sum(near) / len(near) if near else float(current[key]),
                        current[key])

            columns[i].sort(key=centre)


def _wrap(column: list[str]) -> list[list[str]]:
    """Return a column cut into columns of at most MAX_ROWS, as even as possible."""
    if len(column) <= MAX_ROWS:
        return [column]
    parts = math.ceil(len(column) / MAX_ROWS)
    size = math.ceil(len(column) / parts)
    return [column[i:i + size] for i in range(0, len(column), size)]


# ------------------------------------------------------------------ packing


def _pack(clusters: list[Cluster]) -> None:
    """Place each box where the skyline under it is lowest (then leftmost)."""
    width = max([TARGET_W, *(c.width for c in clusters)])
    skyline: list[tuple[float, float, float]] = [(0.0, width, 0.0)]  # x, width, height
    for cluster in clusters:
        best: tuple[float, float] | None = None
        for x, _w, _h in skyline:
            if x + cluster.width > width + 0.01:
                continue
            y = max(h for sx, sw, h in skyline if sx < x + cluster.width and sx + sw > x)
            if best is None or y < best[1] - 0.01:
                best = (x, y)
        assert best is not None  # the leftmost segment always fits: width >= cluster
        cluster.x, cluster.y = best
        skyline = _raise(skyline, cluster.x, cluster.width + CLUSTER_GAP,
                         cluster.y + cluster.height + CLUSTER_GAP, width)


def _raise(skyline: list[tuple[float, float, float]], x: float, w: float, h: float,
           width: float) -> list[tuple[float, float, float]]:
    """Return the skyline with ``[x, x + w)`` raised to ``h`` (segments merged)."""
    end = min(x + w, width)
    out: list[tuple[float, float, float]] = []
    for sx, sw, sh in skyline:
        if sx + sw <= x or sx >= end:
            out.append((sx, sw, sh))
            continue
        if sx < x:
            out.append((sx, x - sx, sh))
        if sx + sw > end:
            out.append((end, sx + sw - end, sh))
    out.append((x, end - x, h))
    out.sort()
    merged: list[tuple[float, float, float]] = []
    for segment in out:
        if merged and merged[-1][2] == segment[2] and \
                abs(merged[-1][0] + merged[-1][1] - segment[0]) < 0.01:
            merged[-1] = (merged[-1][0], merged[-1][1] + segment[1], segment[2])
        else:
            merged.append(segment)
    return merged


def _place(flow: FlowGraph, cluster: Cluster, boxes: dict[str, Box]) -> None:
    """Give each element of a placed box its coordinates (columns centred vertically)."""
    x = cluster.x + PAD
    for column, width in zip(cluster.columns, cluster.widths, strict=True):
        used = len(column) * ROW - (ROW - NODE_H)
        y = cluster.y + HEADER + (cluster.layered - used) / 2
        for key in column:  # nodes line up in the column; topics keep their own width
            _put(flow, cluster, boxes, key, x, y, width)
            y += ROW
        x += width + COLUMN_GAP
    top = cluster.y + HEADER + (cluster.layered + ROW if cluster.columns else 0)
    for number, key in enumerate(cluster.grid):
        row, cell = divmod(number, cluster.grid_columns)
        _put(flow, cluster, boxes, key, cluster.x + PAD + cell * (cluster.cell + GRID_GAP),
             top + row * ROW, cluster.cell)


def _put(flow: FlowGraph, cluster: Cluster, boxes: dict[str, Box], key: str, x: float,
         y: float, width: float) -> None:
    if key in flow.nodes:
        boxes[key] = Box(key, x, y, width, NODE_H)
    else:
        own = element_width(flow, key, cluster.namespace)
        boxes[key] = Box(key, x, y + (NODE_H - TOPIC_H) / 2, own, TOPIC_H)
