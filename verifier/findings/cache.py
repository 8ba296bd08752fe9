"""Results between runs: a tree that has not changed is not checked again.

As ruff does, a check's report is kept in the user's cache folder
(``$XDG_CACHE_HOME/launchverify``, else ``~/.cache/launchverify``; ``--cache-dir``,
``--no-cache``, ``LAUNCHVERIFY_NO_CACHE=1``). Its key is everything the check was asked:
the options and configuration, the working directory (messages hold paths relative to
it), the environment that finds packages, and launchverify's own code. It stays valid
while everything the check could have read is unchanged: every file below the workspace
folders (launch and parameter files, the Python modules launch files import, package.xml,
the sources unnamed nodes are named in) and every file it read outside them (installed
packages' launch and parameter files, the ament index of each prefix).

A file is compared by size and modification time; one modified within
``RACY_SECONDS`` of the check (it could change again within the clock's resolution
without its time changing) by its content hash too, as git does. A folder is compared by
its change time, which a file added, removed or renamed in it changes: a cached run
lists no folder again. Any change invalidates the whole result: never stale, at the
price of checking everything again. Files are stamped after the check (only then is it
known what it read): a result is not kept when a file changed while the check ran
(``settled``), since its stamp would describe content the check may not have read.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import stat
import sys
import time
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field, fields
from pathlib import Path
from typing import TypeVar

import launchverify
from launchverify.findings import plain
from launchverify.findings.sealed import Folder, Seal, default_state_dir, installation_seal
from launchverify.own_code import package_folders
from launchverify.workspace.packages import SKIP_DIRS
from launchverify.workspace.paths import link_inside

# bump when what is stored changes shape (3: folders; 4: per-root results; 5: plain
# data, sealed)
FORMAT = 5
SUFFIX = ".json"
MAX_STORED = 1 << 30  # bytes of one stored file; a larger one is no result of ours
TAG = "CACHEDIR.TAG"  # backup tools skip a folder holding it, as ruff and pip mark theirs
TAG_TEXT = (b"Signature: 8a477f597d28d172789f06886806bc55\n"
            b"# This file is a cache directory tag created by launchverify.\n")
T = TypeVar("T")
RACY_SECONDS = 2.0
CLOCK_SLACK = 0.01  # seconds a file's modification time may trail the real time (a jiffy)
MAX_AGE_DAYS = 30  # cache files unused for longer are removed
Stamp = tuple[int, int, str | None]  # size, mtime_ns, content hash for racy files
# device, inode, ctime_ns: a folder's changes when a file is added, removed or renamed in
# it (or its permissions change); (-1, -1, -1) for one that could not be read
FolderStamp = tuple[int, int, int]
UNREADABLE: FolderStamp = (-1, -1, -1)


def default_cache_dir() -> Path:
    """Return ``$XDG_CACHE_HOME/launchverify``, else ``~/.cache/launchverify``."""
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "launchverify"


def disabled_by_environment() -> bool:
    """Return whether ``LAUNCHVERIFY_NO_CACHE`` asks for no cache.

    A check with knowledge taken away (``LAUNCHVERIFY_ABLATE``) is never cached either: its
    result is not the check's.
    """
    if os.environ.get("LAUNCHVERIFY_ABLATE"):
        return True
    return os.environ.get("LAUNCHVERIFY_NO_CACHE", "").strip().lower() not in ("", "0", "false")


@dataclass
class Entry:
    """One stored result: the report and what it rested on.

    Each folder's listing tells an editor's save by rename from a file added or removed
    (``incremental``).
    """

    report: object
    stamps: dict[str, Stamp] = field(default_factory=dict)  # every file it may rest on
    folder_stamps: dict[str, FolderStamp] = field(default_factory=dict)  # every one walked
    format: int = FORMAT
    listings: dict[str, str] = field(default_factory=dict)  # folder -> digest of its names
    kept: str = ""  # the ``Kept.token`` stored with it


@dataclass
class Kept:
    """What an edit may leave of a stored result (``incremental``), stored beside it.

    Apart from the entry: a run answered from the cache does not read it.
    """

    roots: dict[Path, object]  # incremental.RootResult, by root
    rules: tuple[str, ...]  # the codes of the rules that judged
    other_reads: frozenset[str]  # what the check read besides the roots' own files
    started: float = 0.0  # when the check began (a file changed since is edited)
    format: int = FORMAT
    token: str = field(default_factory=lambda: os.urandom(8).hex())  # pairs it with its entry


def key_parts() -> tuple[object, ...]:
    """Return what every stored result's key holds besides the check's own options.

    The format, launchverify's code, the Python version, the working directory
    (messages hold paths relative to it) and the environment that finds packages.
    """
    return (FORMAT, launchverify.__version__, own_code_stamp(), sys.version, str(Path.cwd()),
            os.environ.get("AMENT_PREFIX_PATH", ""), os.environ.get("PYTHONPATH", ""))


def own_code_stamp() -> str:
    """Return a stamp of launchverify's installed code (an edited checkout changes it)."""
    # an editable install maps the three packages to three folders of the checkout
    roots = set(package_folders())
    digest = hashlib.blake2b(digest_size=16)
    for path, stamp in sorted(_walk(sorted(roots), own=True).items()):
        if path.endswith((".py", ".txt", ".json")):
            digest.update(f"{path}:{stamp[0]}:{stamp[1]}".encode())
    return digest.hexdigest()


