"""Entry points versus included files, decided from the whole workspace.

A launch file that another launch file of the workspace names is meant to be included:
checked on its own, what its includers would provide is not held against it. One that no
file names is launched directly, and whatever ``ros2 launch`` would fail on is an error
there. Names are read from the text of every launch file of the workspace (an include
is written ``$(find-pkg-share pkg)/launch/x.launch.xml`` or
``os.path.join(share, 'launch', 'x_launch.py')``): a file is named when its file name
appears in another launch file. A name computed at run time is not seen, so such a file
counts as an entry point.
"""

from __future__ import annotations

import re
import time
from collections.abc import Iterable
from pathlib import Path

from launchverify.workspace.discover import discover
from launchverify.workspace.paths import resolved
from launchverify.workspace.reading import read_file, unsaved

# A name is a run of name characters ([\w.-]) up to its last file suffix: the longest
# prefix of the run that ends in one, with something before the suffix's dot. Suffixes are
# searched for first (a plain dot search) and runs measured from them: a regex trying every
# word of every file took ten times as long.
_SUFFIX = re.compile(rb"\.(?:py|xml|yaml|yml|launch|urdf|xacro|sdf)\b")
_RUN = re.compile(rb"[\w.\-]*")
_SCANNED_BYTES = 1 << 20
RACY_SECONDS = 2.0  # a file changed this recently could change again unseen by its stamp
MAX_REMEMBERED = 100_000

# path -> (size, mtime_ns, names): a long-lived process (the language server) scans its
# workspace for every check; an unchanged file is not read again.
_REMEMBERED: dict[str, tuple[int, int, frozenset[str]]] = {}


def _names_in(path: Path) -> frozenset[str]:
    """Return the file names a launch file's text mentions (empty when unreadable)."""
    stamp = None
    if unsaved(path) is None:
        try:
            info = path.stat()
        except OSError:
            return frozenset()
        stamp = (info.st_size, info.st_mtime_ns)
        known = _REMEMBERED.get(str(path))
        if known is not None and known[:2] == stamp:
            return known[2]
    try:
        text = read_file(path, prefix=_SCANNED_BYTES)
    except OSError:
        return frozenset()
    names = frozenset(name.decode("utf-8", "replace") for name in file_names(text))
    if stamp is not None and time.time() - stamp[1] / 1e9 > RACY_SECONDS:
        if len(_REMEMBERED) >= MAX_REMEMBERED:
            _REMEMBERED.clear()
        _REMEMBERED[str(path)] = (*stamp, names)
    return names


def file_names(text: bytes) -> set[bytes]:
    """Return the file names in a text: runs of name characters up to a file suffix."""
    ends: dict[int, int] = {}  # where each run with a name starts -> where its name ends
    backwards = b""
    for found in _SUFFIX.finditer(text):
        dot = found.start()
        if not backwards:
            backwards = text[::-1]
        mirrored = len(text) - dot  # the character before the dot, in ``backwards``
        run = _RUN.match(backwards, mirrored)  # (always matches, maybe nothing)
        before = run.end() - mirrored if run else 0
        if before:  # a later suffix in the same run makes a longer name
            ends[dot - before] = found.end()
    return {text[start:end] for start, end in ends.items()}


class Includers:
    """Which launch files of a workspace other launch files name."""

    def __init__(self, files: Iterable[Path], *, real_folders: bool = False) -> None:
        """Scan the files; ``real_folders``: their folders hold no link (need no resolving)."""
        self.files: set[Path] = set()  # every launch file scanned, resolved
        self._named_by: dict[str, set[Path]] = {}
        folders: dict[Path, Path] = {}  # each folder resolved once (a file's links: its own)
        for path in files:
            if path.parent not in folders:
                folders[path.parent] = path.parent if real_folders else resolved(path.parent)
            where = resolved(path) if path.is_symlink() else folders[path.parent] / path.name
            self.files.add(where)
            for name in _names_in(path):
                self._named_by.setdefault(name, set()).add(where)

    @classmethod
    def of_workspace(cls, folders: Iterable[Path]) -> Includers:
        """Scan every launch file below the folders (the workspace's sources).

        A walk from a resolved folder enters no linked folder, so every folder it yields
        is resolved already (resolving each again took a third of the scan).
        """
        return cls(discover([resolved(folder) for folder in folders if folder.is_dir()]),
                   real_folders=True)

    def included(self, path: Path) -> bool:
        """Return whether another launch file names this one."""
        return bool(self._named_by.get(path.name, set()) - {resolved(path)})

    def naming(self, path: Path) -> set[Path]:
        """Return the launch files that name this file (itself left out)."""
        return self._named_by.get(path.name, set()) - {resolved(path)}
