"""The interface of each executable and component of a package, from its sources.

Joins ``sources.package_targets`` (which files) with ``files.file_interfaces`` (what each
file creates). A library registering several components holds all their classes: an
endpoint created by another registered component's class is left to that component.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import replace
from pathlib import Path

from launchverify.models.node_parameters import LIBRARY_PARAMETERS
from launchverify.span import Span
from launchverify.topology.cpp import class_name, member_endpoints
from launchverify.topology.files import file_interfaces
from launchverify.topology.generated_parameters import parameter_libraries, used_definitions
from launchverify.topology.inherited import Lookup, inherited
from launchverify.topology.model import (
    LOADS_PLUGINS,
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


MAX_LIBRARY_HEADERS = 24  # headers of other packages read for what their functions declare


def package_interfaces(package: Package, lookup: Lookup | None = None) -> list[NodeInterface]:
    """Return the node interface of every executable and component of one package.

    ``lookup`` finds other packages' headers and files in the workspace, where a node
    class's base may be (nav2's ``nav2::LifecycleNode`` declares parameters of its own).
    """
    generated = parameter_libraries(package.source) if package.source is not None else {}
    return [target_interface(package.name, target, lookup, generated)
            for target in package_targets(package)]


def target_interface(package: str, target: Target, lookup: Lookup | None = None,
                     generated: dict[str, Path] | None = None) -> NodeInterface:
    """Return what the sources of one executable or component create.

    ``generated`` maps the headers (or modules) generate_parameter_library makes in the
    package to their definition files: a target that includes one declares its
    parameters.
    """
    results = [file_interfaces(path) for path in target.sources]
    roots = frozenset({class_name(target.component)}) if target.component else frozenset()
    bases, missing = inherited(results, target.sources, lookup, roots)
    # read for the declarations only: what the node's own files create stays theirs
    declaring = [*results, *bases, *_library_headers(results, target, lookup),
                 *used_definitions(results, generated or {})]
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
    parameters = _parameters(declaring, bool(loaders))
    node_name = _node_name(results, target)
    return NodeInterface(package, target.executable, target.component,
                         None if node_name is None else node_name.name, tuple(endpoints),
                         target.sources, tuple(problems), parameters=parameters,
                         parameters_open=_parameters_open(declaring, target, parameters,
                                                          missing),
                         parameters_undeclared=next(
                             (r.undeclared for r in results if r.undeclared), None),
                         node_name_at=None if node_name is None or node_name.name is None
                         else node_name.span, loaders=tuple(loaders))


def _library_headers(results: list[FileInterfaces], target: Target,
                     lookup: Lookup | None) -> list[FileInterfaces]:
    """Return what the headers of other packages declare on the node by literal names.

    Their functions given the node declare names of their own (nav2's services declare
    ``introspection_mode``); a helper that declares whatever name it is given is no
    declaration (``_forwarded``): its callers' calls are. A released library's header is
    looked up in ``LIBRARY_PARAMETERS`` instead.
    """
    found: list[FileInterfaces] = []
    seen = set(target.sources)
    pending = [i for r in results for i in r.includes]
    released: set[str] = set()
    while pending and len(found) < MAX_LIBRARY_HEADERS:
        include = pending.pop(0)
        path = lookup.header(include) if lookup is not None else None
        if path is None:
            released.add(include.partition("/")[0])
            continue
        if path in seen:
            continue
        seen.add(path)
        result = file_interfaces(path)
        pending.extend(result.includes)
        found.append(FileInterfaces(path, parameters=tuple(
            p for p in result.parameters if "*" not in p.name)))
    return found + _released(released, results)


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
                     parameters: tuple[Parameter, ...], missing: set[str]) -> str | None:
    """Return why the node may accept names it is not seen to declare, ``None`` if not.

    The sources not all read, a library that declares names of its own, a name declared
    entirely at run time, or a node base class whose code is not here (``missing``);
    then, only when none of those holds, the two reasons that still let a misspelling be
    told (``SOFT_OPEN``): NodeOptions that accept undeclared parameters, and plugins.
    """
    if target.problems or not target.sources:
        return "its sources were not all read"
    unread = next((r for r in results if r.problem or r.declarations_missed), None)
    if unread is not None:
        return f"not every parameter declaration of {display_path(unread.file)} was read"
    library = next((p.via for p in parameters if p.name == "*" and p.via
                    and p.via != "plugins"), None)
    if library is not None:
        return f"it uses {library}, which declares parameters of its own"
    if any(p.name == "*" and p.via != "plugins" for p in parameters):
        return "it declares a parameter whose whole name is built at run time"
    if missing:
        return (f"its node class derives from {sorted(missing)[0]}, whose code is not read "
                "here")
    option = next((r.undeclared for r in results if r.undeclared), None)
    if option is not None:
        return option
    if any(p.via == "plugins" for p in parameters):
        return LOADS_PLUGINS
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


def _node_name(results: Iterable[FileInterfaces], target: Target) -> NodeName | None:
    """Return the one default node name the code gives, where it first gives it.

    A component's own class decides first, then an executable's own files (its ``main``),
    then all files; several different names leave it unknown.
    """
    names: list[NodeName] = [n for r in results for n in r.node_names]
    groups = []
    if target.component is not None:
        groups.append([n for n in names if n.owner == _class(target.component)])
    groups.append([n for n in names if n.span.file in target.main_sources])
    groups.append(names)
    for group in groups:
        if group:  # one name, or computed (None)
            return group[0] if len({n.name for n in group}) == 1 else None
    return None


def workspace_interfaces(roots: Iterable[Path]) -> Iterator[NodeInterface]:
    """Yield the node interfaces of every package found below the given folders."""
    from launchverify.workspace.packages import PackageIndex

    roots = list(roots)
    lookup = PackageIndex(roots).lookup()  # base classes in sibling packages
    seen: set[Path] = set()
    for root in roots:
        for name, folder in sorted(scan_sources(root), key=lambda item: str(item[1])):
            if folder in seen:
                continue
            seen.add(folder)
            yield from package_interfaces(Package(name, source=folder), lookup)


def endpoints_of(interfaces: Iterable[NodeInterface]) -> list[Endpoint]:
    """Return every endpoint of the given interfaces, in order."""
    return [e for interface in interfaces for e in interface.endpoints]
