"""The worker pool, started by the check's first Python launch file.

A check of XML and YAML files alone needs no worker: ``LazyPython`` stands for the pool
(``pool.IsolatedPython``) and imports and starts it only when a Python file is loaded or
prefetched, so such a check imports none of the sandbox, the worker or the zygote.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from launchverify.ir.actions import LaunchFile
    from launchverify.isolation.pool import IsolatedPython
    from launchverify.problems import ProblemSink


class LazyPython:
    """A ``PythonLoader`` that builds ``IsolatedPython(**options)`` when first needed."""

    def __init__(self, **options: Any) -> None:
        self.options = options
        self.pool: IsolatedPython | None = None

    def started(self) -> IsolatedPython:
        """Return the pool, starting it the first time."""
        if self.pool is None:
            from launchverify.isolation.pool import IsolatedPython

            self.pool = IsolatedPython(**self.options)
        return self.pool

    def load(self, path: Path, sink: ProblemSink) -> LaunchFile | None:
        """Evaluate a Python launch file in a worker."""
        return self.started().load(path, sink)

    def prefetch(self, paths: Iterable[Path]) -> None:
        """Start on Python files the check will need (none: nothing is started)."""
        wanted = list(paths)
        if wanted:
            self.started().prefetch(wanted)

    def reads(self, path: Path) -> frozenset[str] | None:
        """Return the files the evaluation of ``path`` opened (``None``: unknown)."""
        return None if self.pool is None else self.pool.reads(path)

    @property
    def evaluated(self) -> int:
        """Return how many files workers evaluated."""
        return 0 if self.pool is None else self.pool.evaluated

    @property
    def protections(self) -> str | None:
        """Return the protections the first worker reported (``None``: no worker ran)."""
        return None if self.pool is None else self.pool.protections

    def close(self) -> None:
        """End the workers, if any were started."""
        if self.pool is not None:
            self.pool.close()

    def __enter__(self) -> LazyPython:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()
