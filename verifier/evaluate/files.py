"""The launch files of one run, each read once, with what is derived from them per run."""

from __future__ import annotations

from pathlib import Path

from launchverify.frontends import LoadedFile, load_launch_file
from launchverify.frontends.param_file import ParamFile, load_param_file
from launchverify.frontends.python import PythonFrontend
from launchverify.graph import StaticArgument
from launchverify.workspace.packages import PackageIndex


class FileCache:
    """Loads each launch file and parameter file once per run, whoever asks for it."""

    def __init__(self, index: PackageIndex, workspace: Path) -> None:
        self._files: dict[Path, LoadedFile] = {}
        self._param_files: dict[Path, ParamFile] = {}
        self.static_arguments: dict[Path, tuple[StaticArgument, ...]] = {}
        self.python = PythonFrontend(index, workspace)

    def __call__(self, path: Path) -> LoadedFile:
        """Return the loaded file, reading it the first time."""
        loaded = self._files.get(path)
        if loaded is None:
            loaded = load_launch_file(path, self.python)
            self._files[path] = loaded
        return loaded

    def param_file(self, path: Path) -> ParamFile:
        """Return a parameter file, reading it the first time."""
        loaded = self._param_files.get(path)
        if loaded is None:
            loaded = load_param_file(path)
            self._param_files[path] = loaded
        return loaded
