"""Resolve ROS package names to folders, with or without ROS 2 installed.

Packages come from the ``package.xml`` files of the workspace (sources), from the
workspace's ``install/`` tree, and from the ament index of every prefix in
``AMENT_PREFIX_PATH``. A path written through the install layout
(``<share of pkg>/launch/x.launch.xml``) is found in the package's sources when only
sources are present: first at the same relative path, then by file name.
"""

from __future__ import annotations

import contextlib
import functools
import os
import re
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from launchverify.workspace.cmake_python import PythonModule, python_modules
from launchverify.workspace.cmake_words import MAX_CMAKE_BYTES
from launchverify.workspace.paths import link_inside, resolved
from launchverify.workspace.reading import read_file

if TYPE_CHECKING:
    from launchverify.topology.inherited import Lookup

SKIP_DIRS = frozenset({
    ".git", ".hg", ".svn", "build", "install", "log", "node_modules", "__pycache__",
    ".venv", "venv", ".tox", ".mypy_cache", ".pytest_cache", ".ruff_cache",
})
IGNORE_MARKERS = ("COLCON_IGNORE", "AMENT_IGNORE", "CATKIN_IGNORE")
MAX_SCANNED_DIRS = 100_000
_NAME = re.compile(rb"<name>\s*([^<\s]+)\s*</name>")


@dataclass(frozen=True, slots=True)
class Package:
    """A package: its source folder (workspace) and/or its installed prefix and share."""

    name: str
    source: Path | None = None
    prefix: Path | None = None

    @property
    def share(self) -> Path:
        """Return the folder ``$(find-pkg-share)`` points at (sources when not installed)."""
        if self.prefix is not None:
            return self.prefix / "share" / self.name
        assert self.source is not None
        return self.source

    @property
    def installed(self) -> bool:
        """Return whether an install prefix is known."""
        return self.prefix is not None


_DEPEND = re.compile(rb"<(?:build_|exec_|test_|build_export_|buildtool_)?depend(?:\s[^>]*)?>"
                     rb"\s*([^<\s]+)\s*</")


@functools.lru_cache(maxsize=4096)
def package_dependencies(package_xml: Path) -> frozenset[str]:
    """Return the packages a manifest declares it depends on (any ``*depend`` tag)."""
    try:
        data = read_file(package_xml, prefix=200_000)
    except OSError:
        return frozenset()
    return frozenset(m.decode("utf-8", "replace") for m in _DEPEND.findall(data))


def package_name(package_xml: Path) -> str | None:
    """Return the ``<name>`` of a package manifest, or ``None`` if unreadable."""
    try:
        data = read_file(package_xml, prefix=200_000)
    except OSError:
        return None
    match = _NAME.search(data)
    return match.group(1).decode("utf-8", "replace") if match else None


def listing(folder: str, *, links: bool | Callable[[str], bool]
            ) -> tuple[list[str], list[os.DirEntry[str]]] | None:
    """Return the folders a walk enters below ``folder`` (paths, sorted), and the rest.

    Build output and dot folders are not entered; linked folders only with ``links``, or
    those it accepts when it is a test (neither kind counts among the rest). ``None``
    for a folder that cannot be listed.
    Walks over every folder of a workspace use this on strings: ``os.walk`` and a
    ``Path`` per entry took most of their time.
    """
    try:
        with os.scandir(folder) as found:
            entries = list(found)
    except OSError:
        return None
    folders, rest = [], []
    for entry in entries:
        try:
            is_folder = entry.is_dir()
        except OSError:
            is_folder = False
        if not is_folder:
            rest.append(entry)
        elif entry.name in SKIP_DIRS or entry.name.startswith("."):
            continue
        elif not entry.is_symlink() or (links(entry.path) if callable(links) else links):
            folders.append(entry.path)
    return sorted(folders), rest  # (paths in one folder sort as their names)


