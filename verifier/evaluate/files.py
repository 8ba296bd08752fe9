"""The launch files of one run, each read once, with what is derived from them per run."""

from __future__ import annotations

from pathlib import Path

from launchverify.frontends import LoadedFile, load_launch_file
from launchverify.graph import StaticArgument


class FileCache:
    """Loads each launch file once per run, whoever asks for it."""

    def __init__(self) -> None:
        self._files: dict[Path, LoadedFile] = {}
        self.static_arguments: dict[Path, tuple[StaticArgument, ...]] = {}

    def __call__(self, path: Path) -> LoadedFile:
        """Return the loaded file, reading it the first time."""
        loaded = self._files.get(path)
        if loaded is None:
            loaded = load_launch_file(path)
            self._files[path] = loaded
        return loaded
