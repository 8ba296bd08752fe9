"""The Python modules an ament_cmake package's build installs, read from ``CMakeLists.txt``.

A launch file imports helpers from the workspace (``from fleet_names import robots``).
Once the workspace is built and sourced, an ament_cmake package's helpers are on
``PYTHONPATH`` when its ``CMakeLists.txt`` installed them into ``PYTHON_INSTALL_DIR``:

- ``ament_python_install_package(<name> [PACKAGE_DIR <dir>] [DESTINATION <dir>] ...)``
  installs the folder ``<dir>`` (default: ``<name>`` beside the ``CMakeLists.txt``; it
  must hold ``__init__.py``) as the package ``<name>``, whatever the folder is called.
  ``VERSION``, ``SETUP_CFG``, ``SCRIPTS_DESTINATION`` and ``SKIP_COMPILE`` change no
  import; a ``DESTINATION`` other than ``PYTHON_INSTALL_DIR`` is not on ``PYTHONPATH``.
- ``ament_python_install_module(<file.py>)`` installs one module under its file's name
  (into a package with ``DESTINATION_SUFFIX``: not followed).
- ``install(DIRECTORY <pkg>/ DESTINATION ${PYTHON_INSTALL_DIR}/<pkg>)``, ``install(DIRECTORY
  <dir> DESTINATION ${PYTHON_INSTALL_DIR})`` (with or without the trailing ``/``, as CMake
  distinguishes them) and ``install(FILES <file.py> DESTINATION ${PYTHON_INSTALL_DIR})``.

The file is run as CMake would run it, only as far as it can be sure (``cmake_reader``:
comments and quoting, ``${PROJECT_NAME}``, plain ``set()`` values, functions and macros
when called, ``foreach`` and ``add_subdirectory`` inside the package), plus
``ament_get_python_install_dir(<var>)``. A word it cannot expand (an environment
variable, a variable set by a command it does not follow, or set differently by the
branches of an ``if``) leaves that install out; a file CMake would refuse installs
nothing. What is left out stays an unknown module for the launch file, as before, never
an error. Every branch of an ``if`` is run (a module some configuration installs is the
one the user's build has).
"""

from __future__ import annotations

import fnmatch
import re
from dataclasses import dataclass
from pathlib import Path

from launchverify.workspace.cmake_reader import Reader
from launchverify.workspace.cmake_scope import PREFIX, Scope
from launchverify.workspace.cmake_words import Command
from launchverify.workspace.paths import resolved

# What ${PYTHON_INSTALL_DIR} expands to: the Python folder of the install prefix.
PYTHON_DIR = "\x01PYTHON_INSTALL_DIR\x01"
# Hard-coded Python folders some packages write instead of ${PYTHON_INSTALL_DIR}.
_LITERAL_PYTHON_DIR = re.compile(
    r"(?:lib/python3(?:\.\d+)?/site-packages|local/lib/python3(?:\.\d+)?/dist-packages"
    r"|lib/python3/dist-packages)(?=/|$)")
_INSTALL_DIRECTORY_OPTIONS = frozenset({
    "DESTINATION", "TYPE", "FILE_PERMISSIONS", "DIRECTORY_PERMISSIONS",
    "USE_SOURCE_PERMISSIONS", "OPTIONAL", "MESSAGE_NEVER", "CONFIGURATIONS", "COMPONENT",
    "EXCLUDE_FROM_ALL", "FILES_MATCHING", "PATTERN", "REGEX", "EXCLUDE", "PERMISSIONS",
    "RENAME",
})


@dataclass(frozen=True, slots=True)
class PythonModule:
    """A top-level module a build installs: a package folder (``__init__.py``) or a file."""

    name: str
    path: Path


def python_modules(package: Path) -> tuple[PythonModule, ...]:
    """Return the top-level Python modules the ``CMakeLists.txt`` of ``package`` installs.

    Only what lies inside the package's folder (its real path) counts: a ``PACKAGE_DIR``
    of ``../../elsewhere`` or ``/usr/lib/...`` is not the workspace's to import.
    """
    reader = _Installs(package, variables={"PYTHON_INSTALL_DIR": PYTHON_DIR})
    reader.read()
    return tuple(reader.found)


