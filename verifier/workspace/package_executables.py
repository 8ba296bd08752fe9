"""Which executables a package installs, read from its install tree or its build files.

``ros2 run``/``Node(executable=...)`` look in ``<prefix>/lib/<package>/``. When the package
is installed we list that folder. Otherwise we read its sources the way colcon would build
them: ``setup.py``/``setup.cfg`` console scripts for ament_python, and for ament_cmake its
``CMakeLists.txt`` (``cmake_targets``). An answer that may miss some is marked incomplete,
and an incomplete answer never produces a finding.

``build_targets`` reads the same ``CMakeLists.txt`` for the sources of each target and the
component plugins registered on libraries (for the node interfaces read from sources).
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

from launchverify.workspace.cmake_targets import CMakeTargets
from launchverify.workspace.packages import Package
from launchverify.workspace.reading import read_file

MAX_SETUP_BYTES = 512 * 1024  # setup.py, setup.cfg and package.xml


@dataclass(frozen=True)
class BuildTargets:
    """The sources of each CMake target, and the components registered on libraries.

    ``sources`` maps a target to its source words, expanded (relative to the package, or
    absolute; a ``DIRECTORY`` of ``ament_auto_*`` ends with ``/``). ``components`` holds
    ``(library, plugin class, executable or None)``.
    """

    sources: dict[str, tuple[str, ...]]
    components: tuple[tuple[str, str, str | None], ...]
    complete: bool
    links: dict[str, tuple[str, ...]] = field(default_factory=dict)  # target_link_libraries
    executables: frozenset[str] = frozenset()  # add_executable targets installed in lib/
    output_names: dict[str, str] = field(default_factory=dict)  # target -> installed name
    partial: frozenset[str] = frozenset()  # targets whose sources may be more than listed
    touched: frozenset[str] = frozenset()  # words of CMake commands not understood
    sources_open: bool = True  # whether such a command may have added to any target

    def sources_known(self, targets: set[str]) -> bool:
        """Return whether these targets' sources are all listed.

        No command not understood names one of them, nor may have named one.
        """
        return not self.sources_open and targets.isdisjoint(self.partial | self.touched)


def build_targets(source: Path, name: str) -> BuildTargets | None:
    """Return the targets a CMake package builds from its sources, or ``None``."""
    if not (source / "CMakeLists.txt").is_file():
        return None
    cmake = CMakeTargets(source, name)
    if _cmake_executables(cmake) is None and not cmake.sources:
        return None
    return BuildTargets({t: tuple(words) for t, words in cmake.sources.items()},
                        tuple(cmake.components), cmake.complete and cmake.built,
                        {t: tuple(words) for t, words in cmake.links.items()},
                        frozenset(cmake.targets & cmake.installed or cmake.targets),
                        dict(cmake.output_names), frozenset(cmake.partial),
                        frozenset(cmake.touched), cmake.sources_open)


@dataclass(frozen=True)
class Executables:
    """What a package provides to ``ros2 run``; ``complete`` says whether that is all."""

    names: frozenset[str]
    complete: bool


def executables(package: Package) -> Executables | None:
    """Return a package's executables, or ``None`` when its layout is not understood."""
    if package.prefix is not None:
        folder = package.prefix / "lib" / package.name
        try:
            names = frozenset(entry.name for entry in folder.iterdir()
                              if entry.is_file() and os.access(entry, os.X_OK))
        except OSError:
            return None
        return Executables(names, complete=True)
    if package.source is None:
        return None
    return _from_sources(package.source, package.name)


_BUILD_TYPE = re.compile(r"<build_type>\s*([\w.]+)\s*</build_type>")


@lru_cache(maxsize=256)
def _from_sources(source: Path, name: str) -> Executables | None:
    manifest = _read(source / "package.xml") or ""
    declared = _BUILD_TYPE.search(manifest)
    build_type = declared.group(1) if declared else (
        "ament_cmake" if (source / "CMakeLists.txt").is_file() else "ament_python")
    if build_type == "ament_python":
        return _python(source, name)
    if build_type.startswith("ament_cmake") and (source / "CMakeLists.txt").is_file():
        return _cmake_executables(CMakeTargets(source, name))
    return None


def _cmake_executables(cmake: CMakeTargets) -> Executables | None:
    """Read a package's CMake files; ``None`` if unreadable, or nothing known installed."""
    if not cmake.read() or (not cmake.installed and not cmake.complete):
        return None
    return Executables(frozenset(cmake.output_names.get(name, name)
                                 for name in cmake.installed), cmake.complete)


# --------------------------------------------------------------------------- ament_python

_ENTRY = re.compile(r"""['"]\s*([A-Za-z0-9_.\-]+)\s*=\s*[A-Za-z0-9_.]+\s*:\s*\w+""")
_CFG_ENTRY = re.compile(r"^\s*([A-Za-z0-9_.\-]+)\s*=\s*[A-Za-z0-9_.]+\s*:\s*\w+", re.M)


# ("lib/" + package_name, ["example/node.py"]) or ('lib/my_pkg', [...]) in data_files
_LIB_FILES = re.compile(r"""\(\s*['"]lib/(?:['"]\s*\+\s*\w+|[\w\-]+['"])\s*,\s*\[([^\]]*)\]""")


def _python(source: Path, package: str) -> Executables | None:
    names: set[str] = set()
    setup = _read(source / "setup.py")
    config = _read(source / "setup.cfg")
    if setup is None and config is None:
        return None
    complete = True
    if setup is not None and "console_scripts" in setup:
        section = setup[setup.index("console_scripts"):]
        end = section.find("]")
        names.update(_ENTRY.findall(section[: end if end >= 0 else None]))
    if config is not None and "console_scripts" in config:
        section = config[config.index("console_scripts"):]
        names.update(_CFG_ENTRY.findall(section.split("\n[", 1)[0]))
    if setup is not None:
        for listed in _LIB_FILES.findall(setup):
            if "glob" in listed or "+" in listed:
                complete = False
            names.update(Path(f).name for f in re.findall(r"""['"]([^'"]+)['"]""", listed))
        if "scripts=" in setup or setup.count("lib/") > len(_LIB_FILES.findall(setup)):
            complete = False  # installs into lib/ in a way not read here
    return Executables(frozenset(names), complete)


def _read(path: Path) -> str | None:
    try:
        data = read_file(path, prefix=MAX_SETUP_BYTES)
    except OSError:
        return None
    return data.decode("utf-8", "replace")