def scan_sources(root: Path, within: Iterable[Path] = ()) -> Iterator[tuple[str, Path]]:
    """Yield ``(name, folder)`` for every package manifest below ``root``.

    Skips build artefacts, hidden folders and folders marked ``COLCON_IGNORE``, and does
    not descend into a package (packages do not nest). Like colcon, it follows symbolic
    links (repositories linked into ``src/`` are common), visiting each folder once, but
    only to folders below ``root`` or ``within`` (the folders the user lets a check
    read): a link to ``/`` in a pull request must not make the check walk the machine.
    """
    allowed = [os.path.realpath(folder) for folder in (root, *within)]

    def inside(link: str) -> bool:
        return link_inside(link, allowed)

    scanned = 0
    seen: set[tuple[int, int]] = set()
    pending = [os.fspath(root)]  # strings: the walk visits every folder of the workspace
    while pending:
        current = pending.pop()
        listed = listing(current, links=inside)  # links followed (as colcon does) inside
        if listed is None:
            continue
        scanned += 1
        if scanned > MAX_SCANNED_DIRS:
            return
        try:
            identity = os.stat(current)  # noqa: PTH116 (string paths)
        except OSError:
            continue
        if (identity.st_dev, identity.st_ino) in seen:
            continue
        seen.add((identity.st_dev, identity.st_ino))
        dirs, others = listed
        files = {entry.name for entry in others}
        if any(marker in files for marker in IGNORE_MARKERS):
            continue
        if "package.xml" in files:
            name = package_name(Path(current, "package.xml"))
            if name:
                yield name, Path(current)
            continue
        pending.extend(reversed(dirs))


def _shared_parts(one: Path, other: Path) -> int:
    """Return how many leading path parts two absolute paths share."""
    return len(Path(os.path.commonpath([one, other])).parts)


def scan_prefix(prefix: Path) -> Iterator[str]:
    """Yield the package names registered in one install prefix's ament index."""
    marker_dir = prefix / "share" / "ament_index" / "resource_index" / "packages"
    try:
        yield from sorted(entry.name for entry in marker_dir.iterdir())
    except OSError:
        return


def workspace_prefixes(workspace: Path) -> list[Path]:
    """Return the install prefixes of a colcon workspace (merged or isolated layout)."""
    install = workspace / "install"
    if not install.is_dir():
        return []
    prefixes = [install] if (install / "share" / "ament_index").is_dir() else []
    with contextlib.suppress(OSError):
        prefixes.extend(
            child for child in sorted(install.iterdir())
            if (child / "share" / "ament_index").is_dir()
        )
    return prefixes