class _Installs(Reader):
    """The Python installs of one package's CMake files."""

    def __init__(self, folder: Path, variables: dict[str, str]) -> None:
        super().__init__(folder, variables=variables)
        self.found: list[PythonModule] = []

    def command(self, scope: Scope, command: Command) -> bool:
        handler = {
            "ament_get_python_install_dir": self.python_dir,
            "ament_python_install_package": self.install_package,
            "ament_python_install_module": self.install_module,
            "install": self.install,
        }.get(command.name)
        if handler is None:
            return False
        handler(scope, command)
        return True

    def add(self, name: str, path: Path) -> None:
        """Record a module, if it is a valid name and really inside the package."""
        if not name.isidentifier() or not resolved(path).is_relative_to(self.root):
            return
        if path.is_dir() and not (path / "__init__.py").is_file():
            return  # not a regular package (a namespace package is not followed)
        if path.is_dir() or (path.suffix == ".py" and path.is_file()):
            self.found.append(PythonModule(name, path))

    def python_dir(self, scope: Scope, command: Command) -> None:
        words = scope.words(command.arguments[:1])
        if words:
            scope.assign(words[0], PYTHON_DIR)

    def install_package(self, scope: Scope, command: Command) -> None:
        """``ament_python_install_package``: the folder becomes the package ``<name>``."""
        words = scope.words(command.arguments)
        if not words:
            return
        options = _keyword_values(words[1:], {"SKIP_COMPILE"},
                                  {"PACKAGE_DIR", "VERSION", "SETUP_CFG", "DESTINATION",
                                   "SCRIPTS_DESTINATION"})
        if options is None:
            return  # unused arguments: CMake stops with a fatal error
        name = words[0]
        below = _below_python_dir(options.get("DESTINATION") or PYTHON_DIR)
        if below != "":
            return  # a destination not on PYTHONPATH (or a package below another)
        self.add(name, scope.path(options.get("PACKAGE_DIR") or name))

    def install_module(self, scope: Scope, command: Command) -> None:
        """``ament_python_install_module``: one file, a module under its own name."""
        words = scope.words(command.arguments)
        if not words:
            return
        options = _keyword_values(words[1:], {"SKIP_COMPILE"}, {"DESTINATION_SUFFIX"})
        if options is None or options.get("DESTINATION_SUFFIX"):
            return
        path = scope.path(words[0])
        self.add(path.stem, path)

    def install(self, scope: Scope, command: Command) -> None:
        """``install(DIRECTORY|FILES ... DESTINATION <the Python folder>[/<pkg>])``."""
        words = scope.words(command.arguments)
        if not words or words[0] not in ("DIRECTORY", "FILES"):
            return
        end = next((i for i, w in enumerate(words) if i and w in _INSTALL_DIRECTORY_OPTIONS),
                   len(words))
        sources, options = words[1:end], words[end:]
        if "DESTINATION" not in options or options.index("DESTINATION") + 1 >= len(options):
            return
        below = _below_python_dir(options[options.index("DESTINATION") + 1])
        if below is None or "/" in below or not _keeps_python(options):
            return
        if words[0] == "FILES":
            self.install_files(scope, sources, below, options)
            return
        for source in sources:
            path = scope.path(source)
            if below and source.endswith("/"):
                self.add(below, path)  # its contents become <below>/
            elif not below and source.endswith("/"):
                self.install_contents(path)
            elif not below:
                self.add(path.name, path)
            # (the folder below another package: not a top-level module)

    def install_files(self, scope: Scope, sources: list[str], below: str,
                      options: list[str]) -> None:
        if below:
            return  # a file into a package's folder: not a top-level module
        rename = options[options.index("RENAME") + 1] if "RENAME" in options and \
            options.index("RENAME") + 1 < len(options) else None
        if rename is not None and len(sources) != 1:
            return  # CMake refuses RENAME with several files
        for source in sources:
            path = scope.path(source)
            installed = Path(rename) if rename is not None else path
            if installed.suffix == ".py":
                self.add(installed.stem, path)

    def install_contents(self, folder: Path) -> None:
        """A folder's contents into the Python folder: each package and module in it."""
        try:
            children = sorted(folder.iterdir())
        except OSError:
            return
        for child in children:
            if child.is_dir() and (child / "__init__.py").is_file():
                self.add(child.name, child)
            elif child.suffix == ".py" and child.is_file():
                self.add(child.stem, child)


def _keyword_values(words: list[str], options: set[str], single: set[str]
                    ) -> dict[str, str] | None:
    """Parse ``cmake_parse_arguments``-style words; ``None`` when some are left unused."""
    out: dict[str, str] = {}
    index = 0
    while index < len(words):
        word = words[index]
        if word in options:
            out[word] = "TRUE"
            index += 1
        elif word in single and index + 1 < len(words):
            out[word] = words[index + 1]
            index += 2
        else:
            return None
    return out


def _below_python_dir(destination: str) -> str | None:
    """Return where a destination is below the Python folder ('' for itself), else ``None``.

    ``${CMAKE_INSTALL_PREFIX}/${PYTHON_INSTALL_DIR}`` and a hard-coded
    ``lib/python3.X/site-packages`` count too.
    """
    text = destination.replace("\\", "/")
    text = text.removeprefix(PREFIX).lstrip("/")
    text = re.sub("/+", "/", text).rstrip("/")
    if text.startswith(PYTHON_DIR):
        rest = text[len(PYTHON_DIR):]
    elif (literal := _LITERAL_PYTHON_DIR.match(text)) is not None:
        rest = text[literal.end():]
    else:
        return None
    if rest and not rest.startswith("/"):
        return None
    rest = rest.lstrip("/")
    if "\x01" in rest or (rest and any(part in (".", "..") for part in rest.split("/"))):
        return None
    return rest


def _keeps_python(options: list[str]) -> bool:
    """Return whether an install's filters keep the Python files of what it installs.

    ``PATTERN "*.pyc" EXCLUDE`` keeps them; ``FILES_MATCHING PATTERN "*.yaml"`` or an
    exclusion that may match a ``.py`` file does not, or cannot be told apart: left out.
    """
    patterns: list[tuple[str, str, bool]] = []  # (PATTERN or REGEX, text, excluded)
    for index, word in enumerate(options):
        if word in ("PATTERN", "REGEX") and index + 1 < len(options):
            excluded = "EXCLUDE" in options[index + 2:index + 3]
            patterns.append((word, options[index + 1], excluded))
    samples = ("__init__.py", "helpers.py")

    def matches(kind: str, text: str) -> bool:
        if kind == "PATTERN":
            return any(fnmatch.fnmatchcase(sample, text) for sample in samples) or \
                text.endswith(".py")
        try:
            return any(re.search(text, sample) for sample in samples)
        except re.error:
            return True
    if any(excluded and matches(kind, text) for kind, text, excluded in patterns):
        return False
    if "FILES_MATCHING" in options:
        return any(not excluded and kind == "PATTERN" and text in ("*.py", "*")
                   for kind, text, excluded in patterns)
    return True
