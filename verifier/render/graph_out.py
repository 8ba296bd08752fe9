"""``launchverify graph``: what a launch would start, as JSON or text.

By default only what runs under the given arguments (command line, then defaults) is
shown, with concrete values. ``symbolic`` shows every action the evaluation reached with
its path condition and values as expressions over the arguments.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, TextIO

from launchverify.dds.discovery import CALLER, discovery_of
from launchverify.graph import LaunchGraph, NodeRecord, Origin, ParamRecord
from launchverify.ir.subst import Sub
from launchverify.lifecycle.explore import Where
from launchverify.models import lifecycle as lc
from launchverify.models.booleans import bool_text
from launchverify.models.parameter_values import typed_parameter
from launchverify.models.ros_names import node_fqn
from launchverify.parameters import Contribution, effective_parameters
from launchverify.render.encodable import write_json
from launchverify.workspace.paths import display_path

if TYPE_CHECKING:
    from launchverify.topology.compose import InterfaceSource, NodeEndpoints

BRINGUP_ORDER = ("unconfigured", "configuring", "inactive", "activating", "active")


class GraphView:
    """Turns a graph into plain data, concrete or symbolic.

    With ``interfaces`` (``launchverify graph``), the nodes' endpoints are composed from
    the workspace's sources into ``topics``, ``services`` and ``actions``; without, those
    fields are left out and no source is read.
    """

    def __init__(self, graph: LaunchGraph, symbolic: bool,
                 interfaces: InterfaceSource | None = None) -> None:
        self.graph = graph
        self.symbolic = symbolic
        self.interfaces = interfaces
        self._composed: dict[int, NodeEndpoints] = {}

    def value(self, sub: Sub | None) -> str | None:
        """Return a value for output."""
        if sub is None:
            return None
        if self.symbolic:
            concrete = self.graph.base(sub) if not _has_inputs(sub) else None
            return concrete if concrete is not None else sub.describe()
        return self.graph.display(sub)

    def shown(self, origin: Origin) -> bool:
        """Return whether a record belongs in the output."""
        return self.symbolic or self.graph.runs(origin) is not False

    def where(self, origin: Origin) -> dict[str, Any]:
        """Return the location fields of a record."""
        return {
            "condition": origin.condition_text(),
            "file": display_path(origin.span.file),
            "line": origin.span.line,
        }

    def node(self, node: NodeRecord) -> dict[str, Any]:
        """Return one node as a dict in the documented shape."""
        name = self.value(node.name)
        namespace = self.value(node.namespace)
        fqn = self.value(node.fqn)
        if fqn is None and name is not None and not self.symbolic:
            fqn = node_fqn(namespace or "/", name)
        return {
            "fqn": fqn,
            "name": name,
            "namespace": namespace,
            "package": self.value(node.package),
            "executable": self.value(node.executable),
            "kind": node.kind,
            "lifecycle": node.lifecycle,
            "container": self.value(node.container),
            "remappings": [[self.value(r.src), self.value(r.dst)] for r in node.remappings],
            "parameters": [self.parameter(p) for p in node.parameters],
            "effective_parameters": self.effective(node),
            "dds": self.dds(node),
            **self.where(node.origin),
            **self.interface(node),
        }

    def bridges(self) -> list[dict[str, Any]] | None:
        """Return what domain_bridge nodes forward; ``None`` when one's config is not known."""
        from launchverify.dds.bridges import crossings

        found = crossings(self.graph)
        return None if found is None else [
            {"topic": c.reads, "published_as": c.writes, "type": c.type,
             "from_domain": c.source, "to_domain": c.target,
             "file": display_path(c.span.file) if c.span else None,
             "line": c.span.line if c.span else None}
            for c in found]

    def dds(self, node: NodeRecord) -> dict[str, Any] | None:
        """Return the node's DDS domain and discovery settings, as given.

        Symbolic: the domain's expression, the rest ``None`` (it is rarely an argument).
        """
        found = discovery_of(self.graph, node)
        if self.symbolic:
            source = found.domain_source
            return {"domain": self.value(source) if isinstance(source, Sub) else source,
                    "discovery_range": None, "localhost_only": None}
        return {"domain": found.domain, "discovery_range": found.range,
                "localhost_only": found.localhost_only}

    def interface(self, node: NodeRecord) -> dict[str, Any]:
        """Return ``{"interface": ...}`` for a node when endpoints are composed, else ``{}``."""
        composed = self._composed.get(id(node))
        if composed is None:
            return {}
        from launchverify.render.graph_topics import node_interface

        return {"interface": node_interface(self, composed)}

    def effective(self, node: NodeRecord) -> dict[str, Any] | None:
        """Return what the node receives per parameter, where from, and what it overrides.

        Under the arguments as given; ``None`` in the symbolic view.
        """
        if self.symbolic:
            return None
        resolved = effective_parameters(self.graph, node)
        out: dict[str, Any] = {}
        for name, contributions in sorted(resolved.values.items()):
            *overridden, winner = contributions
            out[name] = {
                **self.contribution(winner),
                "overrides": [self.contribution(c) for c in reversed(overridden)],
            }
        return out

    def contribution(self, contribution: Contribution) -> dict[str, Any]:
        """Return one value of a parameter with its source."""
        found = {"value": contribution.value, "type": contribution.kind,
                 "from": f"{display_path(contribution.span.file)}:{contribution.span.line}",
                 "layer": contribution.layer}
        if contribution.value is None and contribution.written is not None:
            found["expression"] = contribution.written.describe()  # what decides it
        return found

    def parameter(self, param: ParamRecord) -> dict[str, Any]:
        """Return one parameter source."""
        if param.file is not None:
            return {"file": self.value(param.file)}
        return {"name": self.value(param.name),
                "value": self.plain(param.value, param.value_type)}

    def plain(self, value: object, value_type: str | None = None) -> object:
        """Return a parameter value as JSON data, typed as the node would receive it.

        Text from substitutions is typed with launch_ros's YAML rules once it is concrete;
        a value that still depends on arguments (symbolic view) stays an expression.
        """
        if isinstance(value, Sub):
            concrete = self.graph.base(value) if not (self.symbolic and _has_inputs(value)) \
                else None
            if concrete is None:
                return self.value(value)
            return typed_parameter(concrete, value_type)
        if isinstance(value, tuple):
            return [self.plain(v, value_type) for v in value]
        return value

    def document(self) -> dict[str, Any]:
        """Return the whole graph as the documented JSON object."""
        graph = self.graph
        topology: dict[str, Any] = {}
        if self.interfaces is not None:
            from launchverify.render.graph_topics import composed_nodes, sections

            composed = composed_nodes(self, self.interfaces)
            self._composed = {id(c.node): c for c in composed}
            topology = sections(self, composed)
        return {
            "view": view(graph),
            "nodes": [self.node(n) for n in graph.nodes if self.shown(n.origin)],
            "processes": [
                {"cmd": [self.value(c) for c in p.cmd], "name": self.value(p.settings.name),
                 **self.where(p.origin)}
                for p in graph.processes if self.shown(p.origin)
            ],
            "includes": [
                {"target": display_path(i.target) if i.target else self.value(i.location),
                 "status": i.status,
                 "arguments": {n: self.value(v) for n, v, _ in i.arguments if n is not None},
                 "computed_from": i.computed_from, "candidates": list(i.candidates),
                 **self.where(i.origin)}
                for i in graph.includes if self.shown(i.origin)
            ],
            "lifecycle": self.lifecycle(),
            "bridges": self.bridges(),
            "arguments": [
                {"name": a.name, "default": self.value(a.default), "value": self.value(a.value),
                 "description": a.description,
                 "choices": list(a.choices) if a.choices is not None else None,
                 **self.where(a.origin)}
                for a in graph.arguments if self.shown(a.origin)
            ],
            **topology,
        }


    def lifecycle(self) -> dict[str, Any] | None:
        """Return each managed node's reachable states (with a shortest trace to each)."""
        from launchverify.lifecycle import analyse

        analysis = analyse(self.graph)
        system, exploration = analysis.system, analysis.exploration
        if system.empty:
            return None
        order = {s: i for i, s in enumerate(dict.fromkeys(BRINGUP_ORDER + tuple(lc.STATE_IDS)))}

        def steps(where: Where) -> list[dict[str, Any]]:
            return [{"step": step.text,
                     "file": display_path(step.span.file) if step.span else None,
                     "line": step.span.line if step.span else None}
                    for step in exploration.trace(where)]

        nodes = []
        for index, node in enumerate(system.nodes):
            reached = exploration.reached.get(index, {})
            nodes.append({
                "fqn": node.fqn,
                "states": {state: steps(reached[state])
                           for state in sorted(reached, key=lambda s: order.get(s, 99))},
                "followed": index not in exploration.incomplete_nodes,
                **self.where(node.record.origin)})
        managers = [{"fqn": m.spec.fqn, "node_names": list(m.spec.resolved or ()),
                     "autostart": m.spec.autostart, "completes": i in exploration.managers_done,
                     **self.where(m.spec.record.origin)}
                    for i, m in enumerate(system.managers)]
        return {"complete": system.complete and exploration.complete,
                "states_explored": exploration.states, "nodes": nodes, "managers": managers}