class PackageIndex:
    """Every package launchverify can see, by name."""

    def __init__(self, workspaces: Iterable[Path] = (), prefixes: Iterable[Path] = (),
                 near: Iterable[Path] = ()) -> None:
        self._packages: dict[str, Package] = {}
        self._roots: dict[Path, Package] | None = None  # share/source folder -> package
        self._located: dict[Path, Path | None] = {}
        self._named: dict[Path, dict[str, list[Path]]] = {}  # package source -> its files
        self._installed_from: dict[Path, list[Path]] = {}
        self._files: dict[str, list[Path]] = {}  # package -> its source files (package_files)
        self._headers: dict[str, Path | None] = {}  # #include path -> its file (header)
        self._python_packages: dict[str, list[Path]] | None = None  # name -> packages
        self._cmake_python: dict[str, list[PythonModule]] | None = None  # name -> installs
        self._site: list[Path] | None = None
        self.sources: dict[str, list[Path]] = {}  # every source folder of each name
        self.workspaces = [resolved(w) for w in workspaces]
        self.prefixes = [resolved(p) for p in prefixes]
        self.has_install = bool(self.prefixes)
        for prefix in self.prefixes:
            for name in scan_prefix(prefix):
                self._packages.setdefault(name, Package(name, prefix=prefix))
        for workspace in self.workspaces:
            for prefix in workspace_prefixes(workspace):
                self.has_install = True
                for name in scan_prefix(prefix):
                    self._add(Package(name, prefix=prefix))
            for name, folder in scan_sources(workspace, within=self.workspaces):
                folders = self.sources.setdefault(name, [])
                if folder not in folders:
                    folders.append(folder)
                self._add(Package(name, source=folder))
        self._prefer_near([resolved(p) for p in near])

    @classmethod
    def from_environment(cls, workspaces: Iterable[Path], prefixes: Iterable[Path] = (),
                         near: Iterable[Path] = ()) -> PackageIndex:
        """Build the index for these workspaces and prefixes plus ``AMENT_PREFIX_PATH``."""
        raw = os.environ.get("AMENT_PREFIX_PATH", "")
        found = [*prefixes, *(Path(p) for p in raw.split(os.pathsep) if p)]
        return cls(workspaces, found, near)

    def _prefer_near(self, near: list[Path]) -> None:
        """Give a name defined twice the copy nearest to what is checked.

        What a user checks is the tree they build: its copy of a package overlays another
        repository's copy in the same workspace, as an overlay does an underlay (and as
        the real library finds it where the user builds). Nearest is the copy sharing the
        most leading folders with a checked path; an installed copy (``share/<name>``)
        whose manifest holds a source copy's bytes is that source's install, as near as it
        (``canonical`` says the same of its files). A tie keeps the first one scanned.
        """
        if not near:
            return
        for name, folders in self.sources.items():
            if len(folders) < 2:
                continue
            own = {folder: max(_shared_parts(folder, path) for path in near)
                   for folder in folders}
            nearness = dict(own)
            for folder in folders:
                if _installed_layout(folder / "package.xml", name):
                    nearness[folder] = max([own[folder], *(
                        own[source] for source in folders if source != folder
                        and _same_bytes(source / "package.xml", folder / "package.xml"))])
            best = max(folders, key=nearness.__getitem__)  # max keeps the first of a tie
            known = self._packages[name]
            if best != known.source:
                self._packages[name] = Package(name, source=best, prefix=known.prefix)

    def _add(self, package: Package) -> None:
        known = self._packages.get(package.name)
        if known is None:
            self._packages[package.name] = package
            return
        self._packages[package.name] = Package(
            package.name,
            source=known.source or package.source,
            prefix=package.prefix or known.prefix,
        )

    def duplicates(self, name: str) -> list[Path]:
        """Return the source folders of a name defined more than once (else empty)."""
        folders = self.sources.get(name, [])
        return folders if len(folders) > 1 else []

    def find(self, name: str) -> Package | None:
        """Return the package called ``name``, if any."""
        return self._packages.get(name)

    def header(self, include: str) -> Path | None:
        """Return the source file an ``#include "pkg/x.hpp"`` names, in pkg's sources here.

        ROS 2 packages install ``include/<pkg>/x.hpp`` (humble on: ``include/<pkg>/<pkg>/``).
        """
        if include not in self._headers:  # every target of a package asks the same
            self._headers[include] = self._header(include)
        return self._headers[include]

    def _header(self, include: str) -> Path | None:
        first = include.partition("/")[0]
        found = self.find(first) if first and first != include else None
        if found is None or found.source is None:
            return None
        for base in (found.source / "include", found.source / "include" / first):
            candidate = base / include
            if resolved(candidate).is_relative_to(resolved(found.source)) and \
                    candidate.is_file():
                return candidate  # inside the package: ``..`` in an include reads no more
        return None

    def package_files(self, name: str) -> list[Path]:
        """Return the C++ and Python files of a package's sources here (none when built).

        Listed once per index: every node class deriving from a class of that package asks.
        """
        if name not in self._files:
            found = self.find(name)
            suffixes = {".cpp", ".cc", ".cxx", ".hpp", ".hh", ".hxx", ".h", ".py"}
            self._files[name] = [] if found is None or found.source is None else sorted(
                p for p in found.source.rglob("*") if p.suffix in suffixes
                and p.is_file() and not p.is_symlink())
        return self._files[name]

    def lookup(self) -> Lookup:
        """Return where the topology readers find other packages' headers and files."""
        from launchverify.topology.inherited import Lookup

        return Lookup(self.header, self.package_files)

    def declares(self, path: Path, dependency: str) -> bool:
        """Return whether the package owning ``path`` declares ``dependency`` in package.xml.

        Such a package comes from elsewhere (a ``.repos`` file, another overlay): the
        workspace at hand is incomplete, the launch file is not wrong.
        """
        owner = self.owner(path)
        if owner is None:
            return False
        folders = [f for f in (owner.source, owner.share) if f is not None]
        return any(dependency in package_dependencies(folder / "package.xml")
                   for folder in folders)

    def python_sources(self, module: str) -> list[Path]:
        """Return what workspace packages install as the top-level Python module ``module``.

        Each is a package folder (holding ``__init__.py``) or a ``.py`` file of a
        package's sources: the Python packages of an ament_python package (``setup.py``,
        ``setup.cfg``), and what an ament_cmake package's ``CMakeLists.txt`` installs into
        ``PYTHON_INSTALL_DIR`` (``ament_python_install_package``, ``..._module``,
        ``install(DIRECTORY|FILES ...)``, see ``cmake_python``), whatever the package is
        called. A name two packages install differently is left out: which one a sourced
        workspace imports depends on the build order, so the module stays unknown.
        """
        if self._python_packages is None:  # one listing of every package folder, once
            self._python_packages = {}
            for folders in self.sources.values():
                for folder in folders:
                    for name in _python_package_folders(folder):
                        self._python_packages.setdefault(name, []).append(folder)
        found = [folder / module for folder in self._python_packages.get(module, [])
                 if _build_type(folder) != "cmake" and _setup_installs(folder, module)]
        found += [installed.path for installed in self._cmake_modules().get(module, [])]
        distinct = list(dict.fromkeys(found))
        return distinct if len(distinct) == 1 else []

    def _cmake_modules(self) -> dict[str, list[PythonModule]]:
        """Return the modules the ament_cmake packages here install, by name (read once)."""
        if self._cmake_python is None:
            self._cmake_python = {}
            for folders in self.sources.values():
                for folder in folders:
                    if _build_type(folder) == "python" or \
                            not _may_install_python(folder / "CMakeLists.txt"):
                        continue
                    for installed in python_modules(folder):
                        self._cmake_python.setdefault(installed.name, []).append(installed)
        return self._cmake_python

    def site_packages(self) -> list[Path]:
        """Return the Python folders of the installed prefixes (``lib/python3.*/...``).

        A sourced workspace puts them on ``PYTHONPATH``; with only ``AMENT_PREFIX_PATH``
        set, they are found here.
        """
        if self._site is None:
            patterns = ("lib/python3*/site-packages", "local/lib/python3*/dist-packages",
                        "lib/python3/dist-packages")
            self._site = [folder for prefix in self.prefixes
                          for pattern in patterns for folder in sorted(prefix.glob(pattern))
                          if folder.is_dir()]
        return self._site

    def names(self) -> list[str]:
        """Return every known package name, sorted."""
        return sorted(self._packages)

    def owner(self, path: Path) -> Package | None:
        """Return the package whose share or source folder contains ``path``.

        The deepest such folder wins (a package nested in another's folder owns its
        files). A lookup walks ``path``'s parents in a map of the folders, not every
        package: rules and the evaluator ask this for every file they meet.
        """
        if self._roots is None:
            roots: dict[Path, Package] = {}
            for package in self._packages.values():
                for root in (package.share, package.source):
                    if root is not None:
                        roots.setdefault(root, package)
            for name, folders in self.sources.items():
                for folder in folders:  # a duplicated name: each copy owns its own files
                    roots.setdefault(folder, Package(name, source=folder))
            self._roots = roots
        for folder in (path, *path.parents):
            found = self._roots.get(folder)
            if found is not None:
                return found
        return None

    def locate(self, path: Path) -> Path | None:
        """Find a file as ros2 launch would, falling back from install layout to sources.

        Returns the existing file, or ``None``. Remembered: an index lives for one check,
        during which files do not change, and every root asks again for the files its
        includes and nodes name.
        """
        if path in self._located:
            return self._located[path]
        found = self._locate(path)
        found = self._located[path] = None if found is None else self.canonical(found)
        return found

    def canonical(self, path: Path) -> Path:
        """Return the one path findings use for a file reached by several.

        Links are resolved where they stay in what launchverify sees (the workspace, its
        packages). An installed copy (``.../share/<package>/...``) whose source file
        holds the same bytes is that source file: the one the user edits.
        """
        real = resolved(path)
        if real != path and not self._seen(real):
            return path
        package = self.owner(real)
        if package is None or not _installed_layout(real, package.name):
            return real
        share = next(p for p in real.parents if p.name == package.name
                     and p.parent.name == "share")
        for source in self.sources.get(package.name, []):
            if _installed_layout(source / "package.xml", package.name):
                continue
            twin = source / real.relative_to(share)
            if _same_bytes(twin, real):
                return twin
        return real

    def _seen(self, path: Path) -> bool:
        return (any(path.is_relative_to(w) for w in self.workspaces)
                or self.owner(path) is not None)

    def _locate(self, path: Path) -> Path | None:
        if path.is_file():
            return path
        package = self.owner(path)
        if package is None or package.source is None:
            return None
        relative = path.relative_to(package.share) if path.is_relative_to(package.share) else None
        if relative is None:
            return None
        candidate = package.source / relative
        if candidate.is_file():
            return candidate
        if package.source not in self._named:
            self._named[package.source] = _files_by_name(package.source)
        return _by_name(self._named[package.source].get(relative.name, []), relative)

    def neighbours(self, path: Path) -> list[str]:
        """Return the names of the files in the folder where ``path`` would be.

        The folder itself, and for a path in a package's install layout the matching
        folder of its sources (where ``locate`` finds files first), or the source folders
        an ``install(DIRECTORY bringup/config ...)`` would install there.
        """
        folders = [path.parent, *self.installed_from(path)]
        package = self.owner(path)
        if package is not None and package.source is not None \
                and path.is_relative_to(package.share):
            folders.append(package.source / path.relative_to(package.share).parent)
        names: set[str] = set()
        for folder in folders:
            try:
                with os.scandir(folder) as entries:
                    names.update(entry.name for entry in entries if entry.is_file())
            except OSError:
                continue
        return sorted(names)

    def installed_from(self, path: Path) -> list[Path]:
        """Return the source folders that may install as the folder of a missing ``path``.

        ``$(find-pkg-share pkg)/config/x.yaml`` of a package that is not built points into
        its sources, where ``config/`` may not exist: CMake installs ``bringup/config`` as
        ``share/pkg/config``. The folders below the sources ending in the same names are
        what the user can open. Remembered, as ``locate``: the message, the did-you-mean
        and the fix of one finding all ask.
        """
        if path not in self._installed_from:
            self._installed_from[path] = self._source_folders_like(path)
        return self._installed_from[path]

    def _source_folders_like(self, path: Path) -> list[Path]:
        package = self.owner(path)
        if package is None or package.source is None or path.parent.exists() \
                or not path.is_relative_to(package.share) \
                or _installed_layout(package.source / "package.xml", package.name):
            return []
        wanted = path.relative_to(package.share).parent.parts
        if not wanted:
            return []
        found = []
        for current, dirs, _files in os.walk(package.source):
            dirs[:] = sorted(d for d in dirs if d not in SKIP_DIRS and not d.startswith("."))
            folder = Path(current)
            if folder.parts[-len(wanted):] == wanted and folder != package.source:
                found.append(folder)
            if len(found) > 5:
                break
        return found

    def installed_name(self, path: Path) -> str | None:
        """Return ``share/<package>/<relative>``: the name ros2 launch would open.

        For a path into the sources of a package that is not built, where the sources
        stand for its share folder; ``None`` otherwise.
        """
        package = self.owner(path)
        if package is None or package.installed or package.source is None \
                or not path.is_relative_to(package.source) \
                or _installed_layout(package.source / "package.xml", package.name):
            return None  # an installed copy scanned as sources is what ros2 launch opens
        return f"share/{package.name}/{path.relative_to(package.source).as_posix()}"


