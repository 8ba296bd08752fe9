"""Interface models: node interfaces of released packages, shipped as extracted data.

A launch file often starts nodes of packages the user did not build (robot_state_publisher,
nav2's servers, the controllers): their sources are not in the workspace, so the extractor
cannot read them. ``bench/interface_models.py`` runs the same extractor on each package's
public sources at a recorded commit, one for each distribution's release branch, and
writes only what it found (executables, node names, endpoints, parameters, unresolved
reasons) to ``models/interfaces/<distro>/<package>.json``; this module writes and reads
that format, and picks the checked distribution's model (``topology.releases``). Nothing
here imports tree-sitter, and a package's model is read only when a node of it is asked
for.

The format (``"format": 1``)::

    {"format": 1, "package": "nav2_amcl",
     "source": {"repository": "https://github.com/ros-navigation/navigation2",
                "branch": "jazzy", "commit": "<40 hex digits>", "path": "nav2_amcl"},
     "extracted_with": "launchverify 0.x",
     "interfaces": [{"executable": "amcl", "component": null, "node_name": "amcl",
                     "problems": [...],
                     "endpoints": [{"kind": "publisher", "name": "amcl_pose",
                                    "type": "geometry_msgs/msg/PoseWithCovarianceStamped",
                                    "at": "src/amcl_node.cpp:1561"}, ...]}]}

An endpoint lists only the fields that are set: ``kind``, ``name`` (as written; absent when
unknown), ``type``, ``name_parameter``, ``parameter_default``, ``via``, ``note``,
``unresolved`` (the reason) and ``at`` (file and line in the package, at that commit).

An interface may say where its code gives ``node_name`` (``node_name_at``, file and line as
``at``); a model extracted before that was recorded does not.

An interface may list the ``parameters`` its code declares (``name``, ``type``,
``default``, ``dynamic``, ``required``, ``read_only``, ``limits``, ``via``,
``at``; only those set) and ``parameters_open``: why it may accept other names. A model
without them says its declarations were not read. A node that loads plugins lists the
``loaders``' base classes and the ``plugins`` its repository exports for them (``type``,
``base``, ``open``, ``parameters`` with ``at`` below the repository's root).
"""

from __future__ import annotations

import json
import re
from dataclasses import dataclass, replace
from functools import lru_cache
from importlib import resources
from pathlib import Path
from typing import Any

from launchverify.span import Span
from launchverify.topology.model import (
    Endpoint,
    EndpointKind,
    NodeInterface,
    Parameter,
    PluginContract,
)
from launchverify.topology.releases import BASE, MODEL_DISTROS, merged_interfaces

FORMAT = 1
_PACKAGE_NAME = re.compile(r"[a-z][a-z0-9_]*")
_COMMIT = re.compile(r"[0-9a-f]{40}")
_FIELDS = ("name", "type", "name_parameter", "parameter_default", "via", "note")
_PARAMETER_FIELDS = ("type", "default", "dynamic", "required", "read_only",
                     "limits", "via")

# A released node whose extracted code creates nothing most likely creates its endpoints
# through another package's class (joint_state_publisher_gui builds joint_state_publisher's
# node; a controller derives from another package's base): not known, rather than none.
EMPTY_MODEL = ("the extracted sources create no endpoint: they may create them through "
               "another package's code, which was not read")


class ModelError(ValueError):
    """A model file that is not of the documented format."""


@dataclass(frozen=True, slots=True)
class ModelSource:
    """Where a model was extracted from: repository, branch, commit, package folder."""

    repository: str
    branch: str
    commit: str
    path: str  # the package's folder inside the repository ("" at its root)

    def label(self) -> str:
        """Return ``navigation2@f4108e5`` for messages and source locations."""
        return f"{self.repository.rstrip('/').rsplit('/', 1)[-1]}@{self.commit[:7]}"

    def describe(self) -> str:
        """Return a sentence naming the repository, branch and commit."""
        return f"{self.repository} branch {self.branch} at commit {self.commit[:12]}"


@dataclass(frozen=True, slots=True)
class PackageModel:
    """One package's shipped interfaces and where they were extracted from."""

    package: str
    source: ModelSource
    interfaces: tuple[NodeInterface, ...]
    extracted_with: str = ""


# --------------------------------------------------------------------------- writing


def model_document(package: str, interfaces: list[NodeInterface], source: ModelSource,
                   root: Path, extracted_with: str, tree: Path | None = None) -> dict[str, Any]:
    """Return the model of one package; ``root`` is its source folder (paths below it).

    ``tree`` is the repository's root: a plugin's declarations are written below it
    (plugins come from the repository's other packages too).
    """
    return {
        "format": FORMAT, "package": package,
        "source": {"repository": source.repository, "branch": source.branch,
                   "commit": source.commit, "path": source.path},
        "extracted_with": extracted_with,
        "interfaces": [_interface_document(i, root, tree or root) for i in interfaces],
    }


