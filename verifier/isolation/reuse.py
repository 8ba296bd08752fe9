"""When a worker may evaluate another file of the same repository after its first.

A worker costs a fork, its confinement and its first imports (a few milliseconds, as much
as a small launch file's evaluation). Within one repository the author of the files
controls all of them already, so evaluating two of them in one process buys an attacker
nothing; the boundaries that matter (worker and launchverify, worker and machine) stay.
What must not happen is one file changing how the next one is evaluated by accident:
before it takes another file, ``Baseline.disturbed`` compares the worker with the state
it had before its first (recorded only when the parent may send more). A file that
rebound anything in a loaded module, changed a list, dict or set held by launchverify or
by what it reads with (``builtins``, ``os``, ``sys``, ``yaml``...: their classes too),
kept a library imported that was not before or took one away, left a thread (a
``threading.Timer``) or a timer signal behind, or changed a signal handler, the import
system, the working folder or an interpreter setting (``sys.set_int_max_str_digits``...)
ends the worker's reuse. What a file imported from the
workspace is forgotten after each evaluation anyway (``frontends.python.importer``), and
each file has its own ``os.environ`` (``worker``).
"""

from __future__ import annotations

import builtins
import collections
import functools
import operator
import signal
import sys
import threading
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType

from launchverify.process.collector import collector_paused

_SIGNALS = tuple(getattr(signal, name) for name in (
    "SIGALRM", "SIGVTALRM", "SIGPROF", "SIGTERM", "SIGINT", "SIGHUP", "SIGCHLD", "SIGPIPE",
    "SIGUSR1", "SIGUSR2", "SIGXCPU") if hasattr(signal, name))
_TIMERS = tuple(getattr(signal, name) for name in ("ITIMER_REAL", "ITIMER_VIRTUAL",
                                                    "ITIMER_PROF") if hasattr(signal, name))


# Every module's own bindings are compared. Also the classes' (and their tables) of the
# launch API's models and of what they and the frontend read with; and the items of the
# tables (lists, dicts, sets) of launchverify's modules (the sandbox's state...) and those.
_CLASSES_OF = ("launchverify.models", "yaml", "pathlib", "posixpath", "os", "tempfile",
               "shutil", "json", "builtins")
_TABLES_OF = ("launchverify", *_CLASSES_OF, "sys")
# containers that change by design: the modules (compared by name), the finders' cache
# (emptied after each file)
_CHANGING = {"sys": ("modules", "path_importer_cache")}
# exact types only: iterating them runs no code of a launch file's
_CONTAINERS = frozenset((list, dict, set, collections.OrderedDict, collections.defaultdict,
                         collections.deque))

# what a module binds: the sizes of its containers, then names, values and items
Bindings = tuple[tuple[int, ...], tuple[object, ...]]


def _bindings(module: ModuleType, tables: bool, classes: bool) -> Bindings:
    """Return what a module binds, and what its tables hold and its classes bind if asked.

    The values themselves are kept and later compared with ``is``: ``id()`` raises an
    audit event, which the worker's audit hook hears (a digest of ids was ten times
    slower than this before the hook learnt to return at once for it).
    """
    found: list[object] = []
    sizes: list[int] = []
    own = module.__name__
    changing = _CHANGING.get(own, ())
    for name, value in list(vars(module).items()):
        found.append(name)
        found.append(value)
        if tables and type(value) in _CONTAINERS and _watched(name) and name not in changing:
            _add_items(value, found, sizes)
        elif classes and isinstance(value, type) and value.__module__ == own:
            for entry_name, entry in list(vars(value).items()):
                found.append(entry_name)
                found.append(entry)
                if type(entry) in _CONTAINERS and _watched(entry_name):
                    _add_items(entry, found, sizes)
    return tuple(sizes), tuple(found)


def _watched(name: str) -> bool:
    """Whether a table bound to ``name`` is compared item by item.

    One's own tables are, not what Python keeps (``__builtins__``, annotations,
    dataclass fields...).
    """
    return not name.startswith("__")


def _add_items(container: Iterable[object], found: list[object], sizes: list[int]) -> None:
    size = len(found)
    found.extend(container)
    if isinstance(container, dict):  # (one of ours: an exact type, no code runs)
        found.extend(container.values())
    sizes.append(len(found) - size)


def _same(old: Bindings, new: Bindings) -> bool:
    return old[0] == new[0] and _identical(old[1], new[1])


def _identical(old: tuple[object, ...], new: tuple[object, ...]) -> bool:
    return len(old) == len(new) and all(map(operator.is_, old, new))


def _modules() -> dict[str, ModuleType]:
    """Return every module loaded, by name."""
    return {name: module for name, module in list(sys.modules.items())
            if isinstance(module, ModuleType)}


def _all_bindings(modules: dict[str, ModuleType]) -> dict[str, Bindings]:
    return {name: _of(name, module) for name, module in modules.items()}


def _of(name: str, module: ModuleType) -> Bindings:
    return _bindings(module, *_depth(name))


@functools.cache
def _depth(name: str) -> tuple[bool, bool]:
    """Whether module ``name``'s tables are compared, and its classes."""
    return _within(name, _TABLES_OF), _within(name, _CLASSES_OF)


def _within(name: str, prefixes: tuple[str, ...]) -> bool:
    """Whether module ``name`` is one of ``prefixes`` or inside one."""
    return any(name == prefix or name.startswith(f"{prefix}.") for prefix in prefixes)


@dataclass(frozen=True)
class Baseline:
    """A worker's state before its first file, to compare with after each one."""

    modules: dict[str, Bindings]
    threads: int
    handlers: tuple[object, ...]
    hooks: tuple[object, ...]
    cwd: str
    settings: tuple[float, ...]

    @classmethod
    def take(cls) -> Baseline:
        """Record the worker's state now."""
        with collector_paused():
            return cls(_all_bindings(_modules()), threading.active_count(), _handlers(),
                       _hooks(), _cwd(), _settings())

    def disturbed(self) -> str | None:
        """Return what a file left changed (``None``: the worker may take another file)."""
        if threading.active_count() != self.threads:
            return "a thread is left running"
        if any(signal.getitimer(timer) != (0.0, 0.0) for timer in _TIMERS):
            return "a timer is left armed"
        if _handlers() != self.handlers:
            return "a signal handler changed"
        if not _identical(self.hooks, _hooks()):
            return "the import system changed"
        if _cwd() != self.cwd:
            return "the working folder changed"
        if _settings() != self.settings:
            return "an interpreter setting changed"
        with collector_paused():
            modules = _modules()
            added = modules.keys() - self.modules.keys()
            if added:  # imported and kept (a library): as the file may have left it
                return f"{min(added)} stays imported"
            removed = self.modules.keys() - modules.keys()
            if removed:  # imported anew by the next file, from scratch
                return f"{min(removed)} was unloaded"
            for name, module in modules.items():
                if not _same(self.modules[name], _of(name, module)):
                    return f"{name} was changed"
        return None


def _handlers() -> tuple[object, ...]:
    return tuple(signal.getsignal(number) for number in _SIGNALS)


def _hooks() -> tuple[object, ...]:
    return (*sys.meta_path, *sys.path_hooks, sys.excepthook, sys.gettrace(), sys.getprofile(),
            builtins.__import__)


def _settings() -> tuple[float, ...]:
    """The interpreter's settings a file may change with no binding changed."""
    digits = getattr(sys, "get_int_max_str_digits", lambda: 0)()  # (Python 3.11)
    return sys.getrecursionlimit(), digits, sys.getswitchinterval()


def _cwd() -> str:
    try:
        return str(Path.cwd())
    except OSError:
        return ""
