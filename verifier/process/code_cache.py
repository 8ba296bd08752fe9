"""Compiled code for the methods ``dataclasses`` generates, kept between runs.

``@dataclass`` writes each class's ``__init__``, ``__repr__``, ``__eq__``... as source
text and compiles it when the class is defined: about 0.6 ms a class, and a check
defines some 200 of them before it reads a file, two thirds of its start-up. The text is
the same from run to run, so its compiled code is too: this module lets ``dataclasses``
find it in a file beside the installation (the ``__pycache__`` of the folder holding the
package, not the package's own: a file pip did not install, left in the package's folder
by an uninstall, made the next install's import fail), written as Python writes bytecode
(only when the folder is writable and bytecode writing is not turned off), and never
inside a checked workspace's files. The file holds code compiled
from texts ``dataclasses`` itself produced; a file of another Python, or that does not
read back, is ignored. Code is run from it, so it is sealed as the results cache is
(``findings/sealed.py``: a secret outside any checked tree): a file planted there (a
virtual environment inside a checkout, whose ``__pycache__`` a pull request can fill) is
never run.
"""

from __future__ import annotations

import builtins
import contextlib
import dataclasses
import marshal
import os
import sys
from pathlib import Path
from types import CodeType
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from launchverify.findings.sealed import Seal

MOST_ENTRIES = 4000  # beyond, only what the last run used is kept
_HEADER = f"launchverify dataclass code {sys.version}".encode()


class CodeCache:
    """Compiled method texts by their source, loaded from and saved to one file."""

    def __init__(self, path: Path, state: Path | None = None) -> None:
        self.path = path
        self.state = state  # where the installation's secret is (None: the user's)
        self.known: dict[str, CodeType] = _load(path, _seal(state, create=False))
        self.used: dict[str, CodeType] = {}
        self.added = 0

    def exec(self, source: Any, globals: dict[str, Any] | None = None,
             locals: dict[str, Any] | None = None) -> None:
        """Run ``source`` as ``exec`` does, compiling a text only once across runs."""
        if not isinstance(source, str):
            return builtins.exec(source, globals, locals)
        code = self.known.get(source)
        if code is None:
            code = compile(source, "<string>", "exec")
            self.known[source] = code
            self.added += 1
        self.used[source] = code
        return builtins.exec(code, globals, locals)

    def save(self) -> None:
        """Write the file when this run compiled something new (atomically; quietly)."""
        if not self.added or sys.dont_write_bytecode:
            return
        import tempfile  # only to write (its imports are a tenth of this module's purpose)

        # The secret is the results cache's to make, where a check may (never in a checked
        # tree): a state folder a pull request chose inside its own tree stays untouched
        seal = _seal(self.state, create=False)
        if seal is None:
            return
        kept = self.known if len(self.known) <= MOST_ENTRIES else self.used
        body = marshal.dumps(kept)
        temporary: Path | None = None
        try:
            self.path.parent.mkdir(exist_ok=True)
            handle, name = tempfile.mkstemp(dir=self.path.parent, prefix=".dataclass-")
            temporary = Path(name)
            with os.fdopen(handle, "wb") as out:
                out.write(seal.wrap(_HEADER.decode(), body))
            temporary.chmod(0o644)  # as Python leaves bytecode (mkstemp makes it private)
            temporary.replace(self.path)
        except (OSError, ValueError):
            if temporary is not None:
                with contextlib.suppress(OSError):
                    temporary.unlink()


def install(folder: Path | None = None) -> CodeCache | None:
    """Let ``dataclasses`` take compiled code from the cache; return it (``None``: not here).

    ``dataclasses`` looks up ``exec`` in its own module's globals first, so placing the
    cache's there changes nothing else. Pythons whose ``dataclasses`` builds no text are
    left alone.
    """
    if not hasattr(dataclasses, "_create_fn") and not hasattr(dataclasses, "_FuncBuilder"):
        return None
    # Beside the installation, but not inside the package's folder: pip removes only the
    # files it installed, and a folder ``launchverify`` left holding this one would shadow
    # the next install (an editable one after ``pip install .``) as a namespace package
    cache_folder = folder or Path(__file__).parent.parent.parent / "__pycache__"
    cache = CodeCache(cache_folder /
                      f"launchverify-dataclass-code.{sys.implementation.cache_tag}.bin")
    dataclasses.exec = cache.exec  # type: ignore[attr-defined]
    return cache


def uninstall() -> None:
    """Give ``dataclasses`` the built-in ``exec`` back."""
    dataclasses.__dict__.pop("exec", None)


def _seal(state: Path | None, *, create: bool) -> Seal | None:
    from launchverify.findings.sealed import installation_seal

    return installation_seal(state, create=create)


def _load(path: Path, seal: Seal | None) -> dict[str, CodeType]:
    """Return the compiled texts a file holds (none: absent, stale, broken, not ours).

    Ours: sealed by this installation (a file planted beside our modules is not).
    """
    if seal is None:
        return {}
    try:
        data = path.read_bytes()
    except OSError:
        return {}
    body = seal.unwrap(_HEADER.decode(), data)
    if body is None:
        return {}
    try:
        loaded = marshal.loads(body)
    except (EOFError, ValueError, TypeError):
        return {}
    if not isinstance(loaded, dict):
        return {}
    return {k: v for k, v in loaded.items() if isinstance(k, str) and isinstance(v, CodeType)}