def _walk(folders: Iterable[str], skip: str | None = None,
          folder_stamps: dict[str, FolderStamp] | None = None, *, own: bool = False,
          listings: dict[str, str] | None = None) -> dict[str, Stamp]:
    """Return the size and modification time of every file below the folders.

    ``skip``: a folder left out (the cache's own, when it lies in the workspace). Linked
    folders and files are followed as the package index follows them: to targets inside
    the folders only, each real folder once (a link to a parent is no endless walk, a
    link to ``/`` no walk of the machine). ``own``: launchverify's own code, whose every
    link is followed (a strict editable install is a tree of links into the checkout).
    Paths stay strings: this runs after every check that stores its result, over every
    file of the workspace.
    """
    return {path: (info.st_size, info.st_mtime_ns, None)
            for path, info in _files(folders, skip, folder_stamps, own=own,
                                     listings=listings)}


def _files(folders: Iterable[str], skip: str | None,
           folder_stamps: dict[str, FolderStamp] | None = None, *, own: bool = False,
           listings: dict[str, str] | None = None) -> Iterator[tuple[str, os.stat_result]]:
    """Yield every regular file below the folders with its status (see ``_walk``).

    ``folder_stamps`` receives each folder's stamp (``FolderStamp``), ``listings`` the
    digest of its names (``listing``).
    """
    pending = list(folders)
    roots = [os.path.realpath(folder) for folder in pending]
    visited: set[tuple[int, int]] = set()
    regular = stat.S_ISREG
    while pending:
        folder = pending.pop()
        try:
            info = os.stat(folder)  # noqa: PTH116 (string paths)
        except OSError:
            if folder_stamps is not None:
                folder_stamps[folder] = UNREADABLE
            continue
        if (info.st_dev, info.st_ino) in visited:
            continue
        visited.add((info.st_dev, info.st_ino))
        if folder_stamps is not None:
            folder_stamps[folder] = (info.st_dev, info.st_ino, info.st_ctime_ns)
        try:
            entries = list(os.scandir(folder))
        except OSError:
            continue
        if listings is not None:
            listings[folder] = names_digest(entry.name for entry in entries)
        for entry in entries:
            try:
                if not own and entry.is_symlink() and not link_inside(entry.path, roots):
                    continue
                if entry.is_dir():
                    name = entry.name
                    if name not in SKIP_DIRS and name[0] != "." and entry.path != skip:
                        pending.append(entry.path)
                    continue
                info = entry.stat()
            except OSError:
                continue
            if regular(info.st_mode):  # FIFOs, devices, sockets hold no content
                yield entry.path, info


def names_digest(names: Iterable[str]) -> str:
    """Return a digest of a folder's names (what is there, whatever the order)."""
    return hashlib.blake2b("\0".join(sorted(names)).encode("utf-8", "surrogateescape"),
                           digest_size=16).hexdigest()


def listing(folder: str) -> str | None:
    """Return the digest of a folder's names now (``None``: it cannot be listed)."""
    try:
        return names_digest(os.listdir(folder))  # noqa: PTH208 (string paths)
    except OSError:
        return None


def stat_of(path: str) -> Stamp | None:
    """Return a file's stamp without its content hash (``None``: gone, or not a file)."""
    try:
        info = os.stat(path)  # noqa: PTH116 (string paths: see _walk)
    except OSError:
        return None
    if not stat.S_ISREG(info.st_mode) and not stat.S_ISDIR(info.st_mode):
        return None  # (an ament index folder counts: its time says what was installed)
    return (info.st_size, info.st_mtime_ns, None)


