"""One side of a diff: what each of its launch files starts, as plain data.

A side is checked as ``launchverify check`` would check it (its own configuration, the
same confinement), and each root's graph becomes a ``Launch``: its nodes by fully
qualified name (package, executable, remappings, the value each parameter ends up with
and the file and line that gives it), its arguments, its lifecycle managers. Places are
relative to the side's root, so that the two sides compare by name.
"""

from __future__ import annotations

import dataclasses
import hashlib
import json
import re
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from launchverify.config import Config, confined, find_config, load_config
from launchverify.engine import CheckOptions, NoLaunchFiles, build_index, run_check
from launchverify.findings.fingerprint import fingerprints
from launchverify.findings.incremental import RootResult
from launchverify.graph import LaunchGraph, NodeRecord, Origin
from launchverify.parameters import Contribution
from launchverify.problems import ProblemKind
from launchverify.render.graph_out import GraphView
from launchverify.smt import reasoner_for
from launchverify.topology.compose import WorkspaceInterfaces
from launchverify.workspace.paths import relative_file
from launchverify.workspace.reading import read_file
from launchverify.workspace.sources import source_line


@dataclass
class Launch:
    """What one launch file starts, on one side."""

    file: str  # relative to the side's root
    nodes: dict[str, dict[str, Any]] = field(default_factory=dict)  # by full name
    arguments: dict[str, dict[str, Any]] = field(default_factory=dict)  # by name
    managers: dict[str, list[str]] = field(default_factory=dict)  # lifecycle: node lists
    # nodes that start only for other argument values: "fqn (package/executable)" as
    # written -> the condition they start under
    dormant: dict[str, str] = field(default_factory=dict)
    # each such node under its condition ("<node> when <condition>"): its parameter sources
    # and remappings as written (values as expressions of the arguments)
    dormant_wiring: dict[str, dict[str, list[str]]] = field(default_factory=dict)
    # for each such node, argument values under which it starts ({"use_sim": "true"})
    witnesses: dict[str, dict[str, str]] = field(default_factory=dict)
    includes: dict[str, str] = field(default_factory=dict)  # file or path as written -> status
    # topics, services and actions by name: their type and the nodes on each end
    endpoints: dict[str, dict[str, Any]] = field(default_factory=dict)
    # the files of the side it read (launch, parameter, other files its Python opened),
    # by a digest of their content; None when not known
    inputs: dict[str, str] | None = None
    stopped: bool = False  # the launch stops at an error (what it starts is cut short)


@dataclass
class Snapshot:
    """Every launch file of one side, and its findings by fingerprint."""

    launches: dict[str, Launch] = field(default_factory=dict)
    findings: dict[str, dict[str, Any]] = field(default_factory=dict)
    # each finding's anchor, by fingerprint: the text of the line it points at, stripped
    # ('' when unreadable), as the fingerprint hashes it; findings pair by it (not shown)
    anchors: dict[str, str] = field(default_factory=dict)
    seconds: float = 0.0


@dataclass(frozen=True)
class Request:
    """What to check on each side (the same for both)."""

    paths: tuple[str, ...]  # relative to a side's root ("" for all of it)
    arguments: dict[str, str]
    environment: dict[str, str]
    select: list[str] | None = None
    ignore: tuple[str, ...] = ()
    isolated: bool = False  # no configuration file
    distro: str | None = None
    jobs: int | None = None
    time_limit: float = 10.0
    max_file_size: int = 10_000_000


