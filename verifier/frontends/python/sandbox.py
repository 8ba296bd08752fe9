"""The audit-hook layer of the sandbox a Python launch file runs in.

A launch file runs only in a worker process (``launchverify.isolation``), confined by the
operating system. Inside it, this layer says clearly what was refused: an audit hook
refuses what Python announces that would touch the world (starting processes, sockets,
writing, renaming or deleting files, changing the working directory or the environment,
adding audit hooks), with the user's line. The only writable place is a private scratch
folder (``tempfile`` points there). The environment the code sees is a symbolic
stand-in: variables read as placeholders instead of this machine's values. A timer
interrupts endless loops with the line they are on.

In a worker the hook is armed for the whole process (``arm``); elsewhere ``sandbox()``
switches it on for a block, in the calling thread.
"""

from __future__ import annotations

import io
import os
import re
import shutil
import signal
import sys
import tempfile
import threading
from collections.abc import Iterator, MutableMapping
from contextlib import contextmanager, redirect_stderr, redirect_stdout
from pathlib import Path
from typing import Any

from launchverify.models.launch_api.placeholders import assumed, environment_variable, read
from launchverify.own_code import is_own_file
from launchverify.workspace.paths import SYSTEM_FOLDERS, below

try:
    import resource
except ImportError:  # pragma: no cover - not on POSIX
    resource = None  # type: ignore[assignment]

BLOCKED_PREFIXES = (
    "subprocess.", "os.exec", "os.spawn", "os.posix_spawn", "os.fork", "os.forkpty", "os.system",
    "os.kill", "os.killpg", "socket.", "urllib.Request", "http.client.", "ftplib.", "smtplib.",
    "poplib.", "imaplib.", "nntplib.", "telnetlib.", "webbrowser.", "ctypes.", "pty.",
)
BLOCKED_EVENTS = frozenset({
    "os.remove", "os.rename", "os.rmdir", "os.mkdir", "os.chmod", "os.chown", "os.symlink",
    "os.link", "os.truncate", "os.utime", "os.chdir", "os.chroot", "os.putenv", "os.unsetenv",
    "os.setxattr", "os.removexattr", "shutil.rmtree", "shutil.move", "shutil.copyfile",
    "shutil.copytree", "shutil.chown", "shutil.make_archive", "shutil.unpack_archive",
    "os.startfile", "os.system", "sys.setrecursionlimit", "sys.settrace", "sys.setprofile",
    "sys.addaudithook", "sqlite3.connect", "sqlite3.connect/handle", "os.mkfifo", "os.mknod",
})
_TWO_PATHS = frozenset({"os.rename", "os.link", "os.symlink", "shutil.copyfile", "shutil.move"})
_SCRATCH_EVENTS = frozenset({"os.remove", "os.rename", "os.rmdir", "os.mkdir", "os.chmod",
                             "os.utime", "shutil.rmtree", "shutil.copyfile", "shutil.move"})
_REMOVALS = frozenset({"os.remove", "os.rmdir", "shutil.rmtree"})
_STDLIB = os.path.dirname(os.__file__)  # noqa: PTH120
_WRITE_FLAGS = os.O_WRONLY | os.O_RDWR | os.O_CREAT | os.O_APPEND | os.O_TRUNC
TIME_LIMIT = 10.0
MEMORY_LIMIT = 2 * 1024 ** 3  # bytes of address space beyond what is used already

SCRATCH_PREFIX = "launchverify-"  # the evaluations' scratch folders (mkdtemp adds 8 chars)
SCRATCH_NAME = re.compile(re.escape(SCRATCH_PREFIX) + r"[a-z0-9_]{8}")


class SandboxViolation(PermissionError):
    """A launch file tried to act on the world while being evaluated."""


class TimeLimitExceeded(Exception):
    """A launch file ran for longer than the evaluation allows."""


_state = threading.local()
_scratch: list[str] = []  # the private temporary folder of the current evaluation
_hook: list[bool] = []  # installed once per process (audit hooks cannot be removed)
_armed: list[bool] = []  # a worker: on for every thread, for good
_opened: set[str] = set()  # files opened for reading, as given (``take_opened``)


def _active() -> bool:
    return bool(_armed) or getattr(_state, "depth", 0) > 0


def arm(scratch: str, environment: dict[str, str] | None = None) -> None:
    """Refuse side effects in this whole process from now on (a worker, once confined).

    ``environment``: the variables given with ``--env``, all a launch file may read.
    """
    _install_hook()
    _scratch[:] = [os.path.abspath(scratch)]  # noqa: PTH100
    tempfile.tempdir = _scratch[0]
    sys.dont_write_bytecode = True
    os.environ = SymbolicEnviron(environment)  # type: ignore[assignment]  # noqa: B003
    _wrap_unaudited()
    _armed.append(True)


