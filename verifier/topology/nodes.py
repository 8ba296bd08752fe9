"""The interface of each executable and component of a package, from its sources.

Joins ``sources.package_targets`` (which files) with ``files.file_interfaces`` (what each
file creates). A library registering several components holds all their classes: an
endpoint created by another registered component's class is left to that component.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable, Iterator
from dataclasses import replace
from pathlib import Path

from launchverify.models.node_parameters import LIBRARY_PARAMETERS, NODE_BASES
from launchverify.span import Span
from launchverify.topology.cpp import class_name, member_endpoints
from launchverify.topology.files import file_interfaces
from launchverify.topology.generated_parameters import definitions, parameter_libraries
from launchverify.topology.model import (
    Endpoint,
    FileInterfaces,
    NodeInterface,
    NodeName,
    Parameter,
)
from launchverify.topology.sources import Target, package_targets
from launchverify.topology.wrappers import normalise_type
from launchverify.workspace.packages import Package, scan_sources
from launchverify.workspace.paths import display_path

# Not a syntax error: the C++ reader recovers around what it does not know (macros,
# newer syntax), which valid code has too. `interfaces` says it only under -v.
SKIPPED = "parts the source reader does not understand were skipped"


# ``#include "pkg/x.hpp"`` -> the file in pkg's sources, when the workspace has them
Headers = Callable[[str], Path | None]
MAX_BASE_HEADERS = 24  # headers of other packages read for one target's base classes


def package_interfaces(package: Package, headers: Headers | None = None) -> list[NodeInterface]:
    """Return the node interface of every executable and component of one package.

    ``headers`` finds the headers of other packages of the workspace, where a node class's
    base may be declared (nav2's ``nav2::LifecycleNode`` declares parameters of its own).
    """
    generated = parameter_libraries(package.source) if package.source is not None else {}
    return [target_interface(package.name, target, headers, generated)
            for target in package_targets(package)]


def target_interface(package: str, target: Target, headers: Headers | None = None,
                     generated: dict[str, Path] | None = None) -> NodeInterface:
    """Return what the sources of one executable or component create.

    ``generated`` maps the headers (or modules) generate_parameter_library makes in the
    package to their definition files: a target that includes one declares its
    parameters.
    """
    results = [file_interfaces(path) for path in target.sources]
    results += _library_headers(results, target, headers)
    results += _generated(results, generated or {})
    others = {_class(p) for p in target.other_components}
    aliases = dict(a for r in results for a in r.aliases)
    members = dict(m for r in results for m in r.members)
    created = [e for r in results for e in r.endpoints]
    created += [e for r in results for init in r.inits
                for e in member_endpoints(
                    init, init.written or members.get(f"{init.owner or ''}::{init.member}", ""),
                    aliases)]
    endpoints = [_retyped(e, aliases) for e in created
                 if e.owner is None or e.owner not in others]
    endpoints = _instantiated_only(endpoints, results, target, aliases)
    problems = list(target.problems)
    problems += [f"{display_path(r.file)}: {r.problem}" for r in results if r.problem]
    problems += [f"{display_path(r.file)}: {SKIPPED}" for r in results if r.partial]
    loaders = sorted({base for r in results for base in r.loaders})
    if loaders:
        problems.append("loads plugins chosen by parameters (" + ", ".join(loaders) + "): "
                        "the endpoints they create are not listed")
    if not target.sources and not problems:
        problems.append("no source file found")
    parameters = _parameters(results, bool(loaders))
    return NodeInterface(package, target.executable, target.component,
                         _node_name(results, target), tuple(endpoints),
                         target.sources, tuple(problems), parameters=parameters,
                         parameters_open=_parameters_open(results, target, parameters),
                         parameters_undeclared=next(
                             (r.undeclared for r in results if r.undeclared), None))


def _library_headers(results: list[FileInterfaces], target: Target,
                     headers: Headers | None) -> list[FileInterfaces]:
    """Return what the headers of other packages declare on the node the target builds.

    Read from the workspace's sources: a base class's parameters (nav2's
    ``nav2::LifecycleNode`` declares its own), and the names a library's functions
    declare literally (``introspection_mode``). A header's helper that declares whatever
    name it is given is no declaration (``_forwarded``); its callers' calls are. A
    released library's header is looked up in ``LIBRARY_PARAMETERS`` instead.
    """
    found: list[FileInterfaces] = []
    seen = set(target.sources)
    pending = [i for r in results for i in r.includes]
    wanted = {class_name(base.replace(".", "::")) for r in results for _, base in r.bases
              if base.endswith("Node") and base not in NODE_BASES}
    wanted -= {name for r in results for name, _ in r.classes}
    released: set[str] = set()
    while pending and len(found) < MAX_BASE_HEADERS:
        include = pending.pop(0)
        path = headers(include) if headers is not None else None
        if path is None:
            released.add(include.partition("/")[0])
            continue
        if path in seen:
            continue
        seen.add(path)
        result = file_interfaces(path)
        pending.extend(result.includes)
        classes = {name for name, _ in result.classes} & wanted
        wanted -= classes
        found.append(replace(result, endpoints=(), node_names=(), inits=(),
                             parameters=tuple(p for p in result.parameters
                                              if p.owner in classes or "*" not in p.name),
                             bases=tuple(b for b in result.bases if b[0] in classes),
                             declarations_missed=False, undeclared=None))
    return found + _released(released, results)


def _generated(results: list[FileInterfaces],
               generated: dict[str, Path]) -> list[FileInterfaces]:
    """Return the definitions of the generated parameter libraries the target includes."""
    used = {re.split(r"[/.]", i.removesuffix(".hpp").removesuffix(".h"))[-1]
            for r in results for i in r.includes}
    return [FileInterfaces(path, parameters=definitions(path))
            for name, path in sorted(generated.items()) if name in used]


def _released(libraries: set[str], results: list[FileInterfaces]) -> list[FileInterfaces]:
    """Return what released libraries the target includes may declare (as patterns)."""
    where = _nowhere(results)
    declared: list[Parameter] = []
    for library in sorted(libraries & LIBRARY_PARAMETERS.keys()):
        names = LIBRARY_PARAMETERS[library]
        declared += [Parameter(n, None, where, dynamic=True, via=library)
                     for n in (names if names is not None else ("*",))]
    return [FileInterfaces(where.file, parameters=tuple(declared))] if declared else []


def _parameters(results: list[FileInterfaces], plugins: bool) -> tuple[Parameter, ...]:
    """Return every parameter the target's files declare (once per name and place).

    A target that loads plugins accepts what they declare too, which is not read here:
    nav2's behaviors declare names without their plugin's prefix.
    """
    found = {(p.name, p.span.file, p.span.line): p for r in results for p in r.parameters}
    declared = list(found.values())
    if plugins:  # what plugins declare is not read (yet): any name
        declared.append(Parameter("*", None, declared[0].span if declared else
                                  _nowhere(results), dynamic=True, via="plugins"))
    return tuple(declared)


def _nowhere(results: list[FileInterfaces]) -> Span:
    return Span(results[0].file if results else Path(), 1, 1)


def _parameters_open(results: list[FileInterfaces], target: Target,
                     parameters: tuple[Parameter, ...]) -> str | None:
    """Return why the node may accept names it is not seen to declare, ``None`` if not.

    The sources not all read, NodeOptions that accept undeclared parameters, a name
    declared entirely at run time, or a node base class whose code is not here.
    """
    if target.problems or not target.sources:
        return "its sources were not all read"
    unread = next((r for r in results if r.problem or r.declarations_missed), None)
    if unread is not None:
        return f"not every parameter declaration of {display_path(unread.file)} was read"
    option = next((r.undeclared for r in results if r.undeclared), None)
    if option is not None:
        return option
    library = next((p.via for p in parameters if p.name == "*" and p.via), None)
    if library is not None:
        return (f"it uses {library}, which declares parameters of its own" if library != "plugins"
                else "it loads plugins chosen by parameters, whose own are not read")
    if any(p.name == "*" for p in parameters):
        return "it declares a parameter whose whole name is built at run time"
    defined = {name for r in results for name, _ in r.bases} | {
        name for r in results for name, _ in r.classes}
    for result in results:
        for _, base in result.bases:
            if base.endswith("Node") and base not in NODE_BASES and \
                    class_name(base.replace(".", "::")) not in defined:
                return f"its node class derives from {base}, whose code is not read here"
    return None


def _instantiated_only(endpoints: list[Endpoint], results: list[FileInterfaces],
                       target: Target, aliases: dict[str, str]) -> list[Endpoint]:
    """Keep an executable's endpoints to the classes its ``main`` files build.

    Executables often link one library holding every node class of the package; each
    then gets only the classes its own files instantiate, their bases and their members'
    types (followed through the library's aliases). When none of those classes creates an
    endpoint, nothing is filtered: an over-approximation is safer than a loss.
    """
    if target.component is not None or not target.main_sources:
        return endpoints
    related: dict[str, set[str]] = {}
    for result in results:
        for name, others in result.classes:
            related.setdefault(name, set()).update(others)
    pending = [n for r in results if r.file in target.main_sources for n in r.instantiated]
    reachable: set[str] = set()
    while pending:
        name = pending.pop()
        if name in reachable:
            continue
        reachable.add(name)
        pending.extend(related.get(name, ()))
        if name in aliases:
            pending.append(class_name(aliases[name]))
    owned = {e.owner for e in endpoints if e.owner is not None}
    if not reachable & owned:
        return endpoints
    return [e for e in endpoints if e.owner is None or e.owner in reachable
            or e.span.file in target.main_sources]


def _retyped(endpoint: Endpoint, aliases: dict[str, str]) -> Endpoint:
    """Resolve a type through an alias another file of the target declares (a header's)."""
    written = endpoint.type_written
    if endpoint.type is not None or written is None:
        return endpoint
    for _ in range(4):
        target = aliases.get(written) or aliases.get(written.rsplit("::", 1)[-1])
        if target is None or target == written:
            break
        written = target
    resolved = normalise_type(written)
    return replace(endpoint, type=resolved, type_written=None) if resolved else endpoint


def _class(plugin: str) -> str:
    return plugin.rsplit("::", 1)[-1]


def _node_name(results: Iterable[FileInterfaces], target: Target) -> str | None:
    """Return the one default node name the code gives.

    A component's own class decides first, then an executable's own files (its ``main``),
    then all files; several different names leave it unknown.
    """
    names: list[NodeName] = [n for r in results for n in r.node_names]
    groups = []
    if target.component is not None:
        groups.append({n.name for n in names if n.owner == _class(target.component)})
    groups.append({n.name for n in names if n.span.file in target.main_sources})
    groups.append({n.name for n in names})
    for distinct in groups:
        if distinct:
            return distinct.pop() if len(distinct) == 1 else None  # {None}: computed
    return None


def workspace_interfaces(roots: Iterable[Path]) -> Iterator[NodeInterface]:
    """Yield the node interfaces of every package found below the given folders."""
    from launchverify.workspace.packages import PackageIndex

    roots = list(roots)
    headers = PackageIndex(roots).header  # base classes in sibling packages
    seen: set[Path] = set()
    for root in roots:
        for name, folder in sorted(scan_sources(root), key=lambda item: str(item[1])):
            if folder in seen:
                continue
            seen.add(folder)
            yield from package_interfaces(Package(name, source=folder), headers)


def endpoints_of(interfaces: Iterable[NodeInterface]) -> list[Endpoint]:
    """Return every endpoint of the given interfaces, in order."""
    return [e for interface in interfaces for e in interface.endpoints]
