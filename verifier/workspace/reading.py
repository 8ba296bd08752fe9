"""Reading files of the workspace without ever blocking or reading without end.

A launch tree may hold a FIFO named ``robot.launch.xml``, a symbolic link to
``/dev/zero``, or a file of gigabytes. Every reader of launchverify goes through
``read_file``: it opens without blocking, reads only regular files, and reads at most the
size limit (``--max-file-size``, default 10 MB); anything else is ``Unreadable`` with a
reason the caller reports on the file.

What it reads is confined too: never below ``/proc``, ``/sys`` or ``/dev`` (a launch file
including ``/proc/self/environ`` would put the environment into a code frame), and, once a
check has said where it reads (``confine``), only below those folders, judged by the real
path a link points to.
"""

from __future__ import annotations

import contextlib
import functools
import os
import re
import stat
from collections.abc import Iterable, Iterator, Mapping
from contextvars import ContextVar
from pathlib import Path
from typing import TypeVar

from launchverify.workspace.paths import SYSTEM_FOLDERS, below, forget_real_folders, real_path

DEFAULT_LIMIT = 10 * 1000 * 1000
T = TypeVar("T")
_LIMIT: ContextVar[int] = ContextVar("launchverify_max_file_size", default=DEFAULT_LIMIT)
_RECORD: ContextVar[set[str] | None] = ContextVar("launchverify_reads", default=None)
_KINDS = ((stat.S_ISFIFO, "a FIFO"), (stat.S_ISCHR, "a character device"),
          (stat.S_ISBLK, "a block device"), (stat.S_ISSOCK, "a socket"),
          (stat.S_ISDIR, "a folder"))


class Unreadable(OSError):
    """A file launchverify will not read; ``str()`` says why."""


class Outside(Unreadable):
    """A file whose real path is outside the folders a check reads."""


# Real paths of the folders a check reads below (none set: anywhere but a system file); set by
# the check, kept for the reporters that show code frames after it.
_ROOTS: dict[str, tuple[str, ...]] = {}


def confine(folders: Iterable[str | Path] | None) -> None:
    """Read only below these folders from now on (``None``: lift the confinement).

    The check sets them: the workspace, the packages' folders, the install prefixes,
    the paths given on the command line and the Python installation.
    """
    _ROOTS.clear()
    forget_real_folders()  # links may have changed since the last check (an editor's)
    if folders is not None:
        _ROOTS["below"] = tuple(dict.fromkeys(os.path.realpath(f) for f in folders))


def confined_to() -> tuple[str, ...] | None:
    """Return the folders reads are confined to (``None``: not confined)."""
    return _ROOTS.get("below")


def unsaved_contents() -> dict[str, bytes]:
    """Return the unsaved buffers standing for files, by real path."""
    return dict(_UNSAVED)


def restore(unsaved: Mapping[str, bytes], most: int, roots: tuple[str, ...] | None) -> None:
    """Take over another process's reading state (the zygote, from launchverify)."""
    _UNSAVED.clear()
    _UNSAVED.update(unsaved)
    _LIMIT.set(most)
    _ROOTS.clear()
    if roots is not None:
        _ROOTS["below"] = roots


def outside(path: str | Path) -> str | None:
    """Return the real path of ``path`` when launchverify may not read it, else ``None``.

    Before a check is confined (the package scan, discovery: walks that follow no link
    out of the workspace), anything but a system file may be read; ``read_file`` refuses
    those by the file system they are on.
    """
    roots = _ROOTS.get("below")
    if roots is None:
        return None
    real = real_path(path)
    if below(real, SYSTEM_FOLDERS) or not below(real, roots):
        return real
    return None


@functools.lru_cache(maxsize=1)
def _system_devices() -> frozenset[int]:
    """Return the file systems of ``/proc``, ``/sys`` and ``/dev`` (not the root's)."""
    devices = set()
    for folder in (*SYSTEM_FOLDERS, "/"):
        with contextlib.suppress(OSError):
            devices.add(os.stat(folder).st_dev)  # noqa: PTH116
    with contextlib.suppress(OSError):
        devices.discard(os.stat("/").st_dev)  # noqa: PTH116
    return frozenset(devices)


# Unsaved contents that stand for files on disk (``check - --stdin-filename PATH``), by
# real path. Set before Python workers fork, so they read the same.
_UNSAVED: dict[str, bytes] = {}


def set_unsaved(path: Path, data: bytes) -> None:
    """Make every reader see ``data`` as the content of ``path`` (an editor's buffer)."""
    _UNSAVED[os.path.realpath(path)] = data


@contextlib.contextmanager
def unsaved_buffers(contents: Mapping[Path, bytes], *, only: bool = False) -> Iterator[None]:
    """Let every reader see these buffers in place of their files inside the block only.

    They lay over the buffers already set (a fix pass over an editor's buffer); with
    ``only``, no other buffer counts inside (the language server checks exactly what its
    editor has open: a buffer closed or saved since must not stand for its file).
    """
    saved = dict(_UNSAVED)
    if only:
        _UNSAVED.clear()
    for path, data in contents.items():
        set_unsaved(path, data)
    try:
        yield
    finally:
        _UNSAVED.clear()
        _UNSAVED.update(saved)


