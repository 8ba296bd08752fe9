"""The two trees a diff compares: git revisions, the working tree, or a folder.

A revision is read from git's objects (``git ls-tree``, ``git cat-file``), never checked
out, and the repository is left exactly as it was: git runs only commands that write
nothing and never read the user's index (objects compared by ``diff-tree``; the working
tree by ``status`` against a private index of HEAD, with ``GIT_OPTIONAL_LOCKS=0``), and
no file of the working tree is linked or touched. A revision's files are written into a
private temporary folder that is removed when the diff ends; links that leave the tree
(judged on the final tree), submodules, objects the clone lacks and files larger than
what a check reads are left out, and the whole tree is bounded.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager, suppress
from dataclasses import dataclass
from pathlib import Path

from launchverify.diff.links import Parts, inside_links, parts_of
from launchverify.engine import UsageError

MAX_TREE_BYTES = 2 << 30  # what one side's files may add up to
GIT_SECONDS = 120.0
# git as the repository's owner configured it, without prompts, pagers or file monitors
# (and an index written only whole: a split one would write a shared index into .git)
_GIT = ("git", "-c", "core.fsmonitor=false", "-c", "core.pager=cat",
        "-c", "core.splitIndex=false")
# no prompt, no fetch of a missing object, no index refreshed on disk by `status` (porcelain
# `git diff` ignores GIT_OPTIONAL_LOCKS and rewrites the index: it is never run)
_QUIET = {"GIT_TERMINAL_PROMPT": "0", "GIT_NO_LAZY_FETCH": "1", "GIT_OPTIONAL_LOCKS": "0"}


@dataclass(frozen=True)
class Side:
    """One tree of a diff: where its files are, and what to call it."""

    label: str  # as the user named it (a revision, "working tree", a folder)
    root: Path  # the folder holding its files
    commit: str | None = None  # the commit a revision names


def git(repository: Path, *arguments: str, index: Path | None = None) -> str:
    """Run git in ``repository``; return its output (a failure is a usage error).

    git never sees the user's index: a command is given ``index`` (a private one), else
    none at all (reading the user's would do: with ``core.splitIndex`` every read
    freshens ``.git/sharedindex.*``).
    """
    try:
        with _environment(index) as environment:
            done = subprocess.run([*_GIT, "-C", str(repository), *arguments],
                                  capture_output=True, timeout=GIT_SECONDS, check=False,
                                  env=environment)
    except FileNotFoundError:
        raise UsageError("diff between revisions needs git") from None
    except subprocess.TimeoutExpired:
        raise UsageError(f"git {arguments[0]} took longer than {GIT_SECONDS:g} s") from None
    if done.returncode != 0:
        message = done.stderr.decode("utf-8", "replace").strip().splitlines()
        raise UsageError(f"git {' '.join(arguments)}: {message[-1] if message else 'failed'}")
    return done.stdout.decode("utf-8", "surrogateescape")


@contextmanager
def _environment(index: Path | None = None) -> Iterator[dict[str, str]]:
    """Yield git's environment: quiet, with ``index`` as its index.

    Without one, ``GIT_INDEX_FILE`` names a file that does not exist (an empty index), in
    a private folder removed after.
    """
    if index is not None:
        yield {**os.environ, **_QUIET, "GIT_INDEX_FILE": str(index)}
        return
    with tempfile.TemporaryDirectory(prefix="launchverify-git-") as empty:
        yield {**os.environ, **_QUIET, "GIT_INDEX_FILE": str(Path(empty) / "index")}


@contextmanager
def _head_index(repository: Path) -> Iterator[Path]:
    """Yield a private index holding HEAD's tree, to compare the working tree with.

    It has no file's stat, so git compares every file's content (in memory: nothing is
    written with ``GIT_OPTIONAL_LOCKS=0``); the user's index is never read.
    """
    with tempfile.TemporaryDirectory(prefix="launchverify-index-") as folder:
        index = Path(folder) / "index"
        git(repository, "read-tree", "HEAD", index=index)
        yield index


def repository_of(folder: Path) -> Path:
    """Return the top folder of the git repository holding ``folder``."""
    return Path(git(folder, "rev-parse", "--show-toplevel").strip())


def commit_of(repository: Path, revision: str) -> str:
    """Return the commit a revision names."""
    if revision.startswith("-"):
        raise UsageError(f"not a revision: {revision!r}")
    return git(repository, "rev-parse", "--verify", "--quiet", f"{revision}^{{commit}}").strip()


def checked_out(repository: Path, commit: str) -> bool:
    """Return whether the working tree holds exactly ``commit`` (no change, no new file).

    ``status`` against a private index of HEAD: the user's index is neither read nor
    refreshed (a copy of it would not do: with ``core.splitIndex`` it names the shared
    index in ``.git``, which git freshens on every read). Submodules are not asked (an
    export leaves them out; git would run in each).
    """
    try:
        if commit_of(repository, "HEAD") != commit:
            return False
        with _head_index(repository) as index:
            return not git(repository, "status", "--porcelain", "-z",
                           "--ignore-submodules=all", index=index).strip("\0")
    except UsageError:
        return False


def default_base(repository: Path) -> str:
    """Return the merge base of HEAD with the default branch (what a pull request targets).

    The default branch is the remote's (``origin/HEAD``), else ``main`` or ``master``,
    local or on ``origin``.
    """
    candidates = []
    with suppress(UsageError):
        candidates.append(git(repository, "rev-parse", "--abbrev-ref", "origin/HEAD").strip())
    candidates += ["main", "master", "origin/main", "origin/master"]
    for branch in candidates:
        try:
            return git(repository, "merge-base", branch, "HEAD").strip()
        except UsageError:
            continue
    raise UsageError("no default branch to compare with (main, master, origin/HEAD): "
                     "name the base revision")


def renamed(repository: Path, base: str, head: str | None) -> dict[str, str]:
    """Return the files git sees renamed from ``base`` to ``head`` (None: the working tree).

    Two trees compared as objects (``diff-tree``: no index read, none refreshed); for the
    working tree, the renames committed up to HEAD (a rename not yet committed is not
    followed: its files pair by path). Empty when git cannot tell (a clone without some
    objects): files then pair by path.
    """
    try:
        output = git(repository, "diff-tree", "-r", "-M", "--name-status", "-z", base,
                     head or "HEAD")
    except UsageError:
        return {}
    fields = output.split("\0")
    moved: dict[str, str] = {}
    index = 0
    while index < len(fields) and fields[index]:
        status = fields[index]
        if status.startswith(("R", "C")):
            if status.startswith("R") and index + 2 < len(fields):
                moved[fields[index + 1]] = fields[index + 2]
            index += 3
        else:
            index += 2
    return moved


@contextmanager
def exported(repository: Path, commit: str, label: str,
             max_file_size: int) -> Iterator[Side]:
    """Yield a side holding ``commit``'s tree in a temporary folder (removed after)."""
    folder = Path(tempfile.mkdtemp(prefix="launchverify-diff-"))
    try:
        _extract(repository, commit, folder, max_file_size)
        yield Side(label, folder, commit)
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def _extract(repository: Path, commit: str, into: Path, max_file_size: int) -> None:
    """Write a commit's files into ``into`` from git's objects, within bounds.

    Every file comes from git's objects, none from the working tree: a hard link to the
    reviewer's copy would change its ctime (git then rewrites ``.git/index``, and a
    results cache sees a changed file). Files larger than a check reads, objects the
    clone lacks (a partial clone, a mirror without its largest files), submodules and
    names that are not plain (``..``, empty) are left out. Links are made last, each
    only when its whole walk, in the final tree, stays inside it (``links.py``).
    """
    into = into.resolve()
    files: list[tuple[str, str, Parts]] = []  # (mode, object, path)
    links: list[tuple[str, Parts]] = []
    total = 0
    for mode, kind, oid, size, path in _listing(repository, commit):
        parts = parts_of(path)
        if kind != "blob" or not size.isdigit() or int(size) > max_file_size \
                or parts is None:
            continue
        total += int(size)
        if total > MAX_TREE_BYTES:
            raise UsageError(f"the tree of {commit[:12]} is larger than "
                             f"{MAX_TREE_BYTES >> 30} GiB")
        if mode == "120000":
            links.append((oid, parts))
        else:
            files.append((mode, oid, parts))
    folders = _Folders(into)
    written = [parts for (mode, _, parts), data
               in zip(files, _blobs(repository, [oid for _, oid, _ in files]), strict=True)
               if data is not None and _write(folders, parts, data, mode == "100755")]
    targets: dict[Parts, str] = {}
    for (_, parts), data in zip(links, _blobs(repository, [oid for oid, _ in links]),
                                strict=True):
        if data is not None:
            targets.setdefault(parts, os.fsdecode(data))
    for parts, target in inside_links(written, targets).items():
        with suppress(OSError):
            if folders.make(parts[:-1]):
                into.joinpath(*parts).symlink_to(target)