def take(root: Path, request: Request) -> Snapshot:
    """Check a side and return its snapshot (nothing when it has none of the paths)."""
    started = time.perf_counter()
    paths = [root / p if p else root for p in request.paths]
    paths = [p for p in paths if p.exists()]
    snapshot = Snapshot()
    if not paths:
        return snapshot
    config = _config(root, paths, request)
    options = CheckOptions(
        paths=paths, workspace=root, arguments={**config.arguments, **request.arguments},
        environment={**config.environment, **request.environment}, config=config,
        select=request.select if request.select is not None else config.select,
        ignore=[*config.ignore, *request.ignore], command_select=request.select,
        command_ignore=list(request.ignore), nested_configs=not request.isolated,
        distro=request.distro or config.distro, jobs=request.jobs,
        time_limit=request.time_limit, max_file_size=request.max_file_size)
    try:
        report = run_check(options, keep=True)  # (what each root read comes with it)
    except NoLaunchFiles:
        return snapshot
    local = _Local(root)
    read = report.kept.roots if report.kept is not None else {}
    digests: dict[str, str] = {}
    interfaces = WorkspaceInterfaces(report.packages or build_index(
        paths, root, config.package_paths)[1])
    for graph in report.graphs:
        launch = local.launch(_launch(graph, root, interfaces))
        found = read.get(graph.root)
        if isinstance(found, RootResult) and found.reads is not None:
            launch.inputs = {relative_file(Path(path), root): _digest(path, digests)
                             for path in found.reads if Path(path).is_relative_to(root)}
            for name in _named_files(launch, root):  # (a file rewritten before it is read)
                launch.inputs.setdefault(name, _digest(str(root / name), digests))
        snapshot.launches[launch.file] = launch
    for finding, print_ in zip(report.findings, fingerprints(report.findings, root),
                               strict=True):
        snapshot.findings[print_] = {
            "code": finding.code, "slug": finding.slug, "severity": finding.severity.value,
            "file": relative_file(finding.span.file, root), "line": finding.span.line,
            "message": local.value(finding.message)}
        snapshot.anchors[print_] = source_line(finding.span.file, finding.span.line)
    snapshot.seconds = time.perf_counter() - started
    return snapshot


class _Local:
    """Values with the side's own folder taken out, so that the two sides compare.

    ``$(find-pkg-share demo)/maps/a.yaml`` is a path into each side's tree: the same
    file, in two folders.
    """

    def __init__(self, root: Path) -> None:
        self.prefixes = sorted({f"{root}/", f"{root.resolve()}/"}, key=len, reverse=True)

    def value(self, value: Any) -> Any:
        if isinstance(value, str):
            for prefix in self.prefixes:
                value = value.replace(prefix, "")
            return value
        if isinstance(value, list):
            return [self.value(item) for item in value]
        if isinstance(value, dict):
            return {self.value(key): self.value(item) for key, item in value.items()}
        return value

    def launch(self, launch: Launch) -> Launch:
        """Return a launch with every value of it local (its fields' own, whatever they are)."""
        return dataclasses.replace(launch, **{
            f.name: self.value(getattr(launch, f.name)) for f in dataclasses.fields(launch)})


_FILE_NAME = re.compile(r"[\w.\-/]+\.(?:ya?ml|json)\b")


def _named_files(launch: Launch, root: Path) -> set[str]:
    """Return the side's files its nodes' parameter sources name, as written or rewritten.

    ``RewrittenYaml(params.yaml)`` reads the file at run time: where what it rewrites is
    not followed (``key_rewrites``...), the launch rests on the file all the same.
    """
    written = [source for node in launch.nodes.values() for source in node["parameter_files"]]
    written += [source for wiring in launch.dormant_wiring.values()
                for source in wiring["parameters"] if source.startswith("file ")]
    found = set()
    top = root.resolve()
    for text in written:
        for name in _FILE_NAME.findall(str(text)):
            path = (root / name).resolve()
            if not name.startswith("/") and path.is_relative_to(top) and path.is_file():
                found.add(path.relative_to(top).as_posix())
    return found


def _digest(path: str, known: dict[str, str]) -> str:
    """Return a digest of a file's content (``-`` for one that cannot be read)."""
    if path not in known:
        try:
            known[path] = hashlib.sha256(read_file(Path(path))).hexdigest()[:16]
        except OSError:
            known[path] = "-"
    return known[path]


def _config(root: Path, paths: list[Path], request: Request) -> Config:
    """Return the side's own configuration, as ``check`` would read it there."""
    if request.isolated:
        return Config()
    found = find_config(paths[0])
    if found is None or not found.resolve().is_relative_to(root.resolve()):
        return Config()
    config, _ = confined(load_config(found), paths, root, [])
    return config


class _SideView(GraphView):
    """The graph's concrete view, with places relative to the side's root."""

    def __init__(self, graph: LaunchGraph, root: Path,
                 interfaces: WorkspaceInterfaces | None = None) -> None:
        super().__init__(graph, symbolic=False, interfaces=interfaces)
        self.root = root
        self._relative: dict[Path, str] = {}

    def relative(self, path: Path) -> str:
        """Return a file's path relative to the side's root (each file worked out once)."""
        known = self._relative.get(path)
        if known is None:
            known = self._relative[path] = relative_file(path, self.root)
        return known

    def where(self, origin: Origin) -> dict[str, Any]:
        return {"condition": origin.condition_text(),
                "file": self.relative(origin.span.file), "line": origin.span.line}

    def contribution(self, contribution: Contribution) -> dict[str, Any]:
        found = super().contribution(contribution)
        found["from"] = f"{self.relative(contribution.span.file)}:{contribution.span.line}"
        return found