def _python_package_folders(folder: Path) -> list[str]:
    """Return the names of a package folder's subfolders that are Python packages."""
    try:
        with os.scandir(folder) as entries:
            return [entry.name for entry in entries if entry.is_dir(follow_symlinks=False)
                    and os.path.isfile(os.path.join(entry.path, "__init__.py"))]  # noqa: PTH113, PTH118
    except OSError:
        return []


def _setup_installs(folder: Path, module: str) -> bool:
    """Return whether an ament_python package's build installs the package it holds.

    ``find_packages()`` of its ``setup.py`` (or ``setup.cfg``) finds the Python packages
    beside it.
    """
    return (folder / module / "__init__.py").is_file() and (
        (folder / "setup.py").is_file() or (folder / "setup.cfg").is_file())


_BUILD_TYPE = re.compile(rb"<build_type>\s*ament_(cmake|python)")


def _build_type(folder: Path) -> str | None:
    """Return ``cmake`` or ``python`` as a package's manifest declares its build, if it does.

    A package declaring neither is read both ways (colcon guesses; so may the user).
    """
    try:
        data = read_file(folder / "package.xml", prefix=200_000)
    except OSError:
        return None
    match = _BUILD_TYPE.search(data)
    return match.group(1).decode() if match else None


# Words without which a CMakeLists.txt installs no Python (the many C++ packages of a
# workspace are not parsed for it).
_PYTHON_INSTALL_WORDS = re.compile(
    rb"ament_python_install|PYTHON_INSTALL_DIR|site-packages|dist-packages|add_subdirectory",
    re.IGNORECASE)