def content_hash(path: str) -> str | None:
    """Return a regular file's content hash; never blocks (a FIFO put in its place)."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK)
    except OSError:
        return None
    try:
        if not stat.S_ISREG(os.fstat(fd).st_mode):
            return None
        digest = hashlib.blake2b(digest_size=16)
        while chunk := os.read(fd, 1 << 20):
            digest.update(chunk)
        return digest.hexdigest()
    except OSError:
        return None
    finally:
        os.close(fd)


def stamps_of(folders: list[str], files: Iterable[str], now: float,
              skip: str | None = None, folder_stamps: dict[str, FolderStamp] | None = None,
              listings: dict[str, str] | None = None) -> dict[str, Stamp]:
    """Return the stamps a result rests on; racy files carry their content hash.

    ``folder_stamps`` receives the stamp of every folder walked, ``listings`` its names.
    """
    stamps = _walk(folders, skip, folder_stamps, listings=listings)
    for path in files:
        if path not in stamps and (stamp := stat_of(path)) is not None:
            stamps[path] = stamp
    racy = int((now - RACY_SECONDS) * 1e9)
    for path, (size, mtime, _) in stamps.items():
        if mtime >= racy:
            stamps[path] = (size, mtime, content_hash(path))
    return stamps


def settled(stamps: dict[str, Stamp], started: float,
            folder_stamps: dict[str, FolderStamp] | None = None) -> bool:
    """Return whether nothing was modified since a check started (its result may be kept).

    A file written, or a folder whose files were added, removed or renamed (a file
    deleted leaves no stamp of its own), after the start: what the check read may not be
    what is there. A time may trail the moment it was written by the kernel's coarse
    clock (milliseconds): one within ``CLOCK_SLACK`` of the start counts as during it. A
    time in whole seconds comes from a file system that keeps no finer ones (HFS+, FAT:
    up to two seconds): there, one within ``RACY_SECONDS`` does.
    """
    fine = int((started - CLOCK_SLACK) * 1e9)
    coarse = int((started - RACY_SECONDS) * 1e9)

    def before(time_ns: int) -> bool:
        return time_ns < (coarse if time_ns % 1_000_000_000 == 0 else fine)

    return (all(before(mtime) for _, mtime, _ in stamps.values())
            and all(before(changed) for _, _, changed in (folder_stamps or {}).values()))


def moved(folder: str, stamp: FolderStamp) -> bool:
    """Return whether a folder's stamp is not what it was (it could be read, or not)."""
    try:
        info = os.stat(folder)  # noqa: PTH116 (string paths)
    except OSError:
        return stamp != UNREADABLE
    return (info.st_dev, info.st_ino, info.st_ctime_ns) != stamp


def unchanged(entry: Entry) -> bool:
    """Return whether every file the result rests on is as it was (the first change says).

    No folder is listed again: a folder's stamp changes when a file is added, removed or
    renamed in it, and a file's when it is written. ``settled`` kept only results whose
    times all precede their check, so any later change shows as a later time.
    """
    if any(moved(folder, stamp) for folder, stamp in entry.folder_stamps.items()):
        return False  # a file added, removed or renamed there, or another folder
    for path, (size, mtime, content) in entry.stamps.items():
        now = stat_of(path)
        if now is None or now[:2] != (size, mtime):
            return False
        if content is not None and content_hash(path) != content:
            return False
    return True


