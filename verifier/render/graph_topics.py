"""The computation-graph part of ``launchverify graph``: topics, services, actions.

Shapes the composed endpoints (``topology.compose``) into the documented JSON fields and a
short text section; which nodes take part follows ``GraphView`` (only those that run
under the given arguments, or all of them with ``--symbolic``).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, TextIO

from launchverify.workspace.paths import display_path

if TYPE_CHECKING:
    from launchverify.render.graph_out import GraphView
    from launchverify.topology.compose import ComposedEndpoint, InterfaceSource, NodeEndpoints
    from launchverify.topology.connections import Connection


def composed_nodes(view: GraphView, source: InterfaceSource) -> list[NodeEndpoints]:
    """Return the view's nodes with their endpoints (reads the sources, once per package)."""
    from launchverify.topology.compose import compose

    return compose(view.graph, source, symbolic=view.symbolic)


def node_interface(view: GraphView, composed: NodeEndpoints) -> dict[str, Any]:
    """Return ``nodes[].interface``: whether the sources were read, and what stays unknown."""
    interface = composed.interface
    return {
        "found": interface is not None,
        "note": composed.note,
        "problems": list(interface.problems) if interface is not None else [],
        "endpoints": len(composed.endpoints),
        "unresolved": [{
            "kind": c.endpoint.kind.value, "written": c.endpoint.name,
            "parameter": c.endpoint.name_parameter, "reason": c.reason,
            "file": display_path(c.endpoint.span.file), "line": c.endpoint.span.line,
        } for c in composed.endpoints if c.name is None],
        "parameters": [] if interface is None else [{
            "name": p.name, "type": p.type, "default": p.default, "dynamic": p.dynamic,
            "required": p.required, "via": p.via,
            "file": display_path(p.span.file), "line": p.span.line,
        } for p in interface.parameters],
        "parameters_open": None if interface is None else interface.parameters_open,
    }


def sections(view: GraphView, nodes: list[NodeEndpoints]) -> dict[str, list[dict[str, Any]]]:
    """Return ``topics``, ``services`` and ``actions`` as documented in docs/output.md."""
    from launchverify.topology.connections import SECTIONS, connections

    fqns = {id(n.node): n.fqn for n in nodes}
    grouped = connections(nodes)
    found: dict[str, list[dict[str, Any]]] = {
        section: [_connection(view, c, fqns) for c in grouped[section]]
        for section in SECTIONS}
    found["controllers"] = [_controller(view, n) for n in nodes if n.spawn is not None]
    return found


def _controller(view: GraphView, composed: NodeEndpoints) -> dict[str, Any]:
    """Return one controller a spawner loads: where it runs, its type, what is unknown."""
    assert composed.spawn is not None
    where = view.where(composed.spawn.spawner.origin)
    return {
        "name": composed.spawn.name,
        "node": composed.fqn,
        "manager": composed.spawn.manager,
        "type": composed.executable,
        "defined": not composed.spawn.undefined,
        "found": composed.interface is not None,
        "note": composed.note,
        "spawner": f"{where['file']}:{where['line']}",
        "condition": where["condition"],
    }


def _connection(view: GraphView, connection: Connection,
                fqns: dict[int, str | None]) -> dict[str, Any]:
    from launchverify.topology.connections import SECTIONS

    types = connection.types()
    conditions = {view.where(e.node.origin)["condition"] for e in connection.endpoints()}
    condition = None
    if None not in conditions:
        texts = sorted(c for c in conditions if c is not None)
        condition = texts[0] if len(texts) == 1 else " or ".join(f"({t})" for t in texts)
    out: dict[str, Any] = {"name": connection.name,
                           "type": types[0] if len(types) == 1 else None, "types": types}
    for role in SECTIONS[connection.section]:
        out[role] = [_end(view, e, fqns) for e in connection.ends.get(role, [])]
    out["condition"] = condition
    return out


def _end(view: GraphView, composed: ComposedEndpoint,
         fqns: dict[int, str | None]) -> dict[str, Any]:
    node, endpoint = composed.node, composed.endpoint
    where = view.where(node.origin)
    return {
        "node": fqns.get(id(node)) or view.value(node.fqn),
        "package": view.value(node.package),
        "executable": view.value(node.executable),
        "type": endpoint.type,
        "written": endpoint.name if endpoint.name_parameter is None else None,
        "parameter": endpoint.name_parameter,
        "value_from": composed.value_from,
        "remapped_by": composed.remapped_by,
        "via": endpoint.via,
        "qos": None if endpoint.profile is None else {
            "reliability": endpoint.profile.reliability,
            "durability": endpoint.profile.durability},
        "source": f"{display_path(endpoint.span.file)}:{endpoint.span.line}",
        "launch": f"{where['file']}:{where['line']}",
        "condition": where["condition"],
        "domain": (view.dds(node) or {}).get("domain"),
    }


def render_text(doc: dict[str, Any], out: TextIO) -> None:
    """Write the short text section: each name with who publishes and who listens."""
    for section, roles in (("topics", ("publishers", "subscribers")),
                           ("services", ("servers", "clients")),
                           ("actions", ("servers", "clients"))):
        entries = doc.get(section)
        if not entries:
            continue
        out.write(f"{section}:\n")
        for entry in entries:
            kind = entry["type"] or (" | ".join(entry["types"]) or "?")
            out.write(f"    {entry['name']}  {kind}\n")
            for role in roles:
                names = ", ".join(str(e["node"] or e["executable"]) for e in entry[role])
                if names:
                    out.write(f"        {role}: {names}\n")
            if entry["condition"]:
                out.write(f"        when {entry['condition']}\n")
    if doc.get("controllers"):
        out.write("controllers:\n")
        for entry in doc["controllers"]:
            kind = entry["type"] or "type not known"
            out.write(f"    {entry['node'] or entry['name']}  {kind}  (in "
                      f"{entry['manager'] or '?'}, spawned at {entry['spawner']})\n")
    modelled = [node for node in doc["nodes"] if node.get("interface")
                and node["interface"]["found"] and node["interface"]["note"]]
    if modelled:
        out.write("from shipped models:\n")
        for node in modelled:
            who = node["fqn"] or f"{node['package']}/{node['executable']}"
            out.write(f"    {who}: {node['interface']['note']}\n")
    missing = [node for node in doc["nodes"]
               if node.get("interface") and not node["interface"]["found"]]
    if missing:
        out.write("no interface:\n")
        for node in missing:
            who = node["fqn"] or f"{node['package']}/{node['executable']}"
            out.write(f"    {who}: {node['interface']['note']}\n")
    unresolved = [(node["fqn"] or node["executable"], item)
                  for node in doc["nodes"] if node.get("interface")
                  for item in node["interface"]["unresolved"]]
    if unresolved:
        out.write("not resolved:\n")
        for who, item in unresolved:
            out.write(f"    {who}: {item['kind']} {item['written'] or '?'}  ({item['file']}:"
                      f"{item['line']}): {item['reason']}\n")