def _may_install_python(cmake: Path) -> bool:
    """Return whether a ``CMakeLists.txt`` can install Python modules at all (cheap)."""
    try:
        data = read_file(cmake, prefix=MAX_CMAKE_BYTES + 1)
    except OSError:
        return False
    return _PYTHON_INSTALL_WORDS.search(data) is not None


def _installed_layout(path: Path, package: str) -> bool:
    """Return whether a path lies in a package's install layout (``share/<package>/``)."""
    return any(parent.name == package and parent.parent.name == "share"
               for parent in path.parents)


def _same_bytes(first: Path, second: Path) -> bool:
    """Return whether two files hold the same bytes (``False`` if either is unreadable)."""
    try:
        return (first.stat().st_size == second.stat().st_size
                and read_file(first) == read_file(second))
    except OSError:
        return False


def _files_by_name(source: Path) -> dict[str, list[Path]]:
    """Return a package's files by name, as a walk of its source finds them."""
    out: dict[str, list[Path]] = {}
    for current, dirs, files in os.walk(source):
        dirs[:] = [d for d in dirs if d not in SKIP_DIRS and not d.startswith(".")]
        for name in files:
            out.setdefault(name, []).append(Path(current) / name)
    return out


def _by_name(found: list[Path], relative: Path) -> Path | None:
    """Pick the file for ``relative`` among those of its name: the longest matching suffix."""
    matches = found[:51]  # (a name found everywhere says little more past that)
    if not matches:
        return None

    def shared_suffix(candidate: Path) -> int:
        count = 0
        for mine, theirs in zip(reversed(candidate.parts), reversed(relative.parts), strict=False):
            if mine != theirs:
                break
            count += 1
        return count

    matches.sort(key=lambda m: (-shared_suffix(m), len(m.parts), str(m)))
    return matches[0]


