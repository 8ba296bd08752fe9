"""When a worker may evaluate another file of the same repository after its first.

A worker costs a fork, its confinement and its first imports (a few milliseconds, as much
as a small launch file's evaluation). Within one repository the author of the files
controls all of them already, so evaluating two of them in one process buys an attacker
nothing; the boundaries that matter (worker and launchverify, worker and machine) stay.
What must not happen is one file changing how the next one is evaluated by accident:
before it takes another file, ``Baseline.disturbed`` compares the worker with the state
it had before its first (recorded only when the parent may send more). A file that
rebound anything in a loaded module (launchverify's models, ``builtins``, ``os``,
``yaml``... and the classes of those the models read with), kept a library imported
that was not before, left a thread (a ``threading.Timer``) or a timer signal behind,
changed a signal handler, the import system or the working folder, or registered an
OpaqueFunction (its process stays for it) ends the worker's reuse. What a file imported
from the workspace is forgotten after each evaluation anyway
(``frontends.python.importer``).
"""

from __future__ import annotations

import builtins
import operator
import signal
import sys
import threading
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType

from launchverify.process.collector import collector_paused

_SIGNALS = tuple(getattr(signal, name) for name in (
    "SIGALRM", "SIGVTALRM", "SIGPROF", "SIGTERM", "SIGINT", "SIGHUP", "SIGCHLD", "SIGPIPE",
    "SIGUSR1", "SIGUSR2", "SIGXCPU") if hasattr(signal, name))
_TIMERS = tuple(getattr(signal, name) for name in ("ITIMER_REAL", "ITIMER_VIRTUAL",
                                                    "ITIMER_PROF") if hasattr(signal, name))


# modules whose classes are compared too (what the models and the frontend read with);
# every module's own bindings are
_CLASSES_OF = ("launchverify.models", "yaml", "pathlib", "posixpath", "os", "tempfile",
               "shutil", "json", "builtins")


def _bindings(module: ModuleType, classes: bool) -> tuple[object, ...]:
    """Return what a module binds (and what its own classes bind), names and values.

    The values themselves are kept and later compared with ``is``: ``id()`` raises an
    audit event, which the worker's audit hook hears (a digest of ids was ten times
    slower than this before the hook learnt to return at once for it).
    """
    found: list[object] = []
    own = module.__name__
    for name, value in list(vars(module).items()):
        found.append(name)
        found.append(value)
        if classes and isinstance(value, type) and value.__module__ == own:
            for entry in list(vars(value).items()):
                found.extend(entry)
    return tuple(found)


def _same(old: tuple[object, ...], new: tuple[object, ...]) -> bool:
    return len(old) == len(new) and all(map(operator.is_, old, new))


def _modules() -> dict[str, ModuleType]:
    """Return every module loaded, by name."""
    return {name: module for name, module in list(sys.modules.items())
            if isinstance(module, ModuleType)}


def _all_bindings(modules: dict[str, ModuleType]) -> dict[str, tuple[object, ...]]:
    return {name: _bindings(module, name.startswith(_CLASSES_OF))
            for name, module in modules.items()}


@dataclass(frozen=True)
class Baseline:
    """A worker's state before its first file, to compare with after each one."""

    modules: dict[str, tuple[object, ...]]
    threads: int
    handlers: tuple[object, ...]
    hooks: tuple[object, ...]
    cwd: str

    @classmethod
    def take(cls) -> Baseline:
        """Record the worker's state now."""
        with collector_paused():
            return cls(_all_bindings(_modules()), threading.active_count(), _handlers(),
                       _hooks(), _cwd())

    def disturbed(self) -> str | None:
        """Return what a file left changed (``None``: the worker may take another file)."""
        if threading.active_count() != self.threads:
            return "a thread is left running"
        if any(signal.getitimer(timer) != (0.0, 0.0) for timer in _TIMERS):
            return "a timer is left armed"
        if _handlers() != self.handlers:
            return "a signal handler changed"
        if not _same(self.hooks, _hooks()):
            return "the import system changed"
        if _cwd() != self.cwd:
            return "the working folder changed"
        with collector_paused():
            modules = _modules()
            added = modules.keys() - self.modules.keys()
            if added:  # imported and kept (a library): as the file may have left it
                return f"{min(added)} stays imported"
            for name, module in modules.items():
                if not _same(self.modules[name],
                             _bindings(module, name.startswith(_CLASSES_OF))):
                    return f"{name} was changed"
        return None


def _handlers() -> tuple[object, ...]:
    return tuple(signal.getsignal(number) for number in _SIGNALS)


def _hooks() -> tuple[object, ...]:
    return (*sys.meta_path, *sys.path_hooks, sys.excepthook, sys.gettrace(), sys.getprofile(),
            builtins.__import__)


def _cwd() -> str:
    try:
        return str(Path.cwd())
    except OSError:
        return ""
