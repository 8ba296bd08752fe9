"""The launch files a change affects: what pre-commit should check, not only what changed.

A commit that touches a parameter file, a URDF, a package.xml or an included launch file
can break launch files it does not touch: the parameter file's node keys, a new required
argument of an included file. Given the changed files, the affected launch files are the
changed launch files themselves, the launch files that name a changed file (by its file
name, as ``Includers`` reads them), those of a package whose ``package.xml`` changed, and
then, transitively, every launch file that names an affected one (its includers). A file
named only by a value computed at run time is not seen.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

from launchverify.workspace.includers import Includers
from launchverify.workspace.paths import resolved


def affected_launch_files(changed: Iterable[Path], includers: Includers) -> list[Path]:
    """Return the workspace's launch files that a change to ``changed`` may break."""
    launch_files = includers.files
    pending: list[Path] = []
    for path in (resolved(p) for p in changed):
        if path in launch_files:
            pending.append(path)
        if path.name == "package.xml":
            pending.extend(f for f in launch_files if f.is_relative_to(path.parent))
        pending.extend(includers.naming(path))
    found: set[Path] = set()
    while pending:
        path = pending.pop()
        if path in found:
            continue
        found.add(path)
        pending.extend(includers.naming(path))
    return sorted(found)