def _has_inputs(sub: Sub) -> bool:
    from launchverify.ir.subst import walk
    from launchverify.ir.symbolic import Arg, EnvInput, Select

    return any(isinstance(x, (Arg, EnvInput, Select)) for x in walk(sub))


def view(graph: LaunchGraph) -> dict[str, Any]:
    """Say how the root was judged: launched directly, or meant to be included, and why."""
    if graph.included_elsewhere:
        return {"launched_directly": False, "why": "another launch file of the workspace "
                "includes it: what its includers would provide is not held against it"}
    if not graph.launchable_alone():
        return {"launched_directly": False, "why": "it declares arguments without defaults: "
                "what values given for them would fix is not held against it"}
    return {"launched_directly": True, "why": "no launch file of the workspace includes it: "
            "what ros2 launch would fail on is reported"}


def render_graph_json(graph: LaunchGraph, out: TextIO, *, symbolic: bool = False,
                      interfaces: InterfaceSource | None = None) -> None:
    """Write the graph as JSON (with topics, services and actions given ``interfaces``)."""
    write_json(GraphView(graph, symbolic, interfaces).document(), out)


def unnamed_label(executable: object) -> str:
    """Return how a node is called when neither the launch nor its sources name it.

    One spelling for every output (the listing, the report's picture, its computation
    graph and tooltips): ``<unnamed talker>``.
    """
    return f"<unnamed {executable or 'node'}>"


