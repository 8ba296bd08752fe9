"""Stored results that only this installation can have written.

The results cache may live where a pull request writes too (a CI job that keeps
``XDG_CACHE_HOME`` in its checkout, for ``actions/cache``). A stored result decides a
verdict, so one planted there must not be taken for ours: every stored file is sealed
with a secret that never lies in a checked tree, a random key made once in the user's
state folder (``$XDG_STATE_HOME/launchverify``, else ``~/.local/state/launchverify``).
The seal covers the file's name (a result cannot be moved under another check's key)
and its content; the name itself is a keyed digest of what the check was asked, so it
cannot be computed from outside either. A file without a valid seal is a miss.

The folders are used by descriptor, never through a link (``Folder``): a link planted
in a cache folder is neither read, written through, nor removed through.
"""

from __future__ import annotations

import contextlib
import hashlib
import hmac
import os
import stat
from collections.abc import Iterable, Iterator
from pathlib import Path

SECRET_BYTES = 32
_NAME = "secret"
_MAGIC = b"launchverify sealed 1\n"
_SEAL = 64  # hex digits of the seal, after the magic line
_DIRECTORY = os.O_RDONLY | os.O_DIRECTORY | getattr(os, "O_NOFOLLOW", 0) | getattr(
    os, "O_CLOEXEC", 0)
_READ = os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_NOFOLLOW", 0) | getattr(
    os, "O_CLOEXEC", 0)


def default_state_dir() -> Path:
    """Return ``$XDG_STATE_HOME/launchverify``, else ``~/.local/state/launchverify``."""
    base = os.environ.get("XDG_STATE_HOME") or str(Path.home() / ".local" / "state")
    return Path(base) / "launchverify"


