"""The values an argument may give an include path it computes: one include each.

``$(find-pkg-share $(var sensor_model)_launch)/launch/sensor.launch.py`` names a different
file for every sensor. The candidates are the argument's ``choices`` when it declares
them (every one reachable: a missing file among them is a finding), else what the
workspace offers for the pattern: the packages whose names fit the computed package
name, or the files of a folder whose names fit a computed file name; then only values
that name an existing file are tried, and other values stay unknown.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from launchverify.evaluate.values import text_of
from launchverify.ir import subst as s
from launchverify.ir.subst import walk
from launchverify.ir.symbolic import Arg

if TYPE_CHECKING:
    from launchverify.evaluate.scope import Scopes
    from launchverify.evaluate.values import Reducer
    from launchverify.graph import LaunchGraph
    from launchverify.workspace.packages import PackageIndex

MAX_CANDIDATES = 16
_MARK = "\x00lv\x00"  # a value no package or file name holds


@dataclass(frozen=True, slots=True)
class Candidates:
    """The values tried for the argument an include path is computed from."""

    name: str  # the configuration the path reads
    input: s.Sub  # its value in scope (the argument), for the guards
    values: tuple[str, ...]
    complete: bool  # the launch as given is among them (its choices, or its default)


def candidates_of(path: s.Sub, scopes: Scopes, graph: LaunchGraph, index: PackageIndex,
                  reducer: Reducer, patterns: bool = True) -> Candidates | None:
    """Return the candidates for an include path computed from one argument, or ``None``.

    ``patterns``: look in the workspace when the argument has no choices (off when its
    value as given already names the file: that one is followed, as before).
    """
    names = {text_of(c.name) for c in walk(path) if isinstance(c, s.LaunchConfig)}
    if len(names) != 1 or None in names:
        return None
    name = names.pop()
    assert name is not None
    current = scopes.get(name)
    if not isinstance(current, Arg):
        return None  # set by the launch itself, or from the environment: not a choice
    choices = next((a.choices for a in reversed(graph.arguments)
                    if a.name == name and a.choices), None)
    if choices:
        return Candidates(name, current, tuple(choices[:MAX_CANDIDATES]),
                          len(choices) <= MAX_CANDIDATES)
    values = _from_workspace(path, name, scopes, index, reducer) if patterns else []
    if not values:
        return None
    # the launch as given is seen whole when its value is among them (other values are
    # the user's to give, like any argument's); a default that names no file is not
    default = text_of(reducer.reduce(current.default)) if current.default is not None else None
    return Candidates(name, current, tuple(values[:MAX_CANDIDATES]),
                      default in values[:MAX_CANDIDATES])


def _from_workspace(path: s.Sub, name: str, scopes: Scopes, index: PackageIndex,
                    reducer: Reducer) -> list[str]:
    """Return the values that make the path name an existing file of the workspace."""
    scopes.push_configs()
    try:
        scopes.set(name, s.Text(_MARK), ())
        shares = [c.package for c in walk(path) if isinstance(c, s.FindPackageShare)
                  and any(isinstance(x, s.LaunchConfig) for x in walk(c.package))]
        marked = [text_of(reducer.reduce(p)) for p in shares]
        values: list[str] = []
        if marked and marked[0] and _MARK in marked[0]:
            pattern = _pattern(marked[0])
            values = [m.group(1) for n in index.names() if (m := pattern.fullmatch(n))]
        else:
            whole = text_of(reducer.reduce(path))
            if whole and _MARK in Path(whole).name and _MARK not in str(Path(whole).parent) \
                    and _inside(Path(whole).parent, index):
                folder = Path(whole).parent
                pattern = _pattern(Path(whole).name)
                values = sorted(m.group(1) for f in _listing(folder)
                                if (m := pattern.fullmatch(f)))
        found = []
        for value in sorted(set(values)):
            scopes.set(name, s.Text(value), ())
            target = text_of(reducer.reduce(path))
            if target is not None and _inside(Path(target), index) and Path(target).is_file():
                found.append(value)
        return found
    finally:
        scopes.pop_configs()


def _pattern(marked: str) -> re.Pattern[str]:
    before, _, after = marked.partition(_MARK)
    if _MARK in after:  # the value twice: the same text both times
        return re.compile(re.escape(before) + r"(.+?)" + re.escape(after).replace(
            re.escape(_MARK), r"\1"))
    return re.compile(re.escape(before) + r"(.+?)" + re.escape(after))


def _inside(path: Path, index: PackageIndex) -> bool:
    """Return whether a path lies in a workspace checked (nothing else is listed or probed)."""
    from launchverify.workspace.paths import resolved

    if not path.is_absolute():
        return False
    real = resolved(path)
    return any(real.is_relative_to(w) for w in index.workspaces)


def _listing(folder: Path) -> list[str]:
    try:
        return sorted(entry.name for entry in folder.iterdir() if entry.is_file())
    except OSError:
        return []
