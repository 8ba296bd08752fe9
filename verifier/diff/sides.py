"""The two trees a diff compares: git revisions, the working tree, or a folder.

A revision is read from git's objects (``git ls-tree``, ``git cat-file``), never checked
out: the user's working tree, index and branches stay as they are, and nothing is
fetched. Its files are written into a private temporary folder that is removed when the
diff ends; links out of the tree, submodules, objects the clone lacks and files larger
than what a check reads are left out, and the whole tree is bounded.
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

from launchverify.engine import UsageError

MAX_TREE_BYTES = 2 << 30  # what one side's files may add up to
GIT_SECONDS = 120.0
# git as the repository's owner configured it, without prompts, pagers or file monitors
_GIT = ("git", "-c", "core.fsmonitor=false", "-c", "core.pager=cat")
# no prompt, no fetch of a missing object, no index refreshed on disk
_QUIET = {"GIT_TERMINAL_PROMPT": "0", "GIT_NO_LAZY_FETCH": "1", "GIT_OPTIONAL_LOCKS": "0"}


@dataclass(frozen=True)
class Side:
    """One tree of a diff: where its files are, and what to call it."""

    label: str  # as the user named it (a revision, "working tree", a folder)
    root: Path  # the folder holding its files
    commit: str | None = None  # the commit a revision names


def git(repository: Path, *arguments: str) -> str:
    """Run git in ``repository``; return its output (a failure is a usage error)."""
    try:
        done = subprocess.run([*_GIT, "-C", str(repository), *arguments], capture_output=True,
                              timeout=GIT_SECONDS, check=False, env={**os.environ, **_QUIET})
    except FileNotFoundError:
        raise UsageError("diff between revisions needs git") from None
    except subprocess.TimeoutExpired:
        raise UsageError(f"git {arguments[0]} took longer than {GIT_SECONDS:g} s") from None
    if done.returncode != 0:
        message = done.stderr.decode("utf-8", "replace").strip().splitlines()
        raise UsageError(f"git {' '.join(arguments)}: {message[-1] if message else 'failed'}")
    return done.stdout.decode("utf-8", "surrogateescape")


def repository_of(folder: Path) -> Path:
    """Return the top folder of the git repository holding ``folder``."""
    return Path(git(folder, "rev-parse", "--show-toplevel").strip())


def commit_of(repository: Path, revision: str) -> str:
    """Return the commit a revision names."""
    if revision.startswith("-"):
        raise UsageError(f"not a revision: {revision!r}")
    return git(repository, "rev-parse", "--verify", "--quiet", f"{revision}^{{commit}}").strip()


def checked_out(repository: Path, commit: str) -> bool:
    """Return whether the working tree holds exactly ``commit`` (no change, no new file)."""
    try:
        return (commit_of(repository, "HEAD") == commit
                and not git(repository, "status", "--porcelain", "-z").strip("\0"))
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

    Empty when git cannot tell (a clone without some objects): files then pair by path.
    """
    try:
        output = git(repository, "diff", "--no-ext-diff", "-M", "--name-status", "-z", base,
                     *([head] if head else []))
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

    Files larger than a check reads, objects the clone lacks (a partial clone, a mirror
    without its largest files) and submodules are left out; a link is made only when
    it points inside the tree.
    """
    listing = git(repository, "ls-tree", "-r", "-z", "--long", "--full-tree", commit)
    wanted: list[tuple[str, str, str]] = []  # (mode, object, path)
    total = 0
    for entry in listing.split("\0"):
        if not entry:
            continue
        header, _, path = entry.partition("\t")
        mode, kind, oid, size = header.split()
        if kind != "blob" or not size.isdigit() or int(size) > max_file_size:
            continue
        total += int(size)
        if total > MAX_TREE_BYTES:
            raise UsageError(f"the tree of {commit[:12]} is larger than "
                             f"{MAX_TREE_BYTES >> 30} GiB")
        wanted.append((mode, oid, path))
    place = _Places(into.resolve())
    wanted = _linked(repository, wanted, place)
    for (mode, _, path), data in zip(wanted, _blobs(repository, [w[1] for w in wanted]),
                                     strict=True):
        target = place(path) if data is not None else None
        if data is None or target is None:
            continue
        if mode == "120000":  # a link: kept when it stays inside the tree
            link = Path(os.fsdecode(data))
            if not link.is_absolute() and (target.parent / link).resolve().is_relative_to(
                    place.root):
                with suppress(OSError):
                    target.symlink_to(link)
            continue
        with suppress(OSError):  # (a name the file system refuses)
            target.write_bytes(data)
            if mode == "100755":
                target.chmod(0o700)


class _Places:
    """Where a tree's files go below ``root``: each inside it, each folder made once."""

    def __init__(self, root: Path) -> None:
        self.root = root
        self.folders: set[Path] = set()

    def __call__(self, path: str) -> Path | None:
        """Return where ``path`` goes, its folder made (``None``: it would leave the root)."""
        target = (self.root / path).resolve()
        if not target.is_relative_to(self.root) or target == self.root:
            return None
        if target.parent not in self.folders:
            target.parent.mkdir(parents=True, exist_ok=True)
            self.folders.add(target.parent)
        return target


def _linked(repository: Path, wanted: list[tuple[str, str, str]], place: _Places
            ) -> list[tuple[str, str, str]]:
    """Link the files the working tree holds alike into ``root``; return the others.

    A file counts as alike when the index has the commit's object for it and the working
    tree's copy is unchanged (``git diff``): a hard link then costs a tenth of writing
    it. Only regular files inside the repository are linked.
    """
    try:
        staged = git(repository, "ls-files", "-s", "-z")
        changed = set(git(repository, "diff", "--no-ext-diff", "--name-only", "-z")
                      .split("\0"))  # (content compared where the index's stat is stale)
    except UsageError:
        return wanted
    index: dict[str, str] = {}
    for entry in staged.split("\0"):
        header, _, path = entry.partition("\t")
        fields = header.split()
        if len(fields) == 3 and fields[2] == "0" and path not in changed:
            index[path] = fields[1]
    top = repository.resolve()
    rest = []
    for mode, oid, path in wanted:
        source = top / path
        if (mode == "120000" or index.get(path) != oid or source.is_symlink()
                or not source.resolve().is_relative_to(top)):
            rest.append((mode, oid, path))
            continue
        try:
            target = place(path)
            if target is not None:
                os.link(source, target, follow_symlinks=False)
        except OSError:  # (another file system, a file that went)
            rest.append((mode, oid, path))
    return rest


def _blobs(repository: Path, objects: list[str]) -> Iterator[bytes | None]:
    """Yield each object's content (``None`` for one the repository lacks), in order."""
    with tempfile.TemporaryFile() as asked:  # (a file: no thread to feed a pipe)
        asked.write(b"".join(oid.encode("ascii") + b"\n" for oid in objects))
        asked.seek(0)
        process = subprocess.Popen(
            [*_GIT, "-C", str(repository), "cat-file", "--batch"], stdin=asked,
            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
            env={**os.environ, **_QUIET})
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