def _interface_document(interface: NodeInterface, root: Path, tree: Path) -> dict[str, Any]:
    endpoints: list[dict[str, Any]] = []
    for endpoint in interface.endpoints:
        item = _endpoint_document(endpoint, root)
        if not any(_same(item, seen) for seen in endpoints):  # re-created in callbacks
            endpoints.append(item)
    named_at = {} if interface.node_name_at is None else {
        "node_name_at": f"{_relative(interface.node_name_at.file, root)}:"
                        f"{interface.node_name_at.line}"}
    return {"executable": interface.executable, "component": interface.component,
            "node_name": interface.node_name, **named_at,
            "problems": [_relative_text(p, root) for p in interface.problems],
            "parameters_open": None if interface.parameters_open is None else
            _relative_text(interface.parameters_open, root),
            "endpoints": endpoints,
            "parameters": [_parameter_document(p, root) for p in interface.parameters],
            **({"loaders": list(interface.loaders)} if interface.loaders else {}),
            **({"plugins": [_plugin_document(p, tree) for p in interface.plugins]}
               if interface.plugins else {})}


def _plugin_document(plugin: PluginContract, tree: Path) -> dict[str, Any]:
    return {"type": plugin.type, "base": plugin.base,
            "open": None if plugin.open is None else _relative_text(plugin.open, tree),
            "parameters": [_parameter_document(p, tree) for p in plugin.parameters]}


def _parameter_document(parameter: Parameter, root: Path) -> dict[str, Any]:
    item: dict[str, Any] = {"name": parameter.name}
    for name in _PARAMETER_FIELDS:
        value = getattr(parameter, name)
        # a default of 0, 0.0 or false is a value; a flag that is false, no limit, no type
        # are left out
        if value is not None and (name == "default" or value not in (False, ())):
            item[name] = [[c, list(a)] for c, a in value] if name == "limits" else value
    item["at"] = f"{_relative(parameter.span.file, root)}:{parameter.span.line}"
    return item


def _endpoint_document(endpoint: Endpoint, root: Path) -> dict[str, Any]:
    item: dict[str, Any] = {"kind": endpoint.kind.value}
    for name in _FIELDS:
        value = getattr(endpoint, name)
        if value is not None:
            item[name] = value
    if endpoint.unresolved_reason is not None:
        item["unresolved"] = endpoint.unresolved_reason
    item["at"] = f"{_relative(endpoint.span.file, root)}:{endpoint.span.line}"
    return item


def _same(a: dict[str, Any], b: dict[str, Any]) -> bool:
    """Return whether two endpoints differ only in where they are created."""
    return {k: v for k, v in a.items() if k != "at"} == {k: v for k, v in b.items() if k != "at"}


def _relative(path: Path, root: Path) -> str:
    try:
        return path.resolve().relative_to(root.resolve()).as_posix()
    except ValueError:
        return path.name


def _relative_text(problem: str, root: Path) -> str:
    """Return a problem with the extraction folder taken out of its paths."""
    return problem.replace(f"{root.resolve().as_posix()}/", "")


def dump_model(document: dict[str, Any]) -> str:
    """Return a model as JSON text: one endpoint a line, so that diffs stay readable."""
    lines = ["{"]
    head = {k: v for k, v in document.items() if k != "interfaces"}
    for key, value in head.items():
        lines.append(f"  {json.dumps(key)}: {json.dumps(value, sort_keys=False)},")
    lines.append('  "interfaces": [')
    for i, interface in enumerate(document["interfaces"]):
        fields = {k: v for k, v in interface.items()
                  if k not in ("endpoints", "parameters", "plugins")}
        lines.append("    {" + ", ".join(f"{json.dumps(k)}: {json.dumps(v)}"
                                          for k, v in fields.items()) + ', "endpoints": [')
        endpoints = interface["endpoints"]
        for j, endpoint in enumerate(endpoints):
            comma = "," if j < len(endpoints) - 1 else ""
            lines.append(f"      {json.dumps(endpoint)}{comma}")
        parameters = interface.get("parameters")
        if parameters is not None:
            lines.append('    ], "parameters": [')
            for j, parameter in enumerate(parameters):
                comma = "," if j < len(parameters) - 1 else ""
                lines.append(f"      {json.dumps(parameter)}{comma}")
        plugins = interface.get("plugins")
        if plugins:  # one plugin a line
            lines.append('    ], "plugins": [')
            for j, plugin in enumerate(plugins):
                comma = "," if j < len(plugins) - 1 else ""
                lines.append(f"      {json.dumps(plugin)}{comma}")
        lines.append("    ]}" + ("," if i < len(document["interfaces"]) - 1 else ""))
    lines.append("  ]")
    lines.append("}")
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------- reading


