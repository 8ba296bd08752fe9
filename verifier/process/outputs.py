"""Where launchverify's own process writes: only where the path says, never through a link.

launchverify runs on pull requests, so the tree it checks may hold links its outputs would
go through: ``launchverify.sarif -> ~/.bashrc``, or a folder ``reports -> /etc``. Every
file the main process writes for the user (``-o``, ``--xunit-file``, baselines, the
files ``--fix`` edits, ``diff``'s outputs) goes through this module instead of ``open``:

- A path is walked component by component, each folder opened by descriptor relative to
  the one before (``openat`` with ``O_NOFOLLOW``), so nothing can swap a folder for a
  link between a check and the write. A relative path is walked from the working folder.
- Below an *anchor* (the working folder, and the folders a caller names with ``inside``:
  the checked workspace, the diff's repository) a link on the way is refused, dangling or
  not. Above every anchor is the user's own machine: a link there (``/tmp``, a home
  folder reached through one) is followed, resolved here one component at a time, so a
  link leading back below an anchor is judged by the same rule.
- The last component is never followed, anywhere; when it exists it must be a regular
  file (not a link, FIFO, device or folder).
- ``..`` is taken as written (``os.path.abspath``'s reading): ``reports/../x`` is ``x``.
- The data goes to a new file in the opened folder (``O_CREAT | O_EXCL | O_NOFOLLOW``),
  which then replaces the name (``renameat``, which replaces a link rather than writing
  through it). A file replaced keeps its permission bits; a new one gets ``0o666`` less
  the umask, as ``open`` gives. On any failure the new file is removed: nothing is
  half-written.

A refusal is a ``UsageError`` (exit status 2) saying which component and why.

The API: ``check_writable`` (refuse before any work), ``write_file`` (one output),
``open_folder`` and ``replace_in`` (many files in one folder, as a cache writes them:
open the folder once, then replace entries by name; ``replace_in`` never raises, a
refused or failed write is ``False``). An entry of an opened folder is removed with
``os.unlink(name, dir_fd=folder)``, which removes a link itself, never its target.
"""

# Paths are strings here on purpose: walked by descriptor, '..' read as written (normpath).
# ruff: noqa: PTH109, PTH112, PTH117, PTH118, PTH119, PTH120

from __future__ import annotations

import contextlib
import errno
import os
import stat
from collections import deque
from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, TypeVar

if TYPE_CHECKING:
    from launchverify.engine import UsageError

PathLike = str | os.PathLike[str]
T = TypeVar("T", bound=PathLike)
LINK_NOTE = "(launchverify writes only where the path says)"
MAX_LINKS = 40  # as the kernel: a longer chain of links above the anchors is refused
_CLOEXEC = getattr(os, "O_CLOEXEC", 0)
# O_PATH: a folder only walked through needs search permission, not read permission.
_WALK = getattr(os, "O_PATH", os.O_RDONLY) | os.O_DIRECTORY | os.O_NOFOLLOW | _CLOEXEC
_NEW = os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW | _CLOEXEC
_KINDS = ((stat.S_ISLNK, "a link"), (stat.S_ISDIR, "a folder"), (stat.S_ISFIFO, "a FIFO"),
          (stat.S_ISCHR, "a character device"), (stat.S_ISBLK, "a block device"),
          (stat.S_ISSOCK, "a socket"))


class _Refused(Exception):
    """A write refused; ``str()`` says why (without the path)."""


def check_writable(path: PathLike, *, inside: Iterable[PathLike] = ()) -> None:
    """Refuse, before any work, a path ``write_file`` would refuse (``UsageError``).

    Its folder must exist and be reached without a link below an anchor; the file, if
    it exists, must be a regular file and not a link. Nothing is created.
    """
    shown = os.fspath(path)
    try:
        folder, name = _folder_of(shown, _anchors(inside), create=False)
        try:
            _existing(folder, name)
        finally:
            os.close(folder)
    except (_Refused, OSError, ValueError) as error:
        raise _usage_error(shown, error) from None


def check_outputs(paths: Iterable[PathLike | None],
                  trees: Callable[[], tuple[T, ...]]) -> tuple[T, ...]:
    """Refuse, before any work, each output given that ``write_file`` would refuse.

    ``trees``: the checked trees, below which no link is followed, worked out only when
    there is an output; returned (``()`` without one) for the writes that follow.
    """
    wanted = [path for path in paths if path is not None]
    if not wanted:
        return ()
    inside = trees()
    for path in wanted:
        check_writable(path, inside=inside)
    return inside


