"""LV302 missing-file."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

from launchverify.evaluate.values import text_of
from launchverify.graph import IncludeRecord, LaunchGraph
from launchverify.ir.subst import tail_at
from launchverify.rule import Finding, Fix, Rule, RuleContext, Severity, rename
from launchverify.span import Span
from launchverify.suggest import file_name_typos
from launchverify.workspace.packages import PackageIndex
from launchverify.workspace.paths import display_path


class MissingFile(Rule):
    """An included launch file or a parameter file does not exist.

    ## What it does
    Resolves include paths and parameter file paths (`<param from=...>`,
    `set_parameters_from_file`, `$(file-content)`) against the workspace, finding files
    written through a package's install folder in its sources. Paths outside the workspace
    belong to the machine and are not checked. An empty path given to a node's
    `parameters` names no file (an argument's `default=''` placeholder): launch_ros skips
    it and starts the node without it. A composable node's loader opens it and fails, so
    there it is reported.

    ## Why it matters
    A missing include stops ros2 launch (`FileNotFoundError`). A missing parameter file is
    skipped with only a warning, and the node silently runs on its defaults.

    ## Example
    ```xml
    <include file="$(find-pkg-share my_robot)/launch/sensor.launch.xml"/>
    <!-- the file is called sensors.launch.xml -->
    ```

    ## Fix
    Correct the path, or install the file (check `install(DIRECTORY ...)` or
    `data_files`). Build relative paths from `$(dirname)` or `$(find-pkg-share pkg)`.

    Autofix: when a file beside where the path points has a name one or two edits away
    (same extension), and the file's name is written as plain text at the end of the
    path, renames it there: safe when exactly one file is that close, unsafe otherwise.
    """

    code = "LV302"
    slug = "missing-file"
    severity = Severity.ERROR
    message = "{what} {written} does not exist{note}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        for include in graph.includes:
            if graph.runs(include.origin) is False:
                continue
            written = _written(include.action.path.describe(), graph.display(include.location))
            if include.status == "missing":
                yield self.finding(include.origin, what="included launch file",
                                   written=written, note=_note(include.note),
                                   fix=_include_fix(graph, include, ctx.packages))
            elif include.relative:
                yield self.finding(include.origin, what="included launch file",
                                   written=written, note=_note(include.note) + " where ros2 "
                                   "launch runs; it was found beside the including file")
        seen: set[object] = set()
        for ref in graph.file_refs:
            key = (ref.location, ref.origin.span)
            if ref.exists or key in seen or graph.runs(ref.origin) is False:
                continue
            seen.add(key)
            installed, where = _installed(ref.location, ctx.packages)
            yield self.finding(ref.origin, what=ref.what,
                               written=installed or _written(None, ref.location),
                               note=_note("; ".join(filter(None, (ref.note, where)))),
                               fix=None if ref.note else _fix(ref.written, ref.location,
                                                              ctx.packages))


def _include_fix(graph: LaunchGraph, include: IncludeRecord,
                 packages: PackageIndex | None) -> Fix | None:
    """Return the rename of a missing include's file name to a file beside it, if one."""
    location = text_of(include.location) or graph.base(include.location)
    if include.note or location is None:
        return None
    return _fix(tail_at(include.action.path, Path(location).name), location, packages)


def _fix(written: Span | None, location: str, packages: PackageIndex | None) -> Fix | None:
    """Return the rename of a missing file's name, written at ``written``, to a neighbour's."""
    path = Path(location)
    if written is None or packages is None or not path.is_absolute():
        return None
    close = file_name_typos(path.name, packages.neighbours(path))
    return rename(written, path.name, close[0], unique=len(close) == 1) if close else None


def _written(expression: str | None, resolved: str | None) -> str:
    """Show a path as written and, when different, what it resolved to."""
    shown = display_path(resolved) if resolved else ("''" if resolved == "" else "?")
    if expression is None or expression == resolved:
        return repr(shown) if resolved else shown
    return f"{expression!r} ({shown})"


def _installed(resolved: str | None, packages: PackageIndex | None
               ) -> tuple[str | None, str | None]:
    """Return a missing path's installed name, and where it would be installed from.

    For a path into a package that is not built, with the close file names there.
    ``$(find-pkg-share pkg)`` stands for the package's sources then, where the folder may
    not exist at all (CMake installs ``bringup/config`` as ``share/pkg/config``): the
    user is shown the name ros2 launch opens and the folders they can open.
    """
    if not resolved or packages is None or not Path(resolved).is_absolute():
        return None, None
    path = Path(resolved)
    name = packages.installed_name(path)
    if name is None or path.parent.exists():
        return None, None
    sources = packages.installed_from(path)
    folder = path.parent.name
    if not sources:
        return repr(name), f"no folder {folder}/ in the package's sources"
    places = " or ".join(display_path(str(source)) for source in sources[:3])
    close = file_name_typos(path.name, packages.neighbours(path))
    meant = f"; did you mean {close[0]!r}?" if close else ""
    return repr(name), f"{folder}/ would be installed from {places}{meant}"


def _note(note: str) -> str:
    return f" ({note})" if note else ""