def _wrap_unaudited() -> None:
    """Give clear messages for what Python does not announce to audit hooks.

    The kernel refuses these anyway; the wrappers only say so at the user's line. Handlers
    for the end of the process (``atexit``, ``weakref.finalize``) are noted, not run: a
    worker ends with ``os._exit``.
    """
    import atexit
    import weakref

    def refusing(name: str) -> Any:
        def refuse(*args: Any, **kwargs: Any) -> Any:
            _refuse(f"{name} is not allowed")

        return refuse

    for name in ("mkfifo", "mknod"):
        if hasattr(os, name):
            setattr(os, name, refusing(f"os.{name}"))

    def at_exit(function: Any, *args: Any, **kwargs: Any) -> Any:
        _note("atexit handlers (and weakref finalizers) are never run")
        return function

    atexit.register = at_exit  # type: ignore[assignment]

    class Finalize(weakref.finalize):  # type: ignore[type-arg]
        def __init__(self, obj: Any, function: Any, *args: Any, **kwargs: Any) -> None:
            _note("atexit handlers (and weakref finalizers) are never run")
            super().__init__(obj, function, *args, **kwargs)

    weakref.finalize = Finalize  # type: ignore[misc,assignment]


def armed() -> bool:
    """Return whether this process is a worker with the hook on for good."""
    return bool(_armed)


def in_scratch(path: Any) -> bool:
    """Return whether a path is in the evaluation's private temporary folder."""
    return _in_scratch(path)


def removing(path: Any) -> bool:
    """Return whether the code's last removal in its temporary folder was of ``path``.

    A cleanup of a file that only a process of the launch writes (nav2 removes the world
    xacro wrote, at shutdown): launchverify starts no process, so it is not there.
    """
    return path is not None and getattr(_state, "removing", None) == os.fspath(path)


def in_other_scratch(path: Any) -> bool:
    """Return whether a path names a file in another evaluation's scratch folder.

    A temporary file that one launch file's code wrote (a parameter override passed to an
    include) is read by another evaluation, whose scratch folder differs and which never
    sees the file: at run time it exists, here its content is unknown.
    """
    if not isinstance(path, (str, bytes, os.PathLike)) or _in_scratch(path):
        return False
    folder = os.path.basename(os.path.dirname(os.path.abspath(os.fsdecode(path))))  # noqa: PTH100, PTH119, PTH120
    return bool(SCRATCH_NAME.fullmatch(folder))


def _in_scratch(path: Any) -> bool:
    if not _scratch or not isinstance(path, (str, bytes, os.PathLike)):
        return False
    text = os.path.abspath(os.fsdecode(path))  # noqa: PTH100
    # The folder itself too: NamedTemporaryFile's audit event names the folder it creates
    # the file in (a folder cannot be opened for writing: nothing escapes through it).
    return text == _scratch[-1] or text.startswith(_scratch[-1] + os.sep)


def _audit(event: str, args: tuple[Any, ...]) -> None:
    if event == "builtins.id":  # raised by every id(): the encoder's, the converter's
        return
    if not _active():
        return
    paths = args[:2] if event in _TWO_PATHS else args[:1]
    if paths and all(_in_scratch(p) for p in paths) and (
            event == "open" or event in _SCRATCH_EVENTS):
        if event in _REMOVALS:
            _state.removing = os.fspath(paths[0])
        return  # the evaluation's own temporary folder, deleted afterwards
    if event in BLOCKED_EVENTS or event.startswith(BLOCKED_PREFIXES):
        _refuse(f"{event} is not allowed")
    if event == "open" and len(args) >= 3:
        path, mode, flags = args[0], args[1], args[2]
        writes = (isinstance(mode, str) and any(c in mode for c in "wax+")) or (
            isinstance(flags, int) and flags & _WRITE_FLAGS)
        if writes:
            _refuse(f"writing {path!r} is not allowed")
        if _armed and isinstance(path, (str, bytes, os.PathLike)):  # a worker reports them
            _opened.add(os.path.abspath(os.fsdecode(path)))  # noqa: PTH100


def _refuse(what: str) -> None:
    """Remember the refusal (the launch file may catch the exception) and raise."""
    raise SandboxViolation(_note(what, depth=3))


def _note(what: str, depth: int = 2) -> str:
    """Remember something not done, to be reported with the refusals; return the message."""
    message = f"launch files are evaluated without side effects: {what}"
    frame = sys._getframe(depth)
    while frame is not None and not _user_code(frame.f_code.co_filename):
        frame = frame.f_back  # type: ignore[assignment]
    where = (frame.f_code.co_filename, frame.f_lineno) if frame is not None else None
    refusals = getattr(_state, "refused", None)
    if refusals is not None:
        refusals.append((message, where))
    return message


def note_refusal(what: str) -> None:
    """Remember a side effect a stand-in did not do, for the file's findings (LV003)."""
    _note(what, depth=3)


def _user_code(filename: str) -> bool:
    return not filename.startswith(("<", _STDLIB)) and not is_own_file(filename)


def take_opened() -> list[str]:
    """Return and forget the files opened since the last call, the launch file's own.

    (Not Python's nor launchverify's: what a result kept between checks rests on.)
    """
    opened = sorted(path for path in _opened
                    if _user_code(path) and not below(path, SYSTEM_FOLDERS))
    _opened.clear()
    return opened


