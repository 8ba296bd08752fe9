"""When a worker may evaluate another file of the same repository after its first.

A worker costs a fork, its confinement and its first imports (a few milliseconds, as much
as a small launch file's evaluation). Within one repository the author of the files
controls all of them already, so evaluating two of them in one process buys an attacker
nothing; the boundaries that matter (worker and launchverify, worker and machine) stay.
What must not happen is one file changing how the next one is evaluated by accident:
after each file, ``Baseline.disturbed`` compares the worker with the state it had before
its first file. A file that patched launchverify's models or ``builtins``, left a thread
(a ``threading.Timer``) or a timer signal behind, changed a signal handler, the import
system or the working folder, or registered an OpaqueFunction (its process stays for
it) ends the worker's reuse. What a file imported from the workspace is forgotten after
each evaluation anyway (``frontends.python.importer``).
"""

from __future__ import annotations

import builtins
import gc
import signal
import sys
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType

_SIGNALS = tuple(getattr(signal, name) for name in (
    "SIGALRM", "SIGVTALRM", "SIGPROF", "SIGTERM", "SIGINT", "SIGHUP", "SIGCHLD", "SIGPIPE",
    "SIGUSR1", "SIGUSR2", "SIGXCPU") if hasattr(signal, name))
_TIMERS = tuple(getattr(signal, name) for name in ("ITIMER_REAL", "ITIMER_VIRTUAL",
                                                    "ITIMER_PROF") if hasattr(signal, name))


def _module_digest(module: ModuleType) -> int:
    """Return a digest of what a module binds, and of what its own classes bind.

    Only integers are built (no tuple per entry): the worker's collector is on, and a
    digest that allocated containers would set it walking the whole heap.
    """
    ids: list[int] = []
    own = module.__name__
    for name, value in list(vars(module).items()):
        ids.append(hash(name))
        ids.append(id(value))
        if isinstance(value, type) and value.__module__ == own:
            for key, item in list(vars(value).items()):
                ids.append(hash(key))
                ids.append(id(item))
    return hash(tuple(ids))


def _watched() -> dict[str, ModuleType]:
    """Return the modules a launch file must leave alone: the models and ``builtins``.

    (A launch file reaches launchverify only through the models of the launch API.)
    """
    found = {name: module for name, module in list(sys.modules.items())
             if isinstance(module, ModuleType) and name.startswith("launchverify.models")}
    found["builtins"] = builtins
    return found


@dataclass(frozen=True)
class Baseline:
    """A worker's state before its first file, to compare with after each one."""

    modules: dict[str, int]
    threads: int
    handlers: tuple[object, ...]
    hooks: tuple[int, ...]
    cwd: str

    @classmethod
    def take(cls) -> Baseline:
        """Record the worker's state now."""
        with _collector_paused():
            return cls({name: _module_digest(module) for name, module in _watched().items()},
                       threading.active_count(), _handlers(), _hooks(), _cwd())

    def disturbed(self) -> str | None:
        """Return what a file left changed (``None``: the worker may take another file)."""
        if threading.active_count() != self.threads:
            return "a thread is left running"
        if any(signal.getitimer(timer) != (0.0, 0.0) for timer in _TIMERS):
            return "a timer is left armed"
        if _handlers() != self.handlers:
            return "a signal handler changed"
        if _hooks() != self.hooks:
            return "the import system changed"
        if _cwd() != self.cwd:
            return "the working folder changed"
        with _collector_paused():
            for name, module in _watched().items():
                if name in self.modules and self.modules[name] != _module_digest(module):
                    return f"{name} was changed"
        return None


@contextmanager
def _collector_paused() -> Iterator[None]:
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


def _handlers() -> tuple[object, ...]:
    return tuple(signal.getsignal(number) for number in _SIGNALS)


def _hooks() -> tuple[int, ...]:
    return (*map(id, sys.meta_path), *map(id, sys.path_hooks), id(sys.excepthook),
            id(sys.gettrace()), id(sys.getprofile()), id(builtins.__import__))


def _cwd() -> str:
    try:
        return str(Path.cwd())
    except OSError:
        return ""
