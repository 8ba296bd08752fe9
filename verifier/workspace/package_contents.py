"""What a workspace package provides, read from its sources: the node names its code gives.

A ``Node`` started without ``name=`` is called whatever its code calls it
(``rclcpp::Node("controller_server")``, ``super().__init__('talker')``), and a process may
create more nodes inside (nav2's ``controller_server`` creates ``local_costmap``), which
receive the parameter files of the process too. launchverify cannot run the code, but it
can read the string literals of a package: those passed to node constructors are the
names its nodes may have, and any name-like literal may name an inner node. ``None`` means
the package has no sources here (an installed or released package): nothing is known.
"""

from __future__ import annotations

import os
import re
from functools import lru_cache
from pathlib import Path

from launchverify.graph import LaunchGraph, NodeRecord
from launchverify.models.node_names import builtin_name
from launchverify.workspace.packages import SKIP_DIRS, Package, PackageIndex
from launchverify.workspace.reading import read_file

MAX_SOURCE_FILES = 2_000
# Folders that hold no node code: tests, and launch files (Python ones are .py too).
_NOT_NODE_CODE = frozenset({"test", "tests", "launch"})
MAX_SOURCE_BYTES = 512 * 1024
_SOURCE_SUFFIXES = (".cpp", ".cc", ".cxx", ".hpp", ".hh", ".h", ".py")
# Node("x"), LifecycleNode("x"), rclcpp::Node("x"), make_shared<rclcpp::Node>("x"),
# nav2_util::LifecycleNode("x", ...), super().__init__('x'), Node('x'), node_name='x'.
_NODE_NAME = re.compile(
    r"""(?:Node\s*>?\s*\(|super\(\)\s*\.\s*__init__\s*\(|node_name\s*=)\s*(?:node_name\s*=\s*)?
        ["']([A-Za-z_][A-Za-z0-9_]*)["']""",
    re.VERBOSE,
)


_LITERAL = re.compile(r"""["']([A-Za-z_][A-Za-z0-9_]*)["']""")


def default_node_names(package: Package) -> frozenset[str] | None:
    """Return the node names a package's code may give its nodes (``None``: unknown).

    Unknown when its sources are not here: no source folder, or one without node code
    (an installed package's share folder, a checkout of its launch files only), or more
    code than is read.
    """
    if package.source is None:
        return None
    return _scan(package.source)[0]


def unnamed_node_names(graph: LaunchGraph, node: NodeRecord, packages: PackageIndex | None
                       ) -> tuple[str, frozenset[str] | None] | None:
    """Return the namespace of a node its code names, and the names it may have.

    The names are ``None`` when its package's sources are not here; the whole answer is
    ``None`` when the namespace is unknown or the launch sets a name that is not known.
    """
    if node.name is not None:
        return None
    namespace = "/" if node.namespace is None else graph.base(node.namespace)
    if namespace is None:
        return None
    package_name = graph.base(node.package)
    package = packages.find(package_name) if packages and package_name else None
    names = default_node_names(package) if package is not None else None
    executable = graph.base(node.executable)
    if names is not None and executable is not None:
        names = names | {executable}
    if names is None and (known := builtin_name(package_name, executable)) is not None:
        names = frozenset({known})  # a well-known executable whose sources are not here
    return namespace, names


def name_literals(package: Package) -> frozenset[str] | None:
    """Return every name-like string literal of a package's code (``None``: unknown)."""
    if package.source is None:
        return None
    return _scan(package.source)[1]


Scan = tuple[frozenset[str], frozenset[str]] | tuple[None, None]


@lru_cache(maxsize=256)
def _scan(source: Path) -> Scan:
    names: set[str] = set()
    literals: set[str] = set()
    files = 0
    for folder, dirs, filenames in os.walk(source):
        dirs[:] = [d for d in dirs
                   if d not in SKIP_DIRS and d not in _NOT_NODE_CODE and not d.startswith(".")]
        for filename in filenames:
            if not filename.endswith(_SOURCE_SUFFIXES) or filename == "setup.py":
                continue
            files += 1
            if files > MAX_SOURCE_FILES:
                return None, None  # not all read: what is absent is not known to be
            try:
                data = read_file(Path(folder) / filename, prefix=MAX_SOURCE_BYTES)
            except OSError:
                continue
            text = data.decode("utf-8", "replace")
            names.update(_NODE_NAME.findall(text))
            literals.update(_LITERAL.findall(text))
    if not files:
        return None, None  # no node code here: the package's nodes are not known
    return frozenset(names), frozenset(literals)