def _listing(repository: Path, commit: str) -> Iterator[tuple[str, str, str, str, str]]:
    """Yield each entry of a commit's whole tree: mode, kind, object, size and path."""
    for entry in git(repository, "ls-tree", "-r", "-z", "--long", "--full-tree",
                     commit).split("\0"):
        header, _, path = entry.partition("\t")
        fields = header.split()
        if len(fields) == 4:
            yield fields[0], fields[1], fields[2], fields[3], path


class _Folders:
    """The folders made below ``root``, each made once (only plain names: no link yet)."""

    def __init__(self, root: Path) -> None:
        self.root = root
        self.made: set[Parts] = {()}

    def make(self, folder: Parts) -> bool:
        """Make a folder and those above it; return whether it is there (a file may be)."""
        for end in range(1, len(folder) + 1):
            if folder[:end] not in self.made:
                try:
                    self.root.joinpath(*folder[:end]).mkdir(0o700)
                except OSError:
                    return False
                self.made.add(folder[:end])
        return True


def _write(folders: _Folders, parts: Parts, data: bytes, executable: bool) -> bool:
    """Write one file of the side (a new file, never through a link); return whether done."""
    if not folders.make(parts[:-1]):
        return False
    try:
        descriptor = os.open(folders.root.joinpath(*parts),
                             os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW,
                             0o700 if executable else 0o600)
    except (OSError, ValueError):  # (a name the file system refuses, one given twice)
        return False
    try:
        with os.fdopen(descriptor, "wb") as out:
            out.write(data)
    except OSError:  # (a full disk: the file is then not part of the side)
        return False
    return True


def _blobs(repository: Path, objects: list[str]) -> Iterator[bytes | None]:
    """Yield each object's content (``None`` for one the repository lacks), in order."""
    if not objects:
        return
    with _environment() as environment:
        with tempfile.TemporaryFile() as asked:  # (a file: no thread to feed a pipe)
            asked.write(b"".join(oid.encode("ascii") + b"\n" for oid in objects))
            asked.seek(0)
            process = subprocess.Popen(
                [*_GIT, "-C", str(repository), "cat-file", "--batch"], stdin=asked,
                stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, env=environment)
        assert process.stdout is not None
        try:
            for _ in objects:
                header = process.stdout.readline().split()
                if len(header) != 3 or not header[2].isdigit():
                    yield None  # "<object> missing"
                    continue
                data = process.stdout.read(int(header[2]))
                process.stdout.read(1)  # the line feed after each object
                yield data
        finally:
            process.stdout.close()
            if process.poll() is None:
                process.kill()
            process.wait()
