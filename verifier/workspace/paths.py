"""Paths: how they are shown, and whether a link stays inside what a check may read.

Shown as the user gave them, else relative to the working directory.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from functools import lru_cache
from pathlib import Path


def resolved(path: Path) -> Path:
    """Return ``path`` absolute with symbolic links resolved; never raises on link loops.

    (``Path.resolve`` raises ``RuntimeError`` on a loop, which a hostile tree may hold.)
    """
    return Path(os.path.realpath(path))


SYSTEM_FOLDERS = ("/proc", "/sys", "/dev")  # never read, never walked


def below(real: str, roots: Iterable[str]) -> bool:
    """Return whether a real path is one of ``roots`` (real paths) or inside one."""
    return any(real == root or real.startswith(root.rstrip("/") + "/") for root in roots)


def real_path(path: str | os.PathLike[str]) -> str:
    """Return ``os.path.realpath(path)``, the folders' part remembered.

    Reads ask for the real path of every file they open, often through links (an
    install folder of linked files); their folders are shared by many files, and
    ``realpath`` looks at each component of a path every time. A ``..`` climbs from the
    real folder it follows, as the kernel does, never lexically.
    """
    # strings and os.path on purpose: this runs on every read (pathlib is slower)
    text = os.fspath(path)
    if not text.startswith("/"):
        text = os.getcwd() + "/" + text  # noqa: PTH109
    candidate = _climbed(text)
    for _ in range(40):  # as the kernel, give up on a chain of links this long
        head, tail = os.path.split(candidate)
        candidate = os.path.join(_real_folder_text(head), tail)  # noqa: PTH118
        try:
            target = os.readlink(candidate)  # noqa: PTH115
        except OSError:  # not a link (or nothing there): the path is real
            return candidate
        candidate = _target(os.path.dirname(candidate), target)  # noqa: PTH120
    return os.path.realpath(candidate)


def _target(folder: str, target: str) -> str:
    """Return where a link in the real ``folder`` points, its ``..`` climbed physically.

    An install folder's links climb first (``../../../src/pkg/launch/x.py``): from a real
    folder, each leading ``..`` is its parent; what follows is looked at part by part
    only if it climbs again.
    """
    if target.startswith("/"):
        return _climbed(target)
    parts = target.split("/")
    start = 0
    while start < len(parts) and parts[start] in ("..", ".", ""):
        if parts[start] == "..":
            folder = os.path.dirname(folder)  # noqa: PTH120
        start += 1
    rest = "/".join(parts[start:])
    if not rest:
        return folder
    joined = folder.rstrip("/") + "/" + rest
    return _climbed(joined) if ".." in parts[start:] else os.path.normpath(joined)


def _climbed(text: str) -> str:
    """Return an absolute path with each ``..`` climbed from the real folder before it."""
    if ".." not in text.split("/") and not text.startswith("//"):
        return os.path.normpath(text)
    candidate = "/"
    for part in text.split("/"):
        if part == "..":
            candidate = os.path.dirname(_real_folder_text(candidate))  # noqa: PTH120
        elif part not in ("", "."):
            candidate = os.path.join(candidate, part)  # noqa: PTH118
    return candidate


@lru_cache(maxsize=4096)
def _real_folder_text(folder: str) -> str:
    return os.path.realpath(folder)


def forget_real_folders() -> None:
    """Forget the real paths ``real_path`` remembered (a new check starts)."""
    _real_folder_text.cache_clear()


def link_inside(link: str, roots: Iterable[str]) -> bool:
    """Return whether a link's target is inside ``roots`` and not a system folder.

    Walks of the workspace follow linked folders only this far: a pull request's link to
    ``/`` or ``/proc`` must not make a check walk, hash or read the machine.
    """
    real = real_path(link)
    return below(real, roots) and not below(real, SYSTEM_FOLDERS)


def relative_file(path: Path, base: Path) -> str:
    """Return a path relative to ``base`` (posix), or absolute when outside it."""
    try:
        return resolved(path).relative_to(resolved(base)).as_posix()
    except ValueError:
        return resolved(path).as_posix()


def display_path(path: Path | str) -> str:
    """Return ``path`` relative to the working directory when below it, else unchanged."""
    candidate = Path(path)
    if not candidate.is_absolute():
        return str(candidate)
    try:
        return str(candidate.relative_to(_real_folder(os.getcwd())))  # noqa: PTH109 (a string key)
    except ValueError:
        return str(candidate)


@lru_cache(maxsize=16)
def _real_folder(folder: str) -> Path:
    """Return a folder's real path (remembered: rules show thousands of paths)."""
    return resolved(Path(folder))
