"""The computation graph as inline SVG, with its filter box and tf switch.

Elements are drawn where ``flow_layout`` put them; arrows are cubic curves from an
element's right side into the next one's left side, with a drawn arrowhead (no SVG
markers: those are referenced through ``url(...)``, which the page does without). The
page works without JavaScript: the tf switch is a checkbox styled in CSS, and only the
filter box needs the report's script (it stays hidden without it).
"""

from __future__ import annotations

from launchverify.render.flow_layout import CHAR_W as NODE_CHAR_W
from launchverify.render.flow_layout import TOPIC_CHAR_W, Box, FlowLayout, label_of, layout
from launchverify.render.flow_model import FlowEdge, FlowGraph, FlowNode, FlowTopic
from launchverify.render.html_shared import First, Shared
from launchverify.render.html_text import clip, esc, num

CONDITION_LIMIT = 400  # characters of a path condition in a tooltip
NAMES_LIMIT = 10  # names listed per role in a tooltip
ARROW = 6  # length of an arrowhead
VERBS = {("topics", "publishers"): "publishes", ("topics", "subscribers"): "subscribes to",
         ("services", "servers"): "serves", ("services", "clients"): "calls",
         ("actions", "servers"): "serves action", ("actions", "clients"): "calls action"}
SIDES = {"topics": ("published by", "subscribed by"), "services": ("called by", "served by"),
         "actions": ("called by", "served by")}
MISSING = {"publisher": "nobody in this launch publishes it",
           "subscriber": "nobody in this launch subscribes to it",
           "server": "nobody in this launch serves it"}

FLOW_LEGEND = (
    '<ul class="legend flow-legend">'
    '<li><span class="sw"></span>node</li>'
    '<li><span class="sw sw-cond"></span>node started under a condition</li>'
    '<li><span class="sw sw-unknown"></span>node whose sources were not read</li>'
    '<li><span class="pill p-topics"></span>topic</li>'
    '<li><span class="pill p-services"></span>service</li>'
    '<li><span class="pill p-actions"></span>action</li>'
    '<li><span class="pill p-ref"></span>topic of another namespace, repeated</li>'
    '<li><span class="pill p-missing"></span>nobody publishes (or serves) it</li>'
    '<li><span class="pill p-unread"></span>nobody subscribes to it</li>'
    '<li><span class="ln"></span>publishes / subscribes</li>'
    '<li><span class="ln ln-services"></span>calls / serves</li>'
    '<li><span class="ln ln-actions"></span>action</li>'
    "</ul>"
)


def render_flow(flow: FlowGraph, number: int, anchor: str, shared: Shared | None = None,
                ) -> str:
    """Return the computation graph section of system ``number``.

    Node boxes link to ``#{anchor}-{index}``, the node's row in the table below. A graph
    an earlier system drew (``shared``) is not drawn again: the section links to it.
    """
    summary = f"Computation graph: {_summary(flow)}"
    if flow.reason is not None:
        return (f'<details class="flow-section" open><summary>{summary}</summary>'
                f'<p class="note">Not drawn: {esc(flow.reason)}.</p></details>')
    if not flow.nodes:
        return ""
    ident = f"flow{number}"
    if shared is not None:
        # the picture is drawn from these alone (and the anchors): equal data, equal picture
        key = "flow:" + repr((flow.nodes, flow.topics, flow.edges, flow.containers))
        seen = shared.earlier(key, First(f"{ident}-svg", f"{ident}-svg", "", number))
        if seen is not None:
            return (f'<details class="flow-section" open><summary>{summary}</summary>'
                    f'<p class="same">The same computation graph as <a href="#{seen.href}">'
                    f"system {seen.system}'s</a> (its boxes lead to the nodes there, the "
                    "same nodes as here).</p></details>")
    placed = layout(flow)
    has_tf = any(e.tf for e in flow.edges)
    tools = (f'<div class="flow-tools"><input type="search" class="flow-filter" '
             f'data-flow="{ident}-svg" list="{ident}-names" '
             'placeholder="filter: part of a node\'s name" '
             'aria-label="show only matching nodes and their neighbours" hidden>'
             '<span class="flow-status"></span></div>')
    if has_tf:  # a checkbox before the picture: CSS shows the tf arrows, no script needed
        tools += (f'<input type="checkbox" class="tf-toggle" id="{ident}-tf">'
                  f'<label class="tf-label" for="{ident}-tf">show the /tf arrows</label>')
    # the filter's suggestions (the nodes' names) are the script's to list: the box is
    # hidden without it
    return (f'<details class="flow-section" open><summary>{summary}</summary>'
            f'<div class="flow">{tools}'
            f'<div class="picture">{render_flow_svg(flow, placed, ident, anchor)}</div>'
            "</div></details>")


