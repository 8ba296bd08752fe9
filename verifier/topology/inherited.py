"""What a node class inherits: the parameters its base classes in other packages declare.

A node class may derive from more than rclcpp's ``Node``: nav2's ``nav2::LifecycleNode``
declares ``bond_heartbeat_period``; rtabmap's ``CommonDataSubscriber`` declares
``approx_sync`` and ``qos_*`` on the node that derives from it. Such a base is looked for
in the headers the target includes from other packages of the workspace, and its
declarations in that package's C++ files (those whose code belongs to the class). A base
whose code is not found leaves the node open: it may declare anything.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path

from launchverify.ament import package_root
from launchverify.models.node_parameters import NO_PARAMETERS, NODE_BASES
from launchverify.topology.cpp import class_name as cpp_class_name
from launchverify.topology.files import file_interfaces
from launchverify.topology.generated_parameters import parameter_libraries, used_definitions
from launchverify.topology.model import FileInterfaces

MAX_HEADERS = 24  # headers of other packages read for one target's base classes
MAX_PACKAGE_FILES = 300  # C++ files of a base class's package read for its declarations
_CPP = {".cpp", ".cc", ".cxx", ".hpp", ".hh", ".hxx", ".h"}
_QT = re.compile(r"Q[A-Z]\w*")


@dataclass(frozen=True)
class Lookup:
    """Where other packages' code is: a header by ``#include`` path, a package's files."""

    header: Callable[[str], Path | None]
    package_files: Callable[[str], list[Path]]


def class_name(written: str) -> str:
    """Return ``LifecycleNode`` for ``nav2::LifecycleNode<T>``, or a Python ``a.b.C``."""
    return cpp_class_name(written.replace(".", "::"))


def node_classes(results: list[FileInterfaces]) -> set[str]:
    """Return the classes that are nodes: derived from a node base, however indirectly."""
    bases: dict[str, set[str]] = {}
    for result in results:
        for name, base in result.bases:
            bases.setdefault(name, set()).add(base)
    nodes: set[str] = set()
    changed = True
    while changed:
        changed = False
        for name, written in bases.items():
            if name not in nodes and any(b in NODE_BASES or b.endswith("Node")
                                         or class_name(b) in nodes for b in written):
                nodes.add(name)
                changed = True
    return nodes


def foreign_bases(results: list[FileInterfaces], roots: frozenset[str] = frozenset()) -> set[str]:
    """Return the bases of the node classes that the target's own files do not define.

    ``roots`` are classes known to be nodes whatever their bases (a component's, a
    controller's class). Bases from the standard library, Boost, Qt and rclcpp itself
    declare no parameters.
    """
    nodes = node_classes(results) | roots
    defined = {name for r in results for name, _ in r.classes}
    return {class_name(base) for r in results for name, base in r.bases
            if name in nodes and not _declares_nothing(base)} - defined


def _declares_nothing(base: str) -> bool:
    return base in NODE_BASES or base.startswith(NO_PARAMETERS) or bool(_QT.fullmatch(base))


def inherited(results: list[FileInterfaces], target_sources: tuple[Path, ...],
              lookup: Lookup | None, roots: frozenset[str] = frozenset(),
              ) -> tuple[list[FileInterfaces], set[str]]:
    """Return the declarations of the node classes' foreign bases, and the bases not found."""
    wanted = foreign_bases(results, roots)
    if not wanted or lookup is None:
        return [], wanted
    found: list[FileInterfaces] = []
    seen = set(target_sources)
    pending = [i for r in results for i in r.includes]
    read = 0
    while pending and wanted and read < MAX_HEADERS:
        include = pending.pop(0)
        path = lookup.header(include)
        if path is None or path in seen:
            continue
        seen.add(path)
        read += 1
        header = file_interfaces(path)
        pending.extend(header.includes)
        classes = {name for name, _ in header.classes} & wanted
        if not classes:
            continue
        wanted -= classes
        files = [header] + [file_interfaces(f) for f in
                            lookup.package_files(include.partition("/")[0])[:MAX_PACKAGE_FILES]
                            if f not in seen and f.suffix in _CPP]
        for result in files:
            owned = tuple(p for p in result.parameters if p.owner in classes)
            more = {class_name(b) for name, b in result.bases
                    if name in classes and not _declares_nothing(b)}
            wanted |= more - {n for f in files for n, _ in f.classes}
            if owned or result is header:
                found.append(replace(result, endpoints=(), node_names=(), inits=(),
                                     parameters=owned, includes=(),
                                     bases=tuple(b for b in result.bases if b[0] in classes),
                                     declarations_missed=False, undeclared=None))
        # the base's package's generated parameter libraries its files include
        # (steering_controllers_library's, for every steering controller)
        found.extend(used_definitions(files, parameter_libraries(package_root(path))))
    return found, wanted