def write_file(path: PathLike, data: bytes | str, *, inside: Iterable[PathLike] = (),
               sync: bool = True) -> None:
    r"""Write ``data`` to ``path`` atomically, never through a link (``UsageError`` if not).

    Text is written as UTF-8, a character UTF-8 cannot hold (a lone surrogate of an odd
    file name) escaped as ``\udcff`` rather than losing the whole output. ``sync``:
    flush the data to disk before it replaces the old file (a file ``--fix`` replaces
    must not be lost to a crash).
    """
    shown = os.fspath(path)
    if isinstance(data, str):
        data = data.encode("utf-8", "backslashreplace")
    try:
        folder, name = _folder_of(shown, _anchors(inside), create=False)
        try:
            _replace(folder, name, data, sync=sync)
        finally:
            os.close(folder)
    except (_Refused, OSError, ValueError) as error:
        raise _usage_error(shown, error) from None


def open_folder(path: PathLike, *, inside: Iterable[PathLike] = (), create: bool = False,
                mode: int = 0o777, here: bool = True) -> int:
    """Return a descriptor of the folder ``path`` (close it with ``os.close``).

    The folder is reached as a file's would be, the folder itself included: below an
    anchor no link is followed. ``create``: make the missing folders (``mode``, less the
    umask). ``here``: the working folder is an anchor (a folder the user did not name
    relative to it, the default cache folder, needs only the checked trees: a check run
    from a home whose ``.cache`` is a link uses it). ``UsageError`` when it cannot be
    opened so.
    """
    shown = os.fspath(path)
    try:
        walked = _walk(shown, _anchors(inside, here=here), create=create, mode=mode,
                       whole=True)[0]
        try:
            return os.open(".", os.O_RDONLY | os.O_DIRECTORY | _CLOEXEC, dir_fd=walked)
        finally:
            os.close(walked)
    except (_Refused, OSError, ValueError) as error:
        raise _usage_error(shown, error) from None


def replace_in(folder: int, name: str, data: bytes, *, sync: bool = False) -> bool:
    """Write the file ``name`` of an opened folder atomically; return whether it was.

    ``name`` is one component. An existing entry that is not a regular file (a link, a
    FIFO, a folder) is left alone, and ``False`` returned, as for any failure: a cache
    entry not written is a miss later, not an error now.
    """
    if not name or name in (".", "..") or "/" in name or "\0" in name:
        return False
    try:
        _replace(folder, name, data, sync=sync)
    except (_Refused, OSError, ValueError):
        return False
    return True


def _usage_error(shown: str, error: Exception) -> UsageError:
    """Return the one-line refusal of writing ``shown``."""
    from launchverify.engine import UsageError  # only when refusing (the engine is large)

    reason = (error.strerror if isinstance(error, OSError) else None) or str(error)
    return UsageError(f"cannot write {shown!r}: {reason}")


def _anchors(inside: Iterable[PathLike], *, here: bool = True) -> tuple[str, ...]:
    """Return the real paths below which no link is followed: the working folder's first."""
    try:
        working = os.getcwd() if here else None
    except OSError:  # the working folder was removed: only the named folders count
        working = None
    named = (os.path.realpath(os.fspath(folder)) for folder in inside)
    return tuple(dict.fromkeys(p for p in (working, *named) if p is not None))


def _below(real: str, anchors: tuple[str, ...]) -> bool:
    """Return whether the real path ``real`` is an anchor or inside one."""
    return any(real == anchor or real.startswith(anchor.rstrip("/") + "/")
               for anchor in anchors)


def _folder_of(shown: str, anchors: tuple[str, ...], *, create: bool) -> tuple[int, str]:
    """Return a descriptor of the folder of the file ``shown`` names, and its name there."""
    if not shown or "\0" in shown:
        raise _Refused("no file name")
    if shown.endswith("/") or os.path.basename(os.path.normpath(shown)) in (".", ".."):
        raise _Refused("it is a folder" if os.path.isdir(shown) else "it names a folder")
    return _walk(shown, anchors, create=create, mode=0o777, whole=False)