def _summary(flow: FlowGraph) -> str:
    sections = {"topics": 0, "services": 0, "actions": 0}
    for topic in flow.topics.values():
        if topic.ref is None:
            sections[topic.section] += len(topic.names)
    facts = [f"{len(flow.nodes)} node{'s' if len(flow.nodes) != 1 else ''}"]
    if flow.reason is None:
        facts += [f"{count} {section if count != 1 else section[:-1]}"
                  for section, count in sections.items() if count or section == "topics"]
        unknown = len(flow.nodes) - flow.known()
        if unknown:
            facts.append(f"{unknown} without sources")
    return esc(", ".join(facts))


def render_flow_svg(flow: FlowGraph, placed: FlowLayout, ident: str, anchor: str) -> str:
    """Return the picture: namespace boxes, then arrows, then elements on top."""
    width, height = f"{placed.width:.0f}", f"{placed.height:.0f}"
    parts = [f'<svg class="flow-svg" id="{esc(ident)}-svg" role="img" width="{width}" '
             f'height="{height}" viewBox="0 0 {width} {height}" '
             f'data-box="0 0 {width} {height}" aria-label="computation graph: '
             f'{len(flow.nodes)} nodes, {len(flow.topics)} topics, services and actions">']
    for cluster in placed.clusters:
        count = len(cluster.members())
        parts.append(f'<g class="fc"><rect x="{num(cluster.x)}" y="{num(cluster.y)}" '
                     f'width="{num(cluster.width)}" height="{num(cluster.height)}" rx="5"/>'
                     f'<text class="nsl" x="{num(cluster.x + 8)}" y="{num(cluster.y + 14)}">'
                     f"{esc(cluster.namespace)}</text>"
                     f'<text class="nsc" x="{num(cluster.x + cluster.width - 8)}" '
                     f'y="{num(cluster.y + 14)}">{count}</text></g>')
    parts += [_edge(flow, placed, edge) for edge in flow.edges]
    for cluster in placed.clusters:
        for key in cluster.members():
            box = placed.boxes[key]
            node = flow.nodes.get(key)
            if node is not None:
                parts.append(_node(node, box, cluster.namespace, anchor, flow))
            else:
                parts.append(_topic(flow.topics[key], box, cluster.namespace, flow))
    parts.append("</svg>")
    return "".join(parts)


def _edge(flow: FlowGraph, placed: FlowLayout, edge: FlowEdge) -> str:
    (sx, sy), (tx, ty) = placed.boxes[edge.source].right, placed.boxes[edge.target].left
    end = tx - ARROW
    reach = max(18.0, (end - sx) / 2) if end > sx else 60.0
    classes = ["fedge", f"e-{edge.section}"]
    if edge.tf:
        classes.append("e-tf")
    return (f'<g class="{" ".join(classes)}" data-a="{esc(edge.source)}" '
            f'data-b="{esc(edge.target)}"><path class="el" d="M{num(sx)} {num(sy)} '
            f"C{num(sx + reach)} {num(sy)} {num(end - reach)} {num(ty)} {num(end)} {num(ty)}\"/>"
            f'<path class="ah" d="M{num(tx)} {num(ty)}l-{ARROW} -3.5v7z"/></g>')


def _fit(text: str, room: float, char_w: float) -> str:
    """Return a label cut to what fits in ``room``, the ellipsis in the middle.

    Names differ at their ends as often as at their starts (``list_hardware_components``,
    ``list_hardware_interfaces``): both ends stay; the tooltip has the whole name.
    """
    limit = max(int(room / char_w), 3)
    if len(text) <= limit:
        return text
    head = limit // 2
    return text[:head] + "\u2026" + text[len(text) - (limit - 1 - head):]


