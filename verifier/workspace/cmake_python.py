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

This reads the file as CMake would run it, only as far as it can be sure: comments and
quoting (``cmake_words``), ``${PROJECT_NAME}``, ``set()`` variables with plain values,
``ament_get_python_install_dir(<var>)`` and ``add_subdirectory`` inside the package.
A word it cannot expand (an environment variable, a variable set by a command it does
not follow, or set under a condition) leaves that install out; a file CMake would refuse
installs nothing. What is left out stays an unknown module for the launch file, as
before, never an error. Bodies of ``function``/``macro`` are not run; both branches of
an ``if`` are (a module some configuration installs is the one the user's build has).
"""

from __future__ import annotations

import fnmatch
import re
from dataclasses import dataclass, field
from pathlib import Path

from launchverify.workspace.cmake_words import Argument, Command, read_cmake
from launchverify.workspace.paths import resolved

MAX_SUBDIRECTORIES = 32  # add_subdirectory followed per package, in all
MAX_SUBDIRECTORY_DEPTH = 4
# What a destination expands to: the Python folder of the install prefix, and the prefix.
PYTHON_DIR = "\x01PYTHON_INSTALL_DIR\x01"
PREFIX = "\x01CMAKE_INSTALL_PREFIX\x01"
# Hard-coded Python folders some packages write instead of ${PYTHON_INSTALL_DIR}.
_LITERAL_PYTHON_DIR = re.compile(
    r"(?:lib/python3(?:\.\d+)?/site-packages|local/lib/python3(?:\.\d+)?/dist-packages"
    r"|lib/python3/dist-packages)(?=/|$)")
_VARIABLE = re.compile(r"\$\{([A-Za-z0-9_./+\-]*)\}")
_LIST_SEPARATOR = re.compile(r"(?<!\\);")
_BLOCK_OPENERS = frozenset({"if", "foreach", "while"})
_BLOCK_CLOSERS = frozenset({"endif", "endforeach", "endwhile"})
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
    reader = _Installs(resolved(package))
    reader.run(package, dict(_builtins(package)), depth=0)
    return tuple(reader.found)


def _builtins(folder: Path) -> dict[str, str]:
    """Return the variables CMake has set when it starts reading a ``CMakeLists.txt``."""
    text = str(folder)
    return {"CMAKE_CURRENT_SOURCE_DIR": text, "CMAKE_CURRENT_LIST_DIR": text,
            "PROJECT_SOURCE_DIR": text, "CMAKE_SOURCE_DIR": text,
            "CMAKE_INSTALL_PREFIX": PREFIX, "PYTHON_INSTALL_DIR": PYTHON_DIR}


@dataclass
class _Installs:
    root: Path  # the package's real folder: nothing outside it is installed from here
    found: list[PythonModule] = field(default_factory=list)
    subdirectories: int = 0

    def run(self, folder: Path, variables: dict[str, str], depth: int) -> None:
        """Read one ``CMakeLists.txt`` (the package's, or a subdirectory's in its scope)."""
        read = read_cmake(folder / "CMakeLists.txt")
        if read is None:
            return
        _Scope(self, folder, variables, depth).execute(read)

    def add(self, name: str, path: Path) -> None:
        """Record a module, if it is a valid name and really inside the package."""
        if not name.isidentifier() or not resolved(path).is_relative_to(self.root):
            return
        if path.is_dir() and not (path / "__init__.py").is_file():
            return  # not a regular package (a namespace package is not followed)
        if path.is_dir() or (path.suffix == ".py" and path.is_file()):
            self.found.append(PythonModule(name, path))


@dataclass
class _Scope:
    """One ``CMakeLists.txt`` being read, with its variables (a subdirectory has its own)."""

    installs: _Installs
    folder: Path
    variables: dict[str, str]
    depth: int
    conditional: int = 0  # inside if/foreach/while: a value set here is not certain

    def execute(self, read: list[Command]) -> None:
        index = 0
        while index < len(read):
            command = read[index]
            index += 1
            if command.name in ("function", "macro"):
                index = _after_block(read, index, command.name)  # runs only when called
            elif command.name in _BLOCK_OPENERS:
                self.conditional += 1
                if command.name == "foreach" and command.arguments:
                    self.variables.pop(command.arguments[0].text, None)
            elif command.name in _BLOCK_CLOSERS:
                self.conditional = max(0, self.conditional - 1)
            elif command.name in ("else", "elseif"):
                continue  # both branches are read
            elif command.name == "return" and not self.conditional:
                return
            else:
                self.call(command)

    def call(self, command: Command) -> None:
        name, arguments = command.name, command.arguments
        handlers = {
            "project": self.project, "set": self.set_variable, "unset": self.unset,
            "list": self.list_variable, "ament_get_python_install_dir": self.python_dir,
            "ament_python_install_package": self.install_package,
            "ament_python_install_module": self.install_module,
            "install": self.install, "add_subdirectory": self.subdirectory,
        }
        handler = handlers.get(name)
        if handler is not None:
            handler(arguments)
            return
        for argument in arguments:  # string(... OUT), file(GLOB OUT ...): values we lose
            if not argument.quoted:
                self.variables.pop(argument.text, None)

    # ------------------------------------------------------------------ words

    def words(self, arguments: tuple[Argument, ...]) -> list[str] | None:
        """Return the arguments expanded as CMake passes them, or ``None`` if one is unknown.

        An unquoted argument is a list: it becomes as many words as it has items.
        """
        out: list[str] = []
        for argument in arguments:
            expanded = argument.text if argument.bracket else self.expand(argument.text)
            if expanded is None:
                return None
            if argument.quoted:
                out.append(expanded)
            else:
                out.extend(item for item in _LIST_SEPARATOR.split(expanded) if item)
        return [word.replace("\\;", ";") for word in out]

    def expand(self, text: str) -> str | None:
        """Return ``text`` with its ``${...}`` expanded (innermost first); ``None`` if unknown.

        A variable never set here may have been set by a command not followed (a
        ``find_package``, an ``include``): unknown, not empty.
        """
        for _ in range(16):
            match = _VARIABLE.search(text)  # ${${X}}: the inner one first
            if match is None:
                break
            value = self.variables.get(match.group(1))
            if value is None:
                return None
            text = text[:match.start()] + value + text[match.end():]
        if "${" in text or "$ENV{" in text or "$CACHE{" in text or "$<" in text:
            return None
        return text

    def certain(self, variable: str, value: str | None) -> None:
        """Set a variable, or forget it when its value is unknown or set under a condition."""
        if value is None or self.conditional:
            self.variables.pop(variable, None)
        else:
            self.variables[variable] = value

    # ------------------------------------------------------------------ variables

    def project(self, arguments: tuple[Argument, ...]) -> None:
        words = self.words(arguments[:1])
        self.certain("PROJECT_NAME", words[0] if words else None)
        self.certain("PROJECT_SOURCE_DIR", str(self.folder))

    def set_variable(self, arguments: tuple[Argument, ...]) -> None:
        if not arguments:
            return
        variable = self.expand(arguments[0].text)
        if variable is None:
            return
        values = list(arguments[1:])
        if any(a.text == "PARENT_SCOPE" and not a.quoted for a in values):
            return  # the parent's variable; this scope's stays as it is
        cache = next((i for i, a in enumerate(values) if a.text == "CACHE" and not a.quoted),
                     None)
        if cache is not None:
            values = values[:cache]  # (a -D on the command line could override it)
        words = self.words(tuple(values))
        self.certain(variable, None if not words else ";".join(words))

    def unset(self, arguments: tuple[Argument, ...]) -> None:
        if arguments:
            self.variables.pop(arguments[0].text, None)

    def list_variable(self, arguments: tuple[Argument, ...]) -> None:
        words = self.words(arguments[:2])
        if not words or len(words) < 2:
            return
        operation, variable = words[0], words[1]
        current = self.variables.get(variable)
        added = self.words(arguments[2:])
        if operation == "APPEND" and current is not None and added is not None:
            self.certain(variable, ";".join(filter(None, [current, *added])))
        else:
            self.variables.pop(variable, None)

    def python_dir(self, arguments: tuple[Argument, ...]) -> None:
        words = self.words(arguments[:1])
        if words:
            self.certain(words[0], PYTHON_DIR)

    # ------------------------------------------------------------------ installs

    def install_package(self, arguments: tuple[Argument, ...]) -> None:
        """``ament_python_install_package``: the folder becomes the package ``<name>``."""
        words = self.words(arguments)
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
        self.installs.add(name, self.path(options.get("PACKAGE_DIR") or name))

    def install_module(self, arguments: tuple[Argument, ...]) -> None:
        """``ament_python_install_module``: one file, a module under its own name."""
        words = self.words(arguments)
        if not words:
            return
        options = _keyword_values(words[1:], {"SKIP_COMPILE"}, {"DESTINATION_SUFFIX"})
        if options is None or options.get("DESTINATION_SUFFIX"):
            return
        path = self.path(words[0])
        self.installs.add(path.stem, path)

    def install(self, arguments: tuple[Argument, ...]) -> None:
        """``install(DIRECTORY|FILES ... DESTINATION <the Python folder>[/<pkg>])``."""
        words = self.words(arguments)
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
            self.install_files(sources, below, options)
            return
        for source in sources:
            path = self.path(source)
            if below and source.endswith("/"):
                self.installs.add(below, path)  # its contents become <below>/
            elif not below and source.endswith("/"):
                self.install_contents(path)
            elif not below:
                self.installs.add(path.name, path)
            # (the folder below another package: not a top-level module)

    def install_files(self, sources: list[str], below: str, options: list[str]) -> None:
        if below:
            return  # a file into a package's folder: not a top-level module
        rename = options[options.index("RENAME") + 1] if "RENAME" in options and \
            options.index("RENAME") + 1 < len(options) else None
        if rename is not None and len(sources) != 1:
            return  # CMake refuses RENAME with several files
        for source in sources:
            path = self.path(source)
            installed = Path(rename) if rename is not None else path
            if installed.suffix == ".py":
                self.installs.add(installed.stem, path)

    def install_contents(self, folder: Path) -> None:
        """A folder's contents into the Python folder: each package and module in it."""
        try:
            children = sorted(folder.iterdir())
        except OSError:
            return
        for child in children:
            if child.is_dir() and (child / "__init__.py").is_file():
                self.installs.add(child.name, child)
            elif child.suffix == ".py" and child.is_file():
                self.installs.add(child.stem, child)

    def subdirectory(self, arguments: tuple[Argument, ...]) -> None:
        """Follow ``add_subdirectory(<dir>)`` inside the package, in a scope of its own."""
        words = self.words(arguments)
        installs = self.installs
        if not words or "EXCLUDE_FROM_ALL" in words[1:] or \
                self.depth >= MAX_SUBDIRECTORY_DEPTH or \
                installs.subdirectories >= MAX_SUBDIRECTORIES:
            return
        folder = self.path(words[0])
        if not resolved(folder).is_relative_to(installs.root):
            return
        installs.subdirectories += 1
        variables = dict(self.variables)
        for name in ("CMAKE_CURRENT_SOURCE_DIR", "CMAKE_CURRENT_LIST_DIR"):
            variables[name] = str(folder)
        installs.run(folder, variables, self.depth + 1)

    def path(self, word: str) -> Path:
        """Return a path as CMake takes it: relative to the current ``CMakeLists.txt``."""
        written = Path(word)
        return written if written.is_absolute() else self.folder / written


def _after_block(read: list[Command], index: int, opener: str) -> int:
    """Return the index after the ``end<opener>`` matching the block started before ``index``."""
    depth = 1
    while index < len(read):
        name = read[index].name
        index += 1
        if name == opener:
            depth += 1
        elif name == "end" + opener:
            depth -= 1
            if depth == 0:
                break
    return index


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
