"""How paths are shown: as the user gave them, else relative to the working directory."""

from __future__ import annotations

from pathlib import Path


def relative_file(path: Path, base: Path) -> str:
    """Return a path relative to ``base`` (posix), or absolute when outside it."""
    try:
        return path.resolve().relative_to(base.resolve()).as_posix()
    except ValueError:
        return path.resolve().as_posix()


def display_path(path: Path | str) -> str:
    """Return ``path`` relative to the working directory when below it, else unchanged."""
    candidate = Path(path)
    if not candidate.is_absolute():
        return str(candidate)
    try:
        return str(candidate.relative_to(Path.cwd().resolve()))
    except ValueError:
        return str(candidate)
