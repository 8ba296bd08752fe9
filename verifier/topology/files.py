"""One source file's interfaces, read safely and cached by content.

The cache is keyed by the file's content hash (and language), so an unchanged file is
parsed once per process however many executables list it, and a copy of a file elsewhere
reuses the result (relocated); with a cache folder in use (``check`` without
``--no-cache``), between runs too. Unreadable, binary and oversized files give a result
with a ``problem`` instead of raising.
"""

from __future__ import annotations

import hashlib
from collections.abc import Callable
from pathlib import Path

from launchverify.findings.cache import blobs
from launchverify.topology.model import FileInterfaces
from launchverify.workspace.reading import Unreadable, read_file

MAX_SOURCE_BYTES = 2 * 1000 * 1000
MAX_REMEMBERED = 20_000  # results kept in memory (a language server edits many times)
CPP_SUFFIXES = frozenset({".cpp", ".cc", ".cxx", ".c++", ".hpp", ".hh", ".hxx", ".h", ".ipp"})
PY_SUFFIXES = frozenset({".py"})

_CACHE: dict[tuple[str, str], FileInterfaces] = {}
_STATS = {"parsed": 0, "reused": 0}


def language_of(path: Path) -> str | None:
    """Return ``cpp`` or ``python`` for a source file, ``None`` for anything else."""
    suffix = path.suffix.lower()
    if suffix in CPP_SUFFIXES:
        return "cpp"
    if suffix in PY_SUFFIXES:
        return "python"
    return None


def _extractor(language: str) -> Callable[[Path, bytes], FileInterfaces]:
    if language == "cpp":
        from launchverify.topology import cpp

        return cpp.extract
    from launchverify.topology import python

    return python.extract


def file_interfaces(path: Path, language: str | None = None) -> FileInterfaces:
    """Return what one source file creates (cached by content); never raises on bad input."""
    language = language or language_of(path)
    if language is None:
        return FileInterfaces(path, problem="not a C++ or Python source file")
    try:
        data = read_file(path, prefix=MAX_SOURCE_BYTES + 1)
    except (Unreadable, OSError) as error:
        return FileInterfaces(path, problem=f"cannot read: {error}")
    if len(data) > MAX_SOURCE_BYTES:
        return FileInterfaces(path, problem=f"larger than {MAX_SOURCE_BYTES} bytes: not read")
    if b"\0" in data:
        return FileInterfaces(path, problem="binary file: not read")
    key = (language, hashlib.sha256(data).hexdigest())
    cached = _CACHE.get(key)
    store = blobs("interfaces")
    if cached is None and store is not None:
        stored = store.load(f"{language}-{key[1]}")
        cached = stored if isinstance(stored, FileInterfaces) else None
    if cached is not None:
        _STATS["reused"] += 1
        _remember(key, cached)
        return cached.at(path)
    try:
        result = _extractor(language)(path, data)
    except Exception as error:  # one file's surprise must not end a workspace's reading
        result = FileInterfaces(path, problem=f"could not be analysed: "
                                f"{type(error).__name__}: {error}")
    _STATS["parsed"] += 1
    _remember(key, result)
    if store is not None:
        store.store(f"{language}-{key[1]}", result)
    return result


def _remember(key: tuple[str, str], result: FileInterfaces) -> None:
    if len(_CACHE) >= MAX_REMEMBERED and key not in _CACHE:
        _CACHE.clear()
    _CACHE[key] = result


def cache_stats() -> dict[str, int]:
    """Return how many files were parsed and how many reused from the cache."""
    return dict(_STATS)


def clear_cache() -> None:
    """Forget every cached result (tests; a long-lived process after edits is fine as is)."""
    _CACHE.clear()
    _STATS.update(parsed=0, reused=0)
