"""What the report's picture shows: the launched nodes of one graph, by namespace.

Built from ``GraphView(graph, symbolic=False).document()`` (what ``launchverify graph``
prints) so that the picture and the JSON never disagree; only the placement of findings
on nodes needs the records themselves (their include chains).
"""

from __future__ import annotations

import json
from collections import defaultdict
from dataclasses import dataclass, field
from typing import Any

from launchverify.dds.discovery import CALLER
from launchverify.engine import Report
from launchverify.graph import LaunchGraph
from launchverify.render.graph_out import GraphView, unnamed_label
from launchverify.rule import Finding, Severity
from launchverify.span import Span

# The states a managed node can rest in, best first: the picture shows the best reachable.
RESTING = ("active", "inactive", "unconfigured", "finalized")
PARAMETER_VALUE_LIMIT = 160
NAMED_BY_CODE = "named by its sources (the launch gives no name)"


@dataclass
class Mark:
    """A finding shown on a node: its code, severity and anchor in the page."""

    code: str
    severity: Severity
    anchor: str
    message: str


@dataclass
class SystemNode:
    """One node of the picture, with what its tooltip and table row say."""

    index: int
    fqn: str
    name: str
    namespace: str
    kind: str
    executable: str
    where: str
    condition: str | None
    managed: bool  # a lifecycle node, or driven by a lifecycle manager
    states: list[str]
    manager: dict[str, Any] | None  # the nav2 manager's entry when the node is one
    container: str | None
    remappings: list[tuple[str, str]]
    parameters: list[tuple[str, str, str]]  # name, value, where it comes from
    domain: str | None = None  # its DDS domain, as ``graph`` gives it
    named_by_code: bool = False  # the launch gives no name: its sources (or model) do
    marks: list[Mark] = field(default_factory=list)
    components: list[SystemNode] = field(default_factory=list)

    @property
    def is_container(self) -> bool:
        """Return whether the node hosts components."""
        return self.kind == "node_container" or bool(self.components)

    @property
    def resting(self) -> str | None:
        """Return the best state the node can rest in (managed nodes), else ``None``."""
        return next((s for s in RESTING if s in self.states), None) if self.managed else None

    @property
    def worst(self) -> Severity | None:
        """Return the most severe finding on the node."""
        return max((m.severity for m in self.marks), key=lambda s: s.rank, default=None)


@dataclass
class Namespace:
    """A namespace box: its own nodes and the namespaces below it."""

    path: str
    label: str
    nodes: list[SystemNode] = field(default_factory=list)
    children: dict[str, Namespace] = field(default_factory=dict)
    kept: bool = False  # a DDS domain's box: drawn even when it holds one namespace

    def count(self) -> int:
        """Return how many nodes (components included) the box holds, nested ones too."""
        own = sum(1 + len(n.components) for n in self.nodes)
        return own + sum(c.count() for c in self.children.values())


@dataclass
class SystemModel:
    """The picture's data for one root launch file."""

    root: Namespace
    nodes: list[SystemNode]
    processes: list[dict[str, Any]]
    lifecycle: dict[str, Any] | None

    def namespaces(self) -> int:
        """Return how many namespaces hold nodes."""
        def walk(ns: Namespace) -> int:
            return int(bool(ns.nodes)) + sum(walk(c) for c in ns.children.values())
        return walk(self.root)


def build_model(report: Report, graph: LaunchGraph, anchors: dict[int, str],
                names: dict[int, str] | None = None) -> SystemModel:
    """Return the picture's data for one graph; ``anchors`` maps finding ids to anchors.

    ``names``: the fully qualified names the sources give nodes the launch leaves
    unnamed, by the id of their record (``Composition.names``), so that a node has the
    name the computation graph beside the picture gives it.
    """
    names = names or {}
    view = GraphView(graph, symbolic=False)
    document = view.document()
    records = [n for n in graph.nodes if view.shown(n.origin)]
    lifecycle = document["lifecycle"]
    states = {n["fqn"]: list(n["states"]) for n in (lifecycle or {}).get("nodes", [])}
    managers = {m["fqn"]: m for m in (lifecycle or {}).get("managers", [])}
    marks = _marks(report, records, anchors)
    nodes = []
    for index, (entry, record) in enumerate(zip(document["nodes"], records, strict=True)):
        code_name = names.get(id(record)) if entry["fqn"] is None else None
        fqn = entry["fqn"] or code_name or unnamed_label(entry["executable"])
        nodes.append(SystemNode(
            index=index, fqn=fqn, name=entry["name"] or fqn.rsplit("/", 1)[-1],
            namespace=_namespace_of(entry, fqn), kind=entry["kind"],
            executable="/".join(str(p) for p in (entry["package"], entry["executable"])
                                if p is not None),
            where=f"{report.display_path(record.origin.span.file)}:{entry['line']}",
            condition=entry["condition"],
            managed=bool(entry["lifecycle"]) or fqn in states,
            states=states.get(fqn, []), manager=managers.get(fqn),
            container=entry["container"],
            remappings=[(str(s), str(d)) for s, d in entry["remappings"]],
            parameters=_parameters(entry), marks=marks.get(index, []),
            domain=(entry["dds"] or {}).get("domain"), named_by_code=code_name is not None))
    return SystemModel(_by_domain(nodes), nodes, document["processes"], lifecycle)


