"""The launch files of one run, each read once, with what is derived from them per run."""

from __future__ import annotations

from collections import deque
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from launchverify.evaluate.static_args import StaticSubtree, included_files
from launchverify.frontends import LoadedFile, PythonLoader, launch_format, load_launch_file
from launchverify.frontends.param_file import (
    InlineSubstitution,
    ParamFile,
    load_param_file,
    substitutions_in,
)
from launchverify.graph import StaticArgument
from launchverify.ir import actions as a
from launchverify.workspace.packages import PackageIndex
from launchverify.workspace.paths import resolved
from launchverify.workspace.reading import recording

MAX_OPAQUE_RUNS = 32  # results kept per OpaqueFunction (each compared on reuse)
_MISSING = object()  # a configuration not set (compares unequal to every value)


@dataclass
class _OpaqueRun:
    """An OpaqueFunction's result and what it depended on."""

    reads: tuple[tuple[str, object], ...]  # each configuration it read, with its value
    current: Path
    result: a.OpaqueResult
    used_by: set[int]  # the roots it was given to (each once)


class FileCache:
    """Loads each launch file and parameter file once per run, whoever asks for it.

    Python launch files are evaluated by ``python``; by default by confined worker
    processes owned by this cache (``close`` ends them).
    """

    def __init__(self, index: PackageIndex, workspace: Path,
                 python: PythonLoader | None = None,
                 environment: dict[str, str] | None = None) -> None:
        self.index = index
        self._files: dict[Path, LoadedFile] = {}
        self._param_files: dict[Path, ParamFile] = {}
        self._substitutions: dict[Path, tuple[InlineSubstitution, ...]] = {}
        self._within: dict[tuple[Path, Path], bool] = {}
        self.static_arguments: dict[Path, tuple[StaticArgument, ...]] = {}
        self.static_subtrees: dict[Path, StaticSubtree] = {}  # what each included file declares
        # the names each include action passes, by action (actions live as long as the files)
        self.include_names: dict[int, frozenset[str]] = {}
        self._opaque_runs: dict[a.OpaqueFunction, list[_OpaqueRun]] = {}
        # the files each loaded file includes by a path known without a context
        self._includes: dict[Path, tuple[Path, ...]] = {}
        self.asked: set[Path] = set()  # files asked for (the check empties it per root)
        self._owned = None
        if python is None:
            from launchverify.isolation.pool import IsolatedPython

            self._owned = IsolatedPython(index, workspace, environment=environment)
        self.python: PythonLoader = python or self._owned  # type: ignore[assignment]

    def close(self) -> None:
        """End the worker processes this cache started, if any."""
        if self._owned is not None:
            self._owned.close()

    def __call__(self, path: Path) -> LoadedFile:
        """Return the loaded file, reading it the first time."""
        self.asked.add(path)
        loaded = self._files.get(path)
        if loaded is None:
            with recording(None):  # what it rests on is this file: the root asking says
                loaded = load_launch_file(path, self.python)
            self._files[path] = loaded
            if loaded.launch is not None:
                self._includes[path] = tuple(included_files(loaded.launch.actions, self.index))
                self._start_python(self._includes[path])
        return loaded

    def read_ahead(self, roots: Iterable[Path]) -> None:
        """Read the files the roots include, breadth first, before any is walked.

        Only reading is moved earlier (every file read here would be read by the walk),
        so that the Python files among them start in workers (``_start_python``) while the
        rest is read: the walk then finds them evaluated instead of waiting for each.
        """
        pending = deque(roots)
        seen: set[Path] = set()
        while pending:
            path = pending.popleft()
            if path in seen or launch_format(path) == "python":
                continue  # what a Python file includes is known once a worker ran it
            seen.add(path)
            self(path)
            pending.extend(self._includes.get(path, ()))

    def _start_python(self, targets: Iterable[Path]) -> None:
        """Start evaluating the Python files a file includes before the walk reaches them.

        A worker evaluates each; reached one at a time, each kept the walk waiting
        (autoware_launch: 21 included Python files, 0.27 s). Only includes whose path is
        known without a context are seen: the others are evaluated when reached.
        """
        self.python.prefetch(target for target in targets
                             if target not in self._files and launch_format(target) == "python")

    def opaque_result(self, action: a.OpaqueFunction, configurations: Mapping[str, Any],
                      current: Path, root: int) -> a.OpaqueResult:
        """Run an OpaqueFunction's body, or reuse what a run for another root gave.

        A body gives the same result for the same configurations it reads and the same
        current file (the files it reads do not change during a check): roots that
        include the same file mostly pass it the same values (autoware_launch: 153 of 182
        runs). Not reused: a result with problems (a failure need not repeat: a module is
        imported once, a time limit depends on the machine), one whose body read the
        configurations as a whole, and a result within the root that had it (launch runs
        an object once; a body run again makes new ones).
        ``root``: the ``id`` of the graph being built (graphs outlive the cache).
        """
        runs = self._opaque_runs.setdefault(action, [])
        for run in runs:
            if run.current == current and root not in run.used_by and all(
                    configurations.get(name, _MISSING) == value for name, value in run.reads):
                run.used_by.add(root)
                return run.result
        result = action.run(configurations, current)
        if not result.problems and not result.reads_all and len(runs) < MAX_OPAQUE_RUNS:
            reads = tuple(dict.fromkeys(
                (read[0], configurations.get(read[0], _MISSING)) for read in result.reads))
            runs.append(_OpaqueRun(reads, current, result, {root}))
        return result

    def param_file(self, path: Path) -> ParamFile:
        """Return a parameter file, reading it the first time."""
        self.asked.add(path)
        loaded = self._param_files.get(path)
        if loaded is None:
            with recording(None):
                loaded = load_param_file(path)
            self._param_files[path] = loaded
        return loaded

    def substitutions(self, path: Path) -> tuple[InlineSubstitution, ...]:
        """Return a parameter file's ``$(...)`` lines, parsing them the first time."""
        self.asked.add(path)
        found = self._substitutions.get(path)
        if found is None:
            with recording(None):
                found = self._substitutions[path] = substitutions_in(path)
        return found

    def within(self, path: Path, folder: Path) -> bool:
        """Return whether ``path``, its links resolved, lies in ``folder`` (found once per run)."""
        key = (path, folder)
        inside = self._within.get(key)
        if inside is None:
            inside = self._within[key] = resolved(path).is_relative_to(folder)
        return inside