class ResultCache:
    """A folder of stored results, one file per key, each sealed (``sealed``).

    ``named``: the user named the folder (``--cache-dir``); a folder taken by default is
    not used inside a checked tree (``usable``).
    """

    def __init__(self, folder: Path, *, named: bool = False, state: Path | None = None
                 ) -> None:
        self.path = folder.absolute()  # as given: walked without following links
        self.folder = Path(os.path.realpath(folder))
        self.named = named
        self._state = state
        self._seal: Seal | bool | None = False  # made when first needed
        self.refused: str | None = None  # why this check uses no cache, to say
        self.inside: tuple[str, ...] = ()  # the checked trees: no link followed below

    def usable(self, checked: Iterable[str]) -> bool:
        """Return whether this check may use the folder; else say why (``refused``).

        A folder below a checked tree is the pull request's to fill: taken by default
        (``XDG_CACHE_HOME`` in a checkout) it is not used; named, it is, since a planted
        file has no valid seal. The installation's secret never lies in a checked tree.
        """
        state = Path(os.path.realpath(self._state or default_state_dir()))
        self.inside = tuple(checked)
        for folder in self.inside:
            tree = Path(os.path.realpath(folder))
            if state.is_relative_to(tree):
                self.refused = (f"the state folder {state} is inside the checked tree "
                                f"{tree}: results are not cached (set XDG_STATE_HOME "
                                "elsewhere)")
                return False
            if not self.named and self.folder.is_relative_to(tree):
                self.refused = (f"the cache folder {self.folder} is inside the checked tree "
                                f"{tree}: not used (name it with --cache-dir to use it)")
                return False
        return True

    def seal(self) -> Seal | None:
        """Return the installation's seal (``None``: no secret, so no cache)."""
        if self._seal is False:
            self._seal = installation_seal(self._state)
        return self._seal if isinstance(self._seal, Seal) else None

    def key(self, parts: Iterable[object]) -> str | None:
        """Return the stored name of what a check was asked, if it can have one."""
        seal = self.seal()
        return None if seal is None else seal.name([*key_parts(), *parts])

    def _file(self, key: str) -> str:
        return f"{key}{SUFFIX}"

    def load(self, key: str) -> Entry | None:
        """Return the stored entry for a key if it is still valid (else ``None``)."""
        entry = self.stored(key)
        return entry if entry is not None and self.valid(key, entry) else None

    def _read(self, name: str, kind: type[T]) -> T | None:
        """Return the value of a sealed file of the folder, if it holds a ``kind``."""
        seal = self.seal()
        if seal is None:
            return None
        with self._opened() as folder:
            data = None if folder is None else folder.read(name, MAX_STORED)
        payload = None if data is None else seal.unwrap(name, data)
        if payload is None:
            return None
        try:
            value = plain.loads(payload)
        except plain.Malformed:
            return None
        return value if isinstance(value, kind) and getattr(value, "format", None) == FORMAT \
            else None

    def stored(self, key: str) -> Entry | None:
        """Return the stored entry for a key, valid or not (``None``: none readable)."""
        from launchverify.engine import Report

        entry = self._read(self._file(key), Entry)
        return entry if entry is not None and isinstance(entry.report, Report) else None

    def valid(self, key: str, entry: Entry) -> bool:
        """Return whether nothing an entry rests on changed (and mark it recently used)."""
        if not unchanged(entry):
            return False
        with self._opened() as folder:
            if folder is not None:
                folder.touch(self._file(key))  # recently used: kept by the pruning
        return True

    def kept(self, key: str, entry: Entry) -> Kept | None:
        """Return what an edit may leave of the entry stored under ``key``, if anything."""
        kept = self._read(self._file(key + ".roots"), Kept)
        return kept if kept is not None and entry.kept == kept.token else None

    def store_kept(self, key: str, kept: Kept) -> None:
        """Write what an edit may leave of the result stored under ``key`` (before it)."""
        self._write(self._file(key + ".roots"), kept)

    def prepare(self) -> None:
        """Make the folder before a check (a cache that cannot be made is no error).

        Made during the check inside the workspace, it would change a folder the result
        rests on, and that result would not be kept.
        """
        with self._opened(create=True) as folder:
            if folder is not None and not folder.exists(TAG):
                folder.create(TAG, TAG_TEXT, mode=0o644)

    def store(self, key: str, entry: Entry) -> None:
        """Write an entry atomically; a cache that cannot be written is no error."""
        if self._write(self._file(key), entry):
            self.prune()

    def _write(self, name: str, value: object) -> bool:
        seal = self.seal()
        if seal is None:
            return False
        try:
            payload = plain.dumps(value)
        except plain.Malformed:  # a plugin's result that is not plain data: not kept
            return False
        with self._opened(create=True) as folder:
            return folder is not None and folder.write(name, seal.wrap(name, payload))

    @contextlib.contextmanager
    def _opened(self, *, create: bool = False) -> Iterator[Folder | None]:
        """Open the folder as outputs are opened: never through a link in a checked tree.

        One that cannot be so opened is no cache (and said, once).
        """
        from launchverify.engine import UsageError
        from launchverify.process.outputs import open_folder

        try:
            folder: Folder | None = Folder(open_folder(
                self.path, inside=self.inside, create=create, mode=0o700,
                here=self.named))  # (a folder named may be relative to the working one)
        except UsageError as error:
            if create and self.refused is None:
                self.refused = f"the results cache is not used: {error}"
            folder = None
        try:
            yield folder
        finally:
            if folder is not None:
                folder.close()

    def prune(self) -> None:
        """Remove results (and stored values, ``blobs``) not used for ``MAX_AGE_DAYS`` days."""
        limit = time.time() - MAX_AGE_DAYS * 86400
        with self._opened() as folder:
            if folder is not None:
                _prune(folder, limit, depth=2)