def take_refusals() -> list[tuple[str, tuple[str, int] | None]]:
    """Return and forget the side effects refused in this thread's evaluation."""
    refusals: list[tuple[str, tuple[str, int] | None]] = getattr(_state, "refused", [])
    _state.refused = []
    return refusals


def _install_hook() -> None:
    if not _hook:
        sys.addaudithook(_audit)
        _hook.append(True)


class SymbolicEnviron(MutableMapping[str, str]):
    """``os.environ`` as a launch file sees it: variables of the robot, not of this machine.

    A variable given with ``--env NAME=VALUE`` has that value; any other reads as a
    placeholder for an unknown input, with its default when ``get``/``getenv`` give one
    (as ``$(env NAME default)``: the same input everywhere, never a concrete value that
    an error claim could rest on). Writes stay here.
    """

    def __init__(self, given: dict[str, str] | None = None) -> None:
        self._set: dict[str, str] = dict(given or {})

    def use(self, variables: dict[str, str]) -> None:
        """Read and write ``variables`` from now on (a worker's files each have their own)."""
        self._set = variables

    def __getitem__(self, key: str) -> str:
        if key in self._set:
            return self._set[key]
        return environment_variable(key)

    def get(self, key: str, default: Any = None) -> Any:
        if key in self._set:
            return self._set[key]
        if default is None:
            return environment_variable(key)
        return environment_variable(key, default) if isinstance(default, str) else default

    def __setitem__(self, key: str, value: str) -> None:
        self._set[key] = value

    def __delitem__(self, key: str) -> None:
        self._set.pop(key, None)

    def __contains__(self, key: object) -> bool:
        if key in self._set:
            return True
        # whether the robot sets it is unknown: read as unset, as a default is (an assumption
        # a failure is run again without, not a branch whose other side the graph shows)
        return assumed(False, True, f"env:{read(str(key))} is set", text=True)

    def __iter__(self) -> Iterator[str]:
        return iter(self._set)

    def __len__(self) -> int:
        return len(self._set)

    def copy(self) -> dict[str, str]:
        """Return the variables set by the launch file itself."""
        return dict(self._set)


@contextmanager
def sandbox(seconds: float | None = None) -> Iterator[None]:
    """Run a block with side effects refused, a symbolic environment and resource limits."""
    limit = TIME_LIMIT if seconds is None else seconds
    _install_hook()
    nested = _active()  # in a worker: limits, timer and scratch folder are the worker's
    _state.depth = getattr(_state, "depth", 0) + 1
    saved_bytecode = sys.dont_write_bytecode
    saved_environ = os.environ
    saved_tempdir = tempfile.tempdir
    sys.dont_write_bytecode = True
    scratch = None
    if not nested:
        os.environ = SymbolicEnviron()  # type: ignore[assignment]  # noqa: B003
        _state.depth -= 1  # our own folder is made outside the sandbox
        scratch = tempfile.mkdtemp(prefix=SCRATCH_PREFIX, dir=saved_tempdir)
        _state.depth += 1
        _scratch.append(scratch)
        tempfile.tempdir = scratch
    try:
        with time_limit(limit if not nested else 0), _memory_limit(not nested), \
                redirect_stdout(_Discard()), redirect_stderr(_Discard()):
            yield
    finally:
        os.environ = saved_environ  # noqa: B003
        sys.dont_write_bytecode = saved_bytecode
        _state.depth -= 1
        if scratch is not None:
            _scratch.pop()
            tempfile.tempdir = saved_tempdir
            shutil.rmtree(scratch, ignore_errors=True)


class _Discard(io.TextIOBase):
    """Where a launch file's prints go: nowhere, and without keeping them in memory."""

    def write(self, text: str) -> int:
        return len(text)

    def writable(self) -> bool:
        return True


@contextmanager
def time_limit(seconds: float) -> Iterator[None]:
    """Interrupt the block with ``TimeLimitExceeded`` after ``seconds`` (main thread only)."""
    main = threading.current_thread() is threading.main_thread()
    if seconds <= 0 or not main or not hasattr(signal, "setitimer"):
        yield
        return

    def expire(signum: int, frame: Any) -> None:
        raise TimeLimitExceeded(f"evaluation took longer than {seconds:g} s")

    previous = signal.signal(signal.SIGALRM, expire)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


@contextmanager
def _memory_limit(apply: bool) -> Iterator[None]:
    if not apply or resource is None:
        yield
        return
    try:
        soft, hard = resource.getrlimit(resource.RLIMIT_AS)
        used = _address_space()
        limit = used + MEMORY_LIMIT
        if hard != resource.RLIM_INFINITY:
            limit = min(limit, hard)
        resource.setrlimit(resource.RLIMIT_AS, (limit, hard))
    except (ValueError, OSError):
        yield
        return
    try:
        yield
    finally:
        resource.setrlimit(resource.RLIMIT_AS, (soft, hard))


def _address_space() -> int:
    try:
        pages = int(Path("/proc/self/statm").read_text().split()[0])
        return pages * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        return 0