def read_model(document: Any) -> PackageModel:
    """Return the model a parsed JSON document holds; raise ``ModelError`` when malformed."""
    if not isinstance(document, dict) or document.get("format") != FORMAT:
        raise ModelError(f"not an interface model of format {FORMAT}")
    package = _text(document, "package")
    source_doc = document.get("source")
    if not isinstance(source_doc, dict):
        raise ModelError("'source' must be an object")
    source = ModelSource(_text(source_doc, "repository"), _text(source_doc, "branch"),
                         _text(source_doc, "commit"), _text(source_doc, "path", empty=True))
    if not _COMMIT.fullmatch(source.commit):
        raise ModelError(f"'source.commit' must be 40 hex digits, not {source.commit!r}")
    interfaces = document.get("interfaces")
    if not isinstance(interfaces, list):
        raise ModelError("'interfaces' must be a list")
    extracted = document.get("extracted_with", "")
    return PackageModel(package, source,
                        tuple(_interface(package, item, source) for item in interfaces),
                        extracted if isinstance(extracted, str) else "")


def _interface(package: str, item: Any, source: ModelSource) -> NodeInterface:
    if not isinstance(item, dict):
        raise ModelError("each interface must be an object")
    endpoints = item.get("endpoints", [])
    problems = item.get("problems", [])
    if not isinstance(endpoints, list) or not isinstance(problems, list) or not all(
            isinstance(p, str) for p in problems):
        raise ModelError("'endpoints' and 'problems' must be lists")
    if not endpoints and not problems:  # never "creates nothing" on a model's word
        problems = [EMPTY_MODEL]
    parameters = item.get("parameters")
    if parameters is not None and not isinstance(parameters, list):
        raise ModelError("'parameters' must be a list")
    return NodeInterface(package, _text(item, "executable"), _optional(item, "component"),
                         _optional(item, "node_name"),
                         tuple(_endpoint(e, source) for e in endpoints), (),
                         tuple(problems), source.describe(),
                         tuple(_parameter(p, source) for p in parameters or ()),
                         _optional(item, "parameters_open") if parameters is not None else
                         "its parameter declarations were not extracted into the model",
                         node_name_at=_span(item, source, "node_name_at")
                         if _optional(item, "node_name_at") else None,
                         loaders=_texts(item, "loaders"),
                         plugins=tuple(_plugin(p, source) for p in _list(item, "plugins")))


def _plugin(item: Any, source: ModelSource) -> PluginContract:
    """Return one plugin's contract (its declarations are placed below the repository)."""
    if not isinstance(item, dict):
        raise ModelError("each plugin must be an object")
    at_root = replace(source, path="")
    return PluginContract(_text(item, "type"), _text(item, "base"),
                          tuple(_parameter(p, at_root) for p in _list(item, "parameters")),
                          _optional(item, "open"))


def _list(item: dict[str, Any], key: str) -> list[Any]:
    value = item.get(key, [])
    if not isinstance(value, list):
        raise ModelError(f"'{key}' must be a list")
    return value


def _texts(item: dict[str, Any], key: str) -> tuple[str, ...]:
    value = _list(item, key)
    if not all(isinstance(v, str) for v in value):
        raise ModelError(f"'{key}' must be a list of strings")
    return tuple(value)


def _parameter(item: Any, source: ModelSource) -> Parameter:
    if not isinstance(item, dict) or not isinstance(item.get("name"), str):
        raise ModelError("each parameter must be an object with a name")
    limits = item.get("limits", [])
    if not isinstance(limits, list) or not all(
            isinstance(x, list) and len(x) == 2 and isinstance(x[1], list) for x in limits):
        raise ModelError("'limits' must be a list of [check, [arguments]]")
    return Parameter(item["name"], _optional(item, "type"), _span(item, source),
                     item.get("default"), item.get("dynamic") is True,
                     item.get("required") is True,
                     item.get("read_only") is True,
                     tuple((str(c), tuple(a)) for c, a in limits), _optional(item, "via"))


def _span(item: dict[str, Any], source: ModelSource, key: str = "at") -> Span:
    """Return where a model's item is written: ``<repository>@<commit>/<path>:<line>``."""
    where = _optional(item, key) or ""
    file, _, line = where.rpartition(":")
    location = f"{source.label()}/{source.path}/{file}" if source.path else (
        f"{source.label()}/{file}")
    return Span(Path(location), int(line) if line.isdigit() else 1)