COLCON_MARKERS = ("build", "install", "log", "colcon.meta", ".colcon")


@dataclass(frozen=True, slots=True)
class Workspace:
    """The workspace of a check: the folder packages are found in, and why it was chosen.

    ``note``: a choice the user may not expect, said on standard error.
    """

    folder: Path
    how: str
    note: str = ""


def colcon_marker(folder: Path) -> str | None:
    """Return the colcon marker that makes ``folder`` a workspace root, if one does.

    A colcon workspace holds ``src/`` and what colcon leaves beside it (``build/``,
    ``install/``, ``log/``, ``colcon.meta``, ``.colcon``); a package (its own
    ``package.xml``: a C++ package with ``src/`` and an in-source ``build/``) is none.
    """
    try:
        if not (folder / "src").is_dir() or (folder / "package.xml").is_file():
            return None
        return next((m for m in COLCON_MARKERS if (folder / m).exists()), None)
    except OSError:
        return None


def colcon_root(folder: Path) -> tuple[Path, str] | None:
    """Return the colcon workspace at or above ``folder`` and its marker, if any.

    The nearest, unless it lies in a farther one's ``src/``: a repository cloned there
    (``vcs import``) that looks like a workspace itself is one of its sources.
    """
    found = [(c, m) for c in (folder, *folder.parents) if (m := colcon_marker(c))]
    if not found:
        return None
    chosen = found[0]
    for other in found[1:]:
        if chosen[0].is_relative_to(other[0] / "src"):
            chosen = other
    return chosen