def _walk(shown: str, anchors: tuple[str, ...], *, create: bool, mode: int,
          whole: bool) -> tuple[int, str]:
    """Open the folders of ``shown`` one by one; return the last one's descriptor.

    ``whole``: the path names a folder, walked to its end (else the last component is a
    file's name, returned with the descriptor of its folder).
    """
    path = os.path.normpath(shown)
    from_root = os.path.isabs(path) or path == ".." or path.startswith("../")
    if from_root:
        path = os.path.normpath(os.path.join(os.getcwd(), path))
    parts = [part for part in path.split("/") if part not in ("", ".")]
    name = "" if whole else parts.pop()
    root = "/" if from_root else ""
    real = "/" if from_root else os.getcwd()  # (a relative path: from the working folder)
    folder = os.open("/" if from_root else ".", _WALK)
    pending: deque[tuple[str, str]] = deque(
        (part, root + "/".join(parts[:index + 1])) for index, part in enumerate(parts))
    links = 0
    try:
        while pending:
            part, label = pending.popleft()
            if part in ("", "."):
                continue
            if part == "..":  # only in a link's target, above the anchors
                folder = _step(folder, os.open("..", _WALK, dir_fd=folder))
                real = os.path.dirname(real)
                continue
            try:
                opened = _open_folder(folder, part, label, create=create, mode=mode)
            except _Link:
                if _below(real, anchors):
                    raise _Refused(f"{label!r} is a link {LINK_NOTE}") from None
                links += 1
                if links > MAX_LINKS:
                    raise _Refused(f"more than {MAX_LINKS} links on the way") from None
                target = os.readlink(part, dir_fd=folder)
                if target.startswith("/"):
                    folder, real = _step(folder, os.open("/", _WALK)), "/"
                base = real
                pending.extendleft(reversed([
                    (step, os.path.join(base, *target.split("/")[:index + 1]))
                    for index, step in enumerate(target.split("/"))]))
                continue
            folder = _step(folder, opened)
            real = os.path.join(real, part)
    except BaseException:
        os.close(folder)
        raise
    return folder, name


class _Link(Exception):
    """The component is a link (dangling or not)."""


def _open_folder(folder: int, part: str, label: str, *, create: bool, mode: int) -> int:
    """Open the folder ``part`` of ``folder`` without following it (``_Link`` if a link)."""
    try:
        return os.open(part, _WALK, dir_fd=folder)
    except FileNotFoundError:
        if not create:
            raise _Refused(f"no folder {label!r}") from None
        with contextlib.suppress(FileExistsError):  # made meanwhile: judged as found
            os.mkdir(part, mode, dir_fd=folder)
        return _open_folder(folder, part, label, create=False, mode=mode)
    except OSError as error:
        kind = _kind(folder, part)
        if kind == "a link":
            raise _Link from None
        if kind is not None and kind != "a folder":
            raise _Refused(f"{label!r} is not a folder but {kind}") from None
        if error.errno in (errno.ENOTDIR, errno.ELOOP):
            raise _Refused(f"{label!r} is not a folder") from None
        raise


def _kind(folder: int, name: str) -> str | None:
    """Return what ``name`` is in ``folder`` ("a link", "a folder", ...), ``None`` if gone."""
    try:
        mode = os.stat(name, dir_fd=folder, follow_symlinks=False).st_mode
    except OSError:
        return None
    return next((kind for test, kind in _KINDS if test(mode)),
                "a file" if stat.S_ISREG(mode) else "a special file")


def _step(old: int, new: int) -> int:
    """Close the folder walked through; return the next."""
    os.close(old)
    return new


def _existing(folder: int, name: str) -> os.stat_result | None:
    """Return the status of the regular file ``name`` (``None``: there is none yet)."""
    try:
        info = os.stat(name, dir_fd=folder, follow_symlinks=False)
    except FileNotFoundError:
        return None
    if stat.S_ISLNK(info.st_mode):
        raise _Refused(f"it is a link {LINK_NOTE}")
    if not stat.S_ISREG(info.st_mode):
        kind = next((kind for test, kind in _KINDS if test(info.st_mode)), "a special file")
        raise _Refused(f"it is {kind}")
    return info


def _replace(folder: int, name: str, data: bytes, *, sync: bool) -> None:
    """Write ``data`` to a new file of ``folder``, then rename it to ``name``."""
    info = _existing(folder, name)
    temporary, handle = _new_file(folder)
    try:
        view = memoryview(data)
        while view:
            view = view[os.write(handle, view):]
        if info is not None:  # a file replaced keeps its mode (a launch file --fix edits)
            os.fchmod(handle, stat.S_IMODE(info.st_mode))
        if sync:
            os.fsync(handle)
        os.close(handle)
        handle = -1
        os.replace(temporary, name, src_dir_fd=folder, dst_dir_fd=folder)
    except BaseException:
        if handle >= 0:
            os.close(handle)
        with contextlib.suppress(OSError):
            os.unlink(temporary, dir_fd=folder)
        raise


def _new_file(folder: int) -> tuple[str, int]:
    """Create a new, hidden file in ``folder``; return its name and descriptor."""
    for _ in range(100):
        name = f".launchverify-{os.urandom(6).hex()}.tmp"
        try:
            return name, os.open(name, _NEW, 0o666, dir_fd=folder)
        except FileExistsError:
            continue
    raise _Refused("no new file name could be made in its folder")