def unsaved(path: str | Path) -> bytes | None:
    """Return the unsaved content standing for a file, if any."""
    if not _UNSAVED:
        return None
    return _UNSAVED.get(os.path.realpath(path))


@contextlib.contextmanager
def _set(variable: ContextVar[T], value: T) -> Iterator[None]:
    """Give a context variable a value inside the block."""
    token = variable.set(value)
    try:
        yield
    finally:
        variable.reset(token)


def size_limit(limit: int) -> contextlib.AbstractContextManager[None]:
    """Read at most ``limit`` bytes of any file inside the block."""
    return _set(_LIMIT, limit)


def limit() -> int:
    """Return the size limit in force."""
    return _LIMIT.get()


def recording(into: set[str] | None) -> contextlib.AbstractContextManager[None]:
    """Add every file read inside the block to ``into`` (``None``: record nothing).

    What a check read tells which of its results an edit leaves valid. Each path is kept
    as given (made absolute) and as its real path. Only this thread's reads count (and
    threads it starts do not inherit it).
    """
    return _set(_RECORD, into)


def recording_on() -> bool:
    """Return whether reads are being recorded (``recording``) here."""
    return _RECORD.get() is not None


def note_reads(paths: Iterable[str]) -> None:
    """Record reads made elsewhere for this check (a forked process's)."""
    into = _RECORD.get()
    if into is not None:
        into.update(paths)


def _record(path: str | Path) -> None:
    into = _RECORD.get()
    if into is not None:
        into.add(os.path.abspath(path))  # noqa: PTH100
        into.add(real_path(path))


def read_file(path: str | Path, *, prefix: int | None = None, anywhere: bool = False
              ) -> bytes:
    """Return a regular file's bytes.

    ``prefix``: return at most that many bytes of a larger file instead of refusing it
    (for scans that need only the start, like a package manifest's name). ``anywhere``:
    also outside the folders the check reads (``confine``), for a file the user keeps
    elsewhere (a configuration file above the workspace); system files stay refused.
    """
    _record(path)
    buffered = unsaved(path)
    if buffered is not None:
        most = limit() if prefix is None else prefix
        if prefix is None and len(buffered) > most:
            raise Unreadable(_too_large(most))
        return buffered[:most]
    refused = None if anywhere else outside(path)
    if refused is not None:
        raise Outside(f"{refused} is outside the workspace and its packages: not read")
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0)
                     | getattr(os, "O_NOCTTY", 0))
    except OSError as error:
        raise Unreadable(error.strerror or str(error)) from None
    try:
        info = os.fstat(fd)
        if info.st_dev in _system_devices():  # /proc/self/environ, however it is reached
            raise Outside(f"{os.fspath(path)} is a system file: not read")
        if not stat.S_ISREG(info.st_mode):
            kind = next((name for test, name in _KINDS if test(info.st_mode)), "special")
            raise Unreadable(f"not a regular file ({kind})")
        most = limit() if prefix is None else prefix
        if prefix is None and info.st_size > most:
            raise Unreadable(_too_large(most))
        chunks = []
        size = 0
        while size <= most:
            chunk = os.read(fd, min(1 << 20, most + 1 - size))
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
        data = b"".join(chunks)
        if len(data) > most:
            if prefix is None:
                raise Unreadable(_too_large(most))
            data = data[:most]
        return data
    except Unreadable:
        raise
    except OSError as error:
        raise Unreadable(error.strerror or str(error)) from None
    finally:
        os.close(fd)


def read_text(path: Path, *, prefix: int | None = None) -> str:
    """Return a regular file's text (UTF-8, undecodable bytes replaced)."""
    return read_file(path, prefix=prefix).decode("utf-8", "replace")


def is_regular(path: Path) -> bool:
    """Return whether ``path`` is (or links to) a regular file, without opening it."""
    try:
        return stat.S_ISREG(path.stat().st_mode)
    except (OSError, ValueError):
        return False


MAX_DIGITS = 4300  # Python's int-to-string limit, and so ros2 launch's
_DIGITS = re.compile(rb"[0-9]+")


def long_number(data: bytes) -> tuple[int, int] | None:
    """Return ``(line, digits)`` of the first run of more than ``MAX_DIGITS`` digits.

    Python refuses to convert such integers (and would take quadratic time to); a file
    holding one is not read. The scan is linear: each run of digits is visited once.
    """
    for match in _DIGITS.finditer(data):
        if match.end() - match.start() > MAX_DIGITS:
            return data.count(b"\n", 0, match.start()) + 1, match.end() - match.start()
    return None


def long_number_message(digits: int) -> str:
    """Return the problem text for a number too long to read."""
    return (f"a number of {digits} digits: Python (and ros2 launch with it) reads integers "
            f"of at most {MAX_DIGITS} digits; the file is not read")


def _too_large(most: int) -> str:
    return f"larger than {most / 1e6:g} MB (--max-file-size)"