def _launch(graph: LaunchGraph, root: Path, interfaces: WorkspaceInterfaces) -> Launch:
    """Return what a root's graph starts, under the arguments given (else defaults)."""
    view = _SideView(graph, root, interfaces)
    launch = Launch(relative_file(graph.root, root))
    launch.stopped = any(record.problem.kind in (ProblemKind.PARSE, ProblemKind.EVALUATION)
                         for record in graph.problems)
    symbolic = GraphView(graph, symbolic=True)
    for node in graph.nodes:
        if not view.shown(node.origin):
            key = (f"{symbolic.value(node.fqn) or symbolic.value(node.name)} "
                   f"({symbolic.value(node.package)}/{symbolic.value(node.executable)})")
            condition = node.origin.condition_text() or "(never)"
            known = launch.dormant.get(key)
            launch.dormant[key] = condition if known in (None, condition) \
                else f"{known}, or {condition}"
            launch.dormant_wiring.setdefault(f"{key} when {condition}",
                                             _written(symbolic, node))
            if key not in launch.witnesses:
                witness = reasoner_for(graph).together(node.origin.path)
                if witness is not None and witness.values:
                    launch.witnesses[key] = dict(witness.values)
            continue
        data = _node(view, node)
        key = data["label"]
        while key in launch.nodes:  # two nodes under one name: each kept
            key += "'"
        launch.nodes[key] = data
    for include in graph.includes:
        if view.shown(include.origin):
            target = (relative_file(include.target, root) if include.target is not None
                      else view.value(include.location) or "(unknown)")
            launch.includes.setdefault(target, include.status)
    for argument in graph.arguments:
        if view.shown(argument.origin) and argument.name not in launch.arguments:
            launch.arguments[argument.name] = {
                "default": view.value(argument.default), **view.where(argument.origin)}
    launch.endpoints = _endpoints(view)
    lifecycle = view.lifecycle()
    for manager in (lifecycle or {}).get("managers", []):
        launch.managers[manager["fqn"]] = list(manager["node_names"])
    return launch


def _endpoints(view: _SideView) -> dict[str, dict[str, Any]]:
    """Return each topic, service and action the started nodes use, with who uses it."""
    if view.interfaces is None:
        return {}
    from launchverify.render.graph_topics import sections
    from launchverify.topology.wiring import view_of

    composed = view_of(view.graph, view.interfaces).nodes  # (the rules' own, when kept)
    found = sections(view, composed)
    out: dict[str, dict[str, Any]] = {}
    for kind, ends in (("topics", ("publishers", "subscribers")),
                       ("services", ("servers", "clients")),
                       ("actions", ("servers", "clients"))):
        for entry in found.get(kind, []):
            out[f"{kind[:-1]} {entry['name']}"] = {
                "type": entry["type"],
                **{end: sorted({str(e["node"]) for e in entry[end]}) for end in ends}}
    return out


def _written(view: GraphView, node: NodeRecord) -> dict[str, list[str]]:
    """Return a node's parameter sources and remappings as written (a symbolic view's)."""
    sources = []
    for given in (view.parameter(p) for p in node.parameters):
        sources.append(f"file {given['file']}" if "file" in given
                       else f"{given['name']} := {json.dumps(given['value'], default=str)}")
    return {"parameters": sources,
            "remappings": [f"{view.value(r.src)}:={view.value(r.dst)}"
                           for r in node.remappings]}


def _node(view: _SideView, node: NodeRecord) -> dict[str, Any]:
    """Return a node's identity, wiring and parameters (the value each ends up with)."""
    full = view.node(node)
    parameters = {name: {"value": given["value"], "from": given["from"],
                         **({"expression": given["expression"]} if "expression" in given
                            else {})}
                  for name, given in (full["effective_parameters"] or {}).items()}
    return {
        "fqn": full["fqn"], "package": full["package"], "executable": full["executable"],
        "label": full["fqn"] or f"{full['package']}/{full['executable']} (no name)",
        "kind": full["kind"], "container": full["container"],
        "remappings": [f"{src}:={dst}" for src, dst in full["remappings"]],
        "parameters": parameters,
        "parameter_files": [given["file"] for given in full["parameters"] if "file" in given],
        "condition": full["condition"], "file": full["file"],
        "line": full["line"],
    }