def render_graph_text(graph: LaunchGraph, out: TextIO, *, symbolic: bool = False,
                      interfaces: InterfaceSource | None = None) -> None:
    """Write the graph as an indented listing."""
    doc = GraphView(graph, symbolic, interfaces).document()
    out.write(f"{'launched directly' if doc['view']['launched_directly'] else 'included'}: "
              f"{doc['view']['why']}\n")
    for node in doc["nodes"]:
        label = node["fqn"] or unnamed_label(node["executable"])
        kind = "" if node["kind"] == "node" else f" [{node['kind']}]"
        out.write(f"{label}{kind}  {node['package']}/{node['executable']}  "
                  f"({node['file']}:{node['line']})\n")
        if node["condition"]:
            out.write(f"    when {node['condition']}\n")
        dds = node["dds"] or {}
        if any(v != CALLER for v in dds.values()):  # what the launch sets
            shown = {k: ("not known" if v is None else v) for k, v in dds.items()}
            out.write(f"    dds domain {shown['domain']}, discovery range "
                      f"{shown['discovery_range']}\n")
        for src, dst in node["remappings"]:
            out.write(f"    remap {src} -> {dst}\n")
        for param in node["parameters"]:
            if "file" in param:
                out.write(f"    params {param['file']}\n")
        for name, value in (node["effective_parameters"] or {}).items():
            overrides = "".join(f"; overrides {_shown(o)} from {o['from']}"
                                for o in value["overrides"])
            out.write(f"    param {name} = {_shown(value)}  ({value['from']}, "
                      f"{value['layer']}{overrides})\n")
        if node["effective_parameters"] is None:
            for param in node["parameters"]:
                if "file" not in param:
                    out.write(f"    param {param['name']} = {param['value']}\n")
    _lifecycle_text(doc["lifecycle"], out)
    if doc["bridges"]:
        out.write("bridges:\n")
        for crossing in doc["bridges"]:
            renamed = (f" as {crossing['published_as']}"
                       if crossing["published_as"] != crossing["topic"] else "")
            out.write(f"    {crossing['topic']}{renamed} [{crossing['type']}]  domain "
                      f"{crossing['from_domain']} -> {crossing['to_domain']}  "
                      f"({crossing['file']}:{crossing['line']})\n")
    for process in doc["processes"]:
        out.write(f"process: {' '.join(str(c) for c in process['cmd'])}  "
                  f"({process['file']}:{process['line']})\n")
    if doc["includes"]:
        out.write("includes:\n")
        for include in doc["includes"]:
            status = "" if include["status"] == "loaded" else f" [{include['status']}]"
            out.write(f"    {include['target']}{status}  ({include['file']}:{include['line']})\n")
            if include["condition"]:
                out.write(f"        when {include['condition']}\n")
            for name, value in include["arguments"].items():
                out.write(f"        {name} := {value}\n")
    if doc["arguments"]:
        out.write("arguments:\n")
        for argument in doc["arguments"]:
            out.write(f"    {argument['name']} = {argument['value']}"
                      f"  (default {argument['default']})\n")
    if interfaces is not None:
        from launchverify.render.graph_topics import render_text

        render_text(doc, out)


def _shown(contribution: dict[str, Any]) -> str:
    """Return a parameter's value as a launch file spells it (``false``, ``'text'``).

    A value not known before the run shows the expression that gives it.
    """
    if contribution["value"] is None:
        expression = contribution.get("expression") or "<not known before the run>"
        return expression if len(expression) <= 160 else expression[:157] + "..."
    return _spelled(contribution["value"])


def _spelled(value: object) -> str:
    if isinstance(value, bool):
        return bool_text(value)
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_spelled(item) for item in value) + "]"
    return repr(value)


def _lifecycle_text(lifecycle: dict[str, Any] | None, out: TextIO) -> None:
    if lifecycle is None:
        return
    out.write("lifecycle:" + ("" if lifecycle["complete"] else
                              "  (incomplete: some triggers are not followed)") + "\n")
    for node in lifecycle["nodes"]:
        out.write(f"    {node['fqn']}  reaches {', '.join(node['states']) or 'nothing'}\n")
        primary = [state for state in node["states"] if state in lc.PRIMARY_STATES]
        if primary and primary[-1] != "unconfigured":
            steps = node["states"][primary[-1]]
            out.write(f"        to {primary[-1]}: " + "; ".join(s["step"] for s in steps) + "\n")
    for manager in lifecycle["managers"]:
        verdict = "completes" if manager["completes"] else "does not complete"
        names = ", ".join(manager["node_names"])
        out.write(f"    manager {manager['fqn']} [{names}] {verdict}\n")