def _prune(folder: Folder, limit: float, depth: int) -> None:
    """Remove stored files older than ``limit`` here and ``depth`` folders below."""
    for entry in folder.entries():
        try:
            if entry.is_symlink():
                continue
            if entry.is_dir(follow_symlinks=False):
                below = folder.sub(entry.name) if depth else None
                if below is not None:
                    with below:
                        _prune(below, limit, depth - 1)
                continue
            if entry.name.endswith(SUFFIX) and \
                    entry.stat(follow_symlinks=False).st_mtime < limit:
                folder.remove(entry.name)
        except OSError:
            continue


class BlobStore:
    """Values of one kind kept by a content key below the cache folder, between runs.

    For work that depends only on a file's content (the interfaces extracted from a
    source file): a check that misses the result cache still reuses it. Each value is
    one sealed file, written atomically; the folder is per launchverify code, so another
    version never reads it. A store that cannot be read or written is no error.
    """

    def __init__(self, cache: ResultCache, kind: str, version: str) -> None:
        self.cache = cache
        self.parts = (kind, version)

    @property
    def folder(self) -> Path:
        """Return where the values are kept."""
        return self.cache.folder.joinpath(*self.parts)

    @contextlib.contextmanager
    def _opened(self, *, create: bool = False) -> Iterator[Folder | None]:
        with self.cache._opened(create=create) as top:
            kind = None if top is None else top.sub(self.parts[0], create=create)
            version = None if kind is None else kind.sub(self.parts[1], create=create)
            try:
                yield version
            finally:
                for folder in (version, kind):
                    if folder is not None:
                        folder.close()

    def _sealed_name(self, key: str) -> tuple[str, str]:
        name = f"{key}{SUFFIX}"
        return name, "/".join((*self.parts, name))

    def load(self, key: str) -> object | None:
        """Return the value stored under ``key``, or ``None``."""
        seal = self.cache.seal()
        if seal is None:
            return None
        name, sealed_as = self._sealed_name(key)
        with self._opened() as folder:
            data = None if folder is None else folder.read(name, MAX_STORED)
            payload = None if data is None else seal.unwrap(sealed_as, data)
            if folder is None or payload is None:
                return None
            try:
                value = plain.loads(payload)
            except plain.Malformed:  # cut short, or from another version: compute again
                return None
            folder.touch(name)  # recently used: kept by the pruning
        return value

    def store(self, key: str, value: object) -> None:
        """Write a value atomically (best effort)."""
        seal = self.cache.seal()
        if seal is None:
            return
        try:
            payload = plain.dumps(value)
        except plain.Malformed:
            return
        name, sealed_as = self._sealed_name(key)
        with self._opened(create=True) as folder:
            if folder is not None:
                folder.write(name, seal.wrap(sealed_as, payload))


_IN_USE: list[ResultCache] = []  # the cache of the running check, innermost last
_CODE_STAMP: list[str] = []


@contextlib.contextmanager
def in_use(cache: ResultCache | None) -> Iterator[None]:
    """Let stores of other results (``blobs``) live in this cache inside the block."""
    if cache is not None:
        _IN_USE.append(cache)
    try:
        yield
    finally:
        if cache is not None:
            _IN_USE.pop()


def blobs(kind: str) -> BlobStore | None:
    """Return the store of a kind of value in the running check's cache, if it has one."""
    if not _IN_USE:
        return None
    if not _CODE_STAMP:
        _CODE_STAMP.append(own_code_stamp())
    return BlobStore(_IN_USE[-1], kind, _CODE_STAMP[0])


def options_text(options: object, skip: Iterable[str] = ()) -> str:
    """Return a dataclass's fields as text for a key, leaving some out."""
    left_out = set(skip)
    return repr([(f.name, getattr(options, f.name)) for f in fields(options)  # type: ignore[arg-type]
                 if f.name not in left_out])