def _node(node: FlowNode, box: Box, namespace: str, anchor: str, flow: FlowGraph) -> str:
    classes = ["fnode"]
    tag = ""
    if node.condition:
        classes.append("cond")
        tag = "if"
    if not node.known:
        classes.append("unknown")
        tag = "?"
    label = label_of(flow, node.key, namespace)
    room = box.width - 10 - (16 if tag else 0)
    badge = (f'<text class="tag" x="{num(box.x + box.width - 9)}" y="{num(box.y + 14)}">'
             f"{tag}</text>") if tag else ""
    return (f'<a href="#{esc(anchor)}-{node.index}" class="{" ".join(classes)}" '
            f'data-key="{node.key}" data-fqn="{esc(node.fqn)}">'
            f"<title>{esc(node_tooltip(node))}</title>"
            f'<rect x="{num(box.x)}" y="{num(box.y)}" width="{num(box.width)}" '
            f'height="{num(box.height)}" rx="3"/>'
            f'<text class="nl" x="{num(box.x + 5)}" y="{num(box.y + 14)}">'
            f"{esc(_fit(label, room, NODE_CHAR_W))}</text>{badge}</a>")


def _topic(topic: FlowTopic, box: Box, namespace: str, flow: FlowGraph) -> str:
    classes = ["ftopic", f"s-{topic.section}"]
    if topic.tf:
        classes.append("tf")
    if topic.missing is not None:
        classes.append(f"m-{topic.missing}")
    if topic.ref is not None:
        classes.append("ref")
    label = label_of(flow, topic.key, namespace)
    original = f' data-topic="{esc(topic.ref)}"' if topic.ref is not None else ""
    return (f'<g class="{" ".join(classes)}" data-key="{esc(topic.key)}"{original}>'
            f"<title>{esc(topic_tooltip(topic, flow))}</title>"
            f'<rect x="{num(box.x)}" y="{num(box.y)}" width="{num(box.width)}" '
            f'height="{num(box.height)}" rx="{num(box.height / 2)}"/>'
            f'<text class="tl" x="{num(box.x + 7)}" y="{num(box.y + 11.5)}">'
            f"{esc(_fit(label, box.width - 12, TOPIC_CHAR_W))}</text></g>")


def node_tooltip(node: FlowNode) -> str:
    """Return what hovering a node says (plain text; callers escape it)."""
    lines = [node.fqn, f"{node.executable or '?'}  ({node.kind.replace('_', ' ')})"]
    if node.condition:
        lines.append(f"when {clip(node.condition, CONDITION_LIMIT)}")
    if not node.known:
        lines.append(f"interface not known: {node.note or 'no sources read'}")
    for (_section, role), verb in VERBS.items():
        names = node.uses.get(f"{_section}:{role}", [])
        if names:
            lines.append(f"{verb} {_names(names)}")
    if node.unresolved:
        lines.append(f"{len(node.unresolved)} name(s) not known before launch:")
        lines += [f"  {u}" for u in node.unresolved[:NAMES_LIMIT]]
        if len(node.unresolved) > NAMES_LIMIT:
            lines.append(f"  ... {len(node.unresolved) - NAMES_LIMIT} more")
    return "\n".join(lines)


def topic_tooltip(topic: FlowTopic, flow: FlowGraph) -> str:
    """Return what hovering a topic, service or action says (plain text)."""
    kind = topic.section[:-1]
    lines = [f"{kind} {', '.join(topic.names)}"]
    if topic.types:
        lines.append(" | ".join(topic.types))
    source_side, sink_side = SIDES[topic.section]
    for side, keys in ((source_side, topic.sources), (sink_side, topic.sinks)):
        if keys:
            lines.append(f"{side} {_names([flow.nodes[k].fqn for k in keys])}")
    if topic.qos:
        lines.append("QoS (reliability, durability): " + "; ".join(
            f"{flow.nodes[k].fqn} {q}" for k, q in sorted(topic.qos.items())
            if k in flow.nodes)[:CONDITION_LIMIT])
    if topic.maybe:
        lines.append(f"may also be {source_side if not topic.sources else sink_side} "
                     f"{_names(topic.maybe)}, whose name for it is not known before launch")
    if topic.missing is not None:
        unknown = len(flow.nodes) - flow.known()
        lines.append(MISSING[topic.missing] + (
            f" (among the nodes whose sources were read: {unknown} were not)"
            if unknown else ""))
    if topic.ref is not None:
        lines.append(f"shown again here for the nodes of this namespace that use it; "
                     f"it is drawn in {flow.topics[topic.ref].namespace}")
    if topic.tf:
        lines.append("its arrows are hidden unless 'show the /tf arrows' is ticked")
    return "\n".join(lines)


def _names(names: list[str]) -> str:
    unique = list(dict.fromkeys(names))
    shown = ", ".join(unique[:NAMES_LIMIT])
    return shown + (f" and {len(unique) - NAMES_LIMIT} more" if len(unique) > NAMES_LIMIT
                    else "")