def _colcon_how(marker: str) -> str:
    """Return why a colcon workspace is one: ``colcon workspace: src/ and log/``."""
    return f"colcon workspace: src/ and {marker}{'' if marker == 'colcon.meta' else '/'}"


def _own_root(folder: Path) -> tuple[Path, str]:
    """Return the workspace of one folder alone, and why: colcon, git, or its packages."""
    colcon = colcon_root(folder)
    if colcon is not None:
        return colcon[0], _colcon_how(colcon[1])
    outermost_package: Path | None = None
    for candidate in (folder, *folder.parents):
        if (candidate / ".git").exists():
            return candidate, "git root"
        if (candidate / "package.xml").is_file():
            outermost_package = candidate
    if outermost_package is not None:
        return outermost_package.parent, "the folder above the outermost package"
    return folder, "the folder checked"


def sensible_workspace(folder: Path) -> bool:
    """Return whether a folder is one a user would call a workspace when paths share it.

    Not the file system's root, a folder right below it (``/home``, ``/tmp``, ``/opt``),
    nor the home folder or a folder above it: walking those reads far more than asked.
    """
    if len(folder.parts) <= 2:
        return False
    with contextlib.suppress(RuntimeError, KeyError, OSError):
        home = resolved(Path.home())
        if home.is_relative_to(folder):
            return False
    return True


def discover_workspace(paths: Iterable[Path]) -> Workspace:
    """Return the one workspace of a check of ``paths``, found the way colcon lays it out.

    1. the nearest colcon workspace (``src/`` and a colcon marker) above every path;
    2. else, when the paths' own workspaces (each one's colcon workspace, git root or the
       folder above its outermost package) are one folder, that one;
    3. else the folder that holds them all, when it is a sensible one (see
       ``sensible_workspace``);
    4. else the first path's own workspace, with a note saying so.

    A repository cloned into a workspace's ``src/`` never becomes the workspace while a
    colcon workspace is above it, so every path order gives the same workspace.
    """
    folders: list[Path] = []
    for path in paths:
        real = resolved(path)
        folders.append(real if real.is_dir() else real.parent)
    folders = list(dict.fromkeys(folders)) or [resolved(Path())]
    common = Path(os.path.commonpath(folders))
    colcon = colcon_root(common)
    if colcon is not None:
        return Workspace(colcon[0], _colcon_how(colcon[1]))
    roots = dict(_own_root(folder) for folder in folders)
    if len(roots) == 1:
        (root, how), = roots.items()
        return Workspace(root, how)
    shared = Path(os.path.commonpath(list(roots)))
    if sensible_workspace(shared):
        return Workspace(shared, f"the folder holding the paths' {len(roots)} workspaces")
    first, how = next(iter(roots.items()))
    return Workspace(first, f"the first path's {how}", note=(
        f"the paths share no workspace (only {shared}): packages are searched in the first "
        f"path's {how}, {first}; --workspace DIR or --package-path DIR reads the others"))


def find_workspace(start: Path) -> Path:
    """Return the workspace of a check of ``start`` alone (``discover_workspace``)."""
    return discover_workspace([start]).folder