class Seal:
    """Names and seals stored files with the installation's secret."""

    def __init__(self, secret: bytes) -> None:
        self._secret = secret

    def name(self, parts: Iterable[object]) -> str:
        """Return the stored name of what a check was asked (a keyed digest of it)."""
        digest = hashlib.blake2b(key=self._secret, digest_size=20, person=b"lv-name")
        for part in parts:
            digest.update(repr(part).encode("utf-8", "replace"))
            digest.update(b"\0")
        return digest.hexdigest()

    def _seal(self, name: str, payload: bytes) -> bytes:
        digest = hashlib.blake2b(key=self._secret, digest_size=_SEAL // 2, person=b"lv-seal")
        digest.update(name.encode("utf-8", "surrogateescape") + b"\0")
        digest.update(payload)
        return digest.hexdigest().encode("ascii")

    def wrap(self, name: str, payload: bytes) -> bytes:
        """Return the bytes to store under ``name``: the payload with its seal."""
        return _MAGIC + self._seal(name, payload) + b"\n" + payload

    def unwrap(self, name: str, data: bytes) -> bytes | None:
        """Return the payload stored under ``name`` if this installation sealed it."""
        head = len(_MAGIC)
        if not data.startswith(_MAGIC) or data[head + _SEAL:head + _SEAL + 1] != b"\n":
            return None
        payload = data[head + _SEAL + 1:]
        if not hmac.compare_digest(data[head:head + _SEAL], self._seal(name, payload)):
            return None
        return payload


def installation_seal(state: Path | None = None, *, create: bool = True) -> Seal | None:
    """Return the seal of this installation, making its secret the first time (``create``).

    ``None`` when the secret can neither be read nor made (a read-only home), or is not
    there yet and not to be made: then nothing is stored, and nothing stored is trusted.
    """
    folder = Folder.open(state or default_state_dir(), create=create)
    if folder is None:
        return None
    with folder:
        secret = folder.read(_NAME, SECRET_BYTES + 1)
        if secret is None or len(secret) != SECRET_BYTES:
            if not create:
                return None
            made = os.urandom(SECRET_BYTES)
            if not folder.create(_NAME, made, mode=0o600):
                # another check made it meanwhile, or a malformed one lies there
                secret = folder.read(_NAME, SECRET_BYTES + 1)
                if secret is None or len(secret) != SECRET_BYTES:
                    return None
            else:
                secret = made
    return Seal(secret)


class Folder:
    """A folder opened without following links, used by its descriptor.

    Each name is read, written and removed relative to the descriptor, never through a
    link (a link in its place is refused), so what the path named when it was opened
    is what is used, whatever is renamed meanwhile.
    """

    def __init__(self, fd: int) -> None:
        self.fd = fd

    @classmethod
    def open(cls, path: Path, *, create: bool = False) -> Folder | None:
        """Open ``path`` (making it, and its parents, when asked); ``None``: it cannot be.

        The path's own folders are the user's (a home reached through a link is fine);
        its last component must be a folder, not a link to one.
        """
        if create:
            with contextlib.suppress(OSError):
                path.parent.mkdir(parents=True, exist_ok=True)
            with contextlib.suppress(OSError):
                path.mkdir(mode=0o700)
        try:
            return cls(os.open(path, _DIRECTORY))
        except OSError:
            return None

    def __enter__(self) -> Folder:
        return self

    def __exit__(self, *_: object) -> None:
        self.close()

    def close(self) -> None:
        """Let the descriptor go."""
        if self.fd >= 0:
            with contextlib.suppress(OSError):
                os.close(self.fd)
            self.fd = -1

    def sub(self, name: str, *, create: bool = False) -> Folder | None:
        """Open the folder ``name`` inside this one (never a link), making it when asked."""
        if create:
            with contextlib.suppress(OSError):
                os.mkdir(name, 0o700, dir_fd=self.fd)
        try:
            return Folder(os.open(name, _DIRECTORY, dir_fd=self.fd))
        except OSError:
            return None

    def read(self, name: str, most: int) -> bytes | None:
        """Return a regular file's bytes, at most ``most`` of them (``None``: not one)."""
        try:
            fd = os.open(name, _READ, dir_fd=self.fd)
        except OSError:
            return None
        try:
            info = os.fstat(fd)
            if not stat.S_ISREG(info.st_mode) or info.st_size > most:
                return None
            chunks = []
            size = 0
            while size <= most and (chunk := os.read(fd, min(1 << 22, most + 1 - size))):
                chunks.append(chunk)
                size += len(chunk)
            return b"".join(chunks) if size <= most else None
        except OSError:
            return None
        finally:
            os.close(fd)

    def create(self, name: str, data: bytes, *, mode: int = 0o600) -> bool:
        """Write a file that does not exist yet (``False``: one is there, or no room)."""
        try:
            fd = os.open(name, os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(
                os, "O_NOFOLLOW", 0) | getattr(os, "O_CLOEXEC", 0), mode, dir_fd=self.fd)
        except OSError:
            return False
        try:
            with os.fdopen(fd, "wb") as out:
                out.write(data)
        except OSError:
            self.remove(name)
            return False
        return True

    def write(self, name: str, data: bytes) -> bool:
        """Write ``name`` atomically: a reader sees the old file or the new one, whole."""
        from launchverify.process.outputs import replace_in

        return replace_in(self.fd, name, data)

    def touch(self, name: str) -> None:
        """Mark a file recently used (never a link's target)."""
        with contextlib.suppress(OSError, NotImplementedError):
            os.utime(name, dir_fd=self.fd, follow_symlinks=False)

    def entries(self) -> Iterator[os.DirEntry[str]]:
        """Yield what the folder holds (nothing when it cannot be listed)."""
        try:
            with os.scandir(self.fd) as listing:
                yield from listing
        except OSError:
            return

    def remove(self, name: str) -> None:
        """Remove a file (a link is removed itself, never what it points to)."""
        with contextlib.suppress(OSError):
            os.unlink(name, dir_fd=self.fd)

    def exists(self, name: str) -> bool:
        """Return whether ``name`` is there (a link counts, followed or not)."""
        try:
            os.stat(name, dir_fd=self.fd, follow_symlinks=False)
        except OSError:
            return False
        return True