def _endpoint(item: Any, source: ModelSource) -> Endpoint:
    if not isinstance(item, dict):
        raise ModelError("each endpoint must be an object")
    try:
        kind = EndpointKind(item.get("kind"))
    except ValueError:
        raise ModelError(f"unknown endpoint kind {item.get('kind')!r}") from None
    values = {name: _optional(item, name) for name in _FIELDS}
    span = _span(item, source)
    reason = _optional(item, "unresolved")
    if values["name"] is None and reason is None:
        reason = "the name is not known"
    return Endpoint(kind, values["name"], values["type"], span, values["name_parameter"],
                    values["parameter_default"], None, values["via"], reason, None,
                    values["note"])


def _text(item: dict[str, Any], key: str, empty: bool = False) -> str:
    value = item.get(key)
    if not isinstance(value, str) or (not value and not empty):
        raise ModelError(f"'{key}' must be a non-empty string")
    return value


def _optional(item: dict[str, Any], key: str) -> str | None:
    value = item.get(key)
    if value is not None and not isinstance(value, str):
        raise ModelError(f"'{key}' must be a string or null")
    return value


# --------------------------------------------------------------------------- shipped files


def _folder(distro: str) -> Any:
    return resources.files("launchverify.models") / "interfaces" / distro


def shipped_packages() -> list[str]:
    """Return the packages a model is shipped for (for some distribution), sorted."""
    names: set[str] = set()
    for distro in MODEL_DISTROS:
        folder = _folder(distro)
        if folder.is_dir():
            names.update(entry.name.removesuffix(".json") for entry in folder.iterdir()
                         if entry.name.endswith(".json"))
    return sorted(names)


@lru_cache(maxsize=1)
def modelled_packages() -> frozenset[str]:
    """Return the packages a model is shipped for, listed once per process."""
    return frozenset(shipped_packages())


def shipped_model(package: str, distro: str | None = None) -> PackageModel | None:
    """Return a package's shipped model for one distribution, ``None`` when none.

    For a distribution no model is extracted for, or for any (``None``), the merge of
    every release's (``topology.releases``). A model file that does not parse raises
    ``ModelError``: it ships with launchverify, so that is our bug, and the test over
    every shipped file catches it.
    """
    return _shipped(package, distro if distro in MODEL_DISTROS else None)


@lru_cache(maxsize=64)
def _shipped(package: str, distro: str | None) -> PackageModel | None:
    if not _PACKAGE_NAME.fullmatch(package):
        return None
    if distro is not None:
        return released_model(package, distro)
    releases = {d: m for d in MODEL_DISTROS if (m := released_model(package, d)) is not None}
    if not releases:
        return None
    base = releases[next(d for d in BASE if d in releases)]
    if len(releases) == 1:
        return replace(base, interfaces=tuple(replace(i, distro=None)
                                              for i in base.interfaces))
    merged = merged_interfaces({d: m.interfaces for d, m in releases.items()})
    return replace(base, interfaces=merged)


@lru_cache(maxsize=128)
def released_model(package: str, distro: str) -> PackageModel | None:
    """Return the model extracted for one distribution (read on first use)."""
    if not _PACKAGE_NAME.fullmatch(package) or distro not in MODEL_DISTROS:
        return None
    entry = _folder(distro) / f"{package}.json"
    if not entry.is_file():
        return None
    try:
        document = json.loads(entry.read_text(encoding="utf-8"))
    except (OSError, ValueError) as error:
        raise ModelError(f"model of {package} ({distro}): {error}") from error
    model = read_model(document)
    if model.package != package:
        raise ModelError(f"model file {distro}/{package}.json names package {model.package}")
    return replace(model, interfaces=tuple(replace(i, distro=distro)
                                           for i in model.interfaces))


def releases_declaring(interface: NodeInterface, name: str) -> tuple[str, ...]:
    """Return the distributions whose release of a modelled target declares ``name``.

    A name another release declares and the checked one does not was renamed or
    removed between them (controller_server's ``progress_checker_plugin``, humble's,
    is ``progress_checker_plugins`` since jazzy): no misspelling to fix.
    """
    found = []
    for distro in MODEL_DISTROS:
        model = released_model(interface.package, distro)
        for other in model.interfaces if model is not None else ():
            if (other.executable, other.component) == (interface.executable,
                                                        interface.component) and any(
                    p.name == name for p in other.parameters):
                found.append(distro)
    return tuple(found)


@lru_cache(maxsize=1)
def shipped_node_names() -> frozenset[str]:
    """Return the names the shipped packages' code gives its nodes (nav2's servers...)."""
    return frozenset(interface.node_name for package in shipped_packages()
                     if (model := shipped_model(package)) is not None
                     for interface in model.interfaces if interface.node_name)