def _by_domain(nodes: list[SystemNode]) -> Namespace:
    """Return the namespace tree, under one box per DDS domain when there are several.

    A component is in its container's domain, so a container never leaves its box.
    """
    domains: dict[str | None, list[SystemNode]] = defaultdict(list)
    for node in nodes:
        domains[node.domain].append(node)
    if len(domains) < 2:
        return _group(nodes)
    root = Namespace("/", "/")
    for domain, members in sorted(domains.items(), key=lambda item: _domain_key(item[0])):
        tree = _group(members)
        label = ("DDS domain not known" if domain is None
                 else "DDS domain: the caller's" if domain == CALLER
                 else f"DDS domain {domain}")
        root.children[label] = Namespace(f"({label})", label, tree.nodes, tree.children,
                                         kept=True)
    return root


def _domain_key(domain: str | None) -> tuple[int, int, str]:
    """Sort domains by number, the caller's and unknown ones last."""
    if domain is None:
        return (2, 0, "")
    return (0, int(domain), "") if domain.isdigit() else (1, 0, domain)


def _namespace_of(entry: dict[str, Any], fqn: str) -> str:
    namespace = entry["namespace"]
    if isinstance(namespace, str) and namespace.startswith("/"):
        return namespace.rstrip("/") or "/"
    parent = fqn.rsplit("/", 1)[0] if fqn.startswith("/") else ""
    return parent or "/"


def _parameters(entry: dict[str, Any]) -> list[tuple[str, str, str]]:
    """Return the parameters a node receives (effective values), else those written."""
    effective = entry["effective_parameters"]
    if effective:
        return [(name, _value(value["value"]), value["from"])
                for name, value in effective.items()]
    return [(str(p["name"]), _value(p["value"]), "") for p in entry["parameters"]
            if "file" not in p]


def _value(value: object) -> str:
    """Return a parameter value as written in YAML (``true``, ``[a, b]``), cut if long."""
    try:
        text = value if isinstance(value, str) else json.dumps(value, ensure_ascii=False)
    except (TypeError, ValueError):
        text = repr(value)
    return text if len(text) <= PARAMETER_VALUE_LIMIT else text[:PARAMETER_VALUE_LIMIT] + "\u2026"


def _span_key(span: Span) -> tuple[str, int]:
    return (str(span.file), span.line)


def _marks(report: Report, records: list[Any], anchors: dict[int, str]
           ) -> dict[int, list[Mark]]:
    """Return the findings that point at each node (by index).

    A finding names one instance of a node through its include chain; a finding without
    a matching chain (found where the file was checked alone) marks every instance.
    """
    at: dict[tuple[str, int], list[int]] = defaultdict(list)
    for index, record in enumerate(records):
        at[_span_key(record.origin.span)].append(index)
    marks: dict[int, list[Mark]] = defaultdict(list)
    for finding in report.findings:
        candidates = at.get(_span_key(finding.span), [])
        if not candidates:
            continue
        exact = [i for i in candidates if records[i].origin.chain == finding.chain]
        for index in exact or candidates:
            marks[index].append(_mark(finding, anchors.get(id(finding), "")))
    return marks


def _mark(finding: Finding, anchor: str) -> Mark:
    return Mark(finding.code, finding.severity, anchor, finding.message)


def _group(nodes: list[SystemNode]) -> Namespace:
    """Return the namespace tree; components go inside their container when it runs."""
    # a container is a node_container, or any node components are loaded into (nav2
    # starts component_container_isolated as a plain Node)
    hosts = {n.container for n in nodes if n.container}
    by_fqn = {n.fqn: n for n in nodes if n.kind == "node_container" or n.fqn in hosts}
    root = Namespace("/", "/")
    for node in nodes:
        host = by_fqn.get(node.container or "") if node.kind.startswith("composable") else None
        if host is None and node.container and node.kind.startswith("composable"):
            host = next((c for c in by_fqn.values()
                         if c.fqn.rsplit("/", 1)[-1] == node.container.strip("/")), None)
        if host is not None and host is not node:
            host.components.append(node)
            continue
        _namespace(root, node.namespace).nodes.append(node)
    return root


def _namespace(root: Namespace, path: str) -> Namespace:
    current = root
    for part in [p for p in path.split("/") if p]:
        child_path = (current.path.rstrip("/") + "/" + part)
        current = current.children.setdefault(part, Namespace(child_path, part))
    return current
