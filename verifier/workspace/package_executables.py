"""Which executables a package installs, read from its install tree or its build files.

``ros2 run``/``Node(executable=...)`` look in ``<prefix>/lib/<package>/``. When the package
is installed we list that folder. Otherwise we read its sources the way colcon would build
them: ``setup.py``/``setup.cfg`` console scripts for ament_python, and for ament_cmake a
small interpreter of ``CMakeLists.txt`` that follows ``set``, functions and macros,
``foreach`` and both branches of ``if``, and collects ``add_executable`` + ``install(TARGETS
... DESTINATION lib/${PROJECT_NAME})``, ``install(PROGRAMS ...)``,
``ament_auto_add_executable`` and ``rclcpp_components_register_node(... EXECUTABLE x)``.
Anything it cannot follow (an ``include``, a subdirectory, a name it cannot expand) makes
the answer incomplete, and an incomplete answer never produces a finding.

``build_targets`` reads the same ``CMakeLists.txt`` for the sources of each target and the
component plugins registered on libraries (for the node interfaces read from sources).
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

from launchverify.workspace.packages import Package
from launchverify.workspace.reading import read_file

MAX_CMAKE_BYTES = 512 * 1024
MAX_CALL_DEPTH = 8
# Commands that install no executable into lib/<package> (anything else we do not
# understand makes the answer incomplete).
_HARMLESS = frozenset({
    "cmake_minimum_required", "cmake_policy", "find_package", "find_path", "find_library",
    "find_program", "unset", "string", "math", "option", "message", "include_directories",
    "link_directories", "link_libraries", "add_compile_options", "add_compile_definitions",
    "add_definitions", "add_library", "set_target_properties", "set_property",
    "get_target_property", "get_filename_component", "get_property", "configure_file",
    "add_dependencies", "add_custom_target", "add_custom_command", "enable_testing",
    "add_test", "add_launch_test", "return", "break", "continue", "endfunction", "endmacro",
    "endforeach", "generate_parameter_library", "rclcpp_components_register_nodes",
    "pluginlib_export_plugin_description_file", "autoware_package",
    "autoware_ament_auto_package", "ament_auto_package", "ament_package",
    "ament_auto_find_build_dependencies", "ament_auto_add_library",
    "ament_python_install_package", "ament_target_dependencies", "ament_environment_hooks",
    "ament_index_register_resource", "ament_lint_auto_find_test_dependencies",
    "add_ros_test", "call_for_each_rmw_implementation",  # tests: nothing in lib/<package>
})
_HARMLESS_PREFIXES = ("target_", "ament_export_", "ament_add_", "ament_auto_add_gtest",
                      "ament_find_", "rosidl_", "ament_cmake_", "find_", "cuda_add_library")
_TEST_FOLDERS = frozenset({"test", "tests", "testing"})
_TARGET_COMMANDS = frozenset({"add_executable", "ament_auto_add_executable",
                              "cuda_add_executable", "add_library", "ament_auto_add_library",
                              "target_sources"})
_TARGET_KEYWORDS = frozenset({"WIN32", "MACOSX_BUNDLE", "EXCLUDE_FROM_ALL", "STATIC", "SHARED",
                              "MODULE", "OBJECT", "INTERFACE", "PRIVATE", "PUBLIC",
                              "DIRECTORY", "NO_TARGET_LINK_LIBRARIES", "IMPORTED", "ALIAS"})


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


def build_targets(source: Path, name: str) -> BuildTargets | None:
    """Return the targets a CMake package builds from its sources, or ``None``."""
    if not (source / "CMakeLists.txt").is_file():
        return None
    cmake = _CMake(name)
    for variable in ("CMAKE_CURRENT_SOURCE_DIR", "PROJECT_SOURCE_DIR", "CMAKE_SOURCE_DIR"):
        cmake.variables[variable] = str(source)
    if cmake.run(source / "CMakeLists.txt") is None and not cmake.sources:
        return None
    return BuildTargets({t: tuple(words) for t, words in cmake.sources.items()},
                        tuple(cmake.components), cmake.complete,
                        {t: tuple(words) for t, words in cmake.links.items()},
                        frozenset(cmake.targets & cmake.installed or cmake.targets),
                        dict(cmake.output_names))


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
        return _CMake(name).run(source / "CMakeLists.txt")
    return None


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


# --------------------------------------------------------------------------- ament_cmake

_COMMAND = re.compile(r"([A-Za-z_][A-Za-z0-9_]*)\s*\(")
_VARIABLE = re.compile(r"\$\{([A-Za-z0-9_.+\-]+)\}")


@dataclass
class _Function:
    params: list[str]
    body: list[tuple[str, list[str]]]


@dataclass
class _CMake:
    project: str
    variables: dict[str, str] = field(default_factory=dict)
    functions: dict[str, _Function] = field(default_factory=dict)
    targets: set[str] = field(default_factory=set)
    installed: set[str] = field(default_factory=set)
    complete: bool = True
    sources: dict[str, list[str]] = field(default_factory=dict)
    components: list[tuple[str, str, str | None]] = field(default_factory=list)
    links: dict[str, list[str]] = field(default_factory=dict)
    output_names: dict[str, str] = field(default_factory=dict)  # target -> its file's name

    def run(self, path: Path) -> Executables | None:
        text = _read(path)
        if text is None:
            return None
        self.variables["PROJECT_NAME"] = self.project
        self.execute(_commands(text), depth=0)
        if not self.installed and not self.complete:
            return None
        return Executables(frozenset(self.output_names.get(name, name)
                                     for name in self.installed), self.complete)

    def expand(self, word: str) -> str | None:
        def value(match: re.Match[str]) -> str:
            return self.variables.get(match.group(1), "\x00")

        expanded = _VARIABLE.sub(value, word)
        return None if "\x00" in expanded or "$" in expanded else expanded

    def list_items(self, word: str) -> list[str]:
        """Return a word expanded and split as a CMake list ([] and incomplete when unknown)."""
        expanded = self.expand(word)
        if expanded is None:
            self.complete = False
            return []
        return expanded.split(";")

    def execute(self, commands: list[tuple[str, list[str]]], depth: int) -> None:
        index = 0
        while index < len(commands):
            name, args = commands[index]
            index += 1
            lowered = name.lower()
            if lowered in ("function", "macro") and args:
                body, index = _block(commands, index, ("endfunction", "endmacro"))
                self.functions[args[0].lower()] = _Function(args[1:], body)
            elif lowered == "foreach" and args:
                body, index = _block(commands, index, ("endforeach",))
                self.loop(args, body, depth)
            elif lowered in ("if", "elseif", "else", "endif", "while", "endwhile"):
                continue  # both branches are read: more executables, never fewer
            else:
                self.call(lowered, args, depth)

    def loop(self, args: list[str], body: list[tuple[str, list[str]]], depth: int) -> None:
        variable, items = args[0], args[1:]
        if items[:2] == ["IN", "LISTS"]:
            items = [w for name in items[2:]
                     for w in (self.variables.get(name) or "").split(";") if w]
        elif items[:2] == ["IN", "ITEMS"]:
            items = items[2:]
        for item in items:
            for word in self.list_items(item):
                self.variables[variable] = word
                self.execute(body, depth + 1)

    def call(self, name: str, args: list[str], depth: int) -> None:
        if name == "set" and args:
            words = [self.expand(a) for a in args[1:] if a not in ("PARENT_SCOPE", "CACHE")]
            self.variables[args[0]] = ";".join(w for w in words if w is not None)
        elif name == "list" and len(args) >= 2 and args[0] == "APPEND":
            words = [self.expand(a) for a in args[2:]]
            current = self.variables.get(args[1], "")
            self.variables[args[1]] = ";".join(
                w for w in [current, *(x for x in words if x is not None)] if w)
        elif name in _TARGET_COMMANDS and args:
            self.record_sources(name, args)
            if name in ("add_library", "ament_auto_add_library", "target_sources"):
                return
            self.call_target(name, args)
        elif name == "target_link_libraries" and args:
            target = self.expand(args[0])
            if target is not None:
                self.links.setdefault(target, []).extend(
                    w for w in (self.expand(a) for a in args[1:]) if w)
        elif name == "rclcpp_components_register_nodes" and len(args) > 1:
            target = self.expand(args[0])
            for plugin in args[1:]:
                if target is not None and plugin != "NO_TARGET_LINK_LIBRARIES":
                    self.components.append((target, plugin, None))
        elif name == "project" and args:
            self.variables["PROJECT_NAME"] = self.expand(args[0]) or self.project
        elif name == "cmake_parse_arguments" and len(args) >= 4:
            self.parse_arguments(args)
        else:
            self.call_rest(name, args, depth)

    def parse_arguments(self, args: list[str]) -> None:
        """``cmake_parse_arguments``: a function's keyword arguments as ``PREFIX_KEYWORD``.

        ``create_demo_library(plugin exe FILES a.cpp DEPENDENCIES ...)`` in ros2/demos reads
        its sources from ``${ARG_FILES}``.
        """
        if args[0] == "PARSE_ARGV" and len(args) >= 6:
            try:
                skip = int(args[1])
            except ValueError:
                self.complete = False
                return
            prefix, keywords = args[2], args[3:6]
            given = (self.variables.get("ARGV") or "").split(";")[skip:]
        else:
            prefix, keywords = args[0], args[1:4]
            given = [w for a in args[4:] for w in (self.expand(a) or "").split(";")]
        options, single, multiple = (set(filter(None, (self.expand(k) or "").split(";")))
                                     for k in keywords)
        values: dict[str, list[str]] = {}
        current: str | None = None
        for word in given:
            if word in options:
                values[word], current = ["TRUE"], None
            elif word in single or word in multiple:
                values[word], current = [], word
            elif current is not None:
                values[current].append(word)
                if current in single:
                    current = None
        for keyword in options | single | multiple:
            default = "FALSE" if keyword in options else ""
            self.variables[f"{prefix}_{keyword}"] = ";".join(values.get(keyword, [default]))

    def call_target(self, name: str, args: list[str]) -> None:
        """``add_executable`` and its variants: a target that may be installed."""
        if name in ("add_executable", "ament_auto_add_executable", "cuda_add_executable"):
            target = self.expand(args[0]) if args else None
            if target is None:
                self.complete = False
            else:
                self.targets.add(target)
                if name == "ament_auto_add_executable":
                    self.installed.add(target)

    def call_rest(self, name: str, args: list[str], depth: int) -> None:
        """Every other command: installs, user functions and macros, components."""
        if name == "install":
            self.install(args)
        elif name in self.functions:
            if depth < MAX_CALL_DEPTH:
                self.invoke(self.functions[name], args, depth)
            else:
                self.complete = False
        elif "EXECUTABLE" in args:  # rclcpp_components_register_node and its wrappers
            self.register(args)
        elif name in ("set_target_properties", "set_property"):
            self.properties(name, args)
        elif name == "add_subdirectory" and args and Path(args[0]).name in _TEST_FOLDERS:
            pass  # tests install no executables into lib/<package>
        elif name.endswith("_package") and not args:
            pass  # a project's setup macro (nav2_package()): compiler flags, no targets
        elif name not in _HARMLESS and not name.startswith(_HARMLESS_PREFIXES):
            self.complete = False  # include(), add_subdirectory(), unknown macros...

    def invoke(self, function: _Function, args: list[str], depth: int) -> None:
        saved = dict(self.variables)
        for index, param in enumerate(function.params):
            value = self.expand(args[index]) if index < len(args) else ""
            self.variables[param] = value if value is not None else "\x00"
        rest = [self.expand(a) or "" for a in args[len(function.params):]]
        self.variables["ARGN"] = ";".join(rest)
        self.variables["ARGV"] = ";".join(self.expand(a) or "" for a in args)
        self.execute(function.body, depth + 1)
        self.variables = saved

    def install(self, args: list[str]) -> None:
        destinations = [args[i + 1] for i, word in enumerate(args[:-1]) if word == "DESTINATION"]
        into_lib = any((self.expand(d) or "").rstrip("/") == f"lib/{self.project}"
                       for d in destinations)
        if not into_lib:
            return
        keywords = {"TARGETS", "PROGRAMS", "FILES", "DESTINATION", "RUNTIME", "LIBRARY",
                    "ARCHIVE", "EXPORT", "PERMISSIONS", "OPTIONAL", "COMPONENT"}
        kind = args[0] if args else ""
        for word in args[1:]:
            if word in keywords:
                break
            for item in self.list_items(word):
                if kind == "TARGETS" and item in self.targets:
                    self.installed.add(item)
                elif kind == "PROGRAMS":
                    self.installed.add(Path(item).name)

    def properties(self, name: str, args: list[str]) -> None:
        """Follow ``OUTPUT_NAME``: the file installed into lib/ is named by it, not the target.

        ``set_target_properties(t PROPERTIES OUTPUT_NAME x)`` and ``set_property(TARGET t
        PROPERTY OUTPUT_NAME x)`` (teleop_twist_joy installs ``teleop_node`` so).
        """
        if name == "set_target_properties":
            if "PROPERTIES" not in args:
                return
            split = args.index("PROPERTIES")
            targets, rest = args[:split], args[split + 1:]
            pairs = list(zip(rest[::2], rest[1::2], strict=False))
        else:
            if not args or args[0] != "TARGET" or "PROPERTY" not in args:
                return
            split = args.index("PROPERTY")
            targets = [word for word in args[1:split] if word not in ("APPEND", "APPEND_STRING")]
            pairs = [(args[split + 1], args[split + 2])] if len(args) > split + 2 else []
        for key, value in pairs:
            if key not in ("OUTPUT_NAME", "RUNTIME_OUTPUT_NAME"):
                continue
            renamed = self.expand(value)
            for target in targets:
                expanded = self.expand(target)
                if renamed is None or expanded is None:
                    self.complete = False
                else:
                    self.output_names[expanded] = renamed

    def register(self, args: list[str]) -> None:
        if "EXECUTABLE" in args:
            position = args.index("EXECUTABLE") + 1
            name = self.expand(args[position]) if position < len(args) else None
            if name is None:
                self.complete = False
            else:
                self.installed.add(name)
            plugin = args.index("PLUGIN") + 1 if "PLUGIN" in args else 0
            library = self.expand(args[0]) if args else None
            if plugin and plugin < len(args) and library is not None:
                expanded = self.expand(args[plugin])
                if expanded is None:
                    self.complete = False
                else:
                    self.components.append((library, expanded, name))

    def record_sources(self, name: str, args: list[str]) -> None:
        """Remember the source words of a target (keywords dropped, variables expanded)."""
        target = self.expand(args[0])
        if target is None:
            return
        words = self.sources.setdefault(target, [])
        directory = False
        for word in args[1:]:
            if word in _TARGET_KEYWORDS:
                directory = word == "DIRECTORY"
                continue
            for item in self.list_items(word):
                if item:
                    words.append(item.rstrip("/") + "/" if directory else item)


def _block(commands: list[tuple[str, list[str]]], index: int,
           ends: tuple[str, ...]) -> tuple[list[tuple[str, list[str]]], int]:
    """Return the commands up to the matching end command, and the index after it."""
    depth = 1
    starts = {"endfunction": "function", "endmacro": "macro", "endforeach": "foreach"}
    opener = {starts[e] for e in ends}
    body: list[tuple[str, list[str]]] = []
    while index < len(commands):
        name = commands[index][0].lower()
        index += 1
        if name in opener:
            depth += 1
        elif name in ends:
            depth -= 1
            if depth == 0:
                return body, index
        body.append(commands[index - 1])
    return body, index


def _commands(text: str) -> list[tuple[str, list[str]]]:
    """Split CMake code into (command, arguments); quoted arguments keep their spaces."""
    text = re.sub(r"#\[\[.*?\]\]", "", text, flags=re.S)
    text = "\n".join(line.split("#", 1)[0] if '"' not in line else line
                     for line in text.splitlines())
    out: list[tuple[str, list[str]]] = []
    position = 0
    while True:
        match = _COMMAND.search(text, position)
        if match is None:
            return out
        depth, index = 1, match.end()
        while index < len(text) and depth:
            if text[index] == "(":
                depth += 1
            elif text[index] == ")":
                depth -= 1
            index += 1
        body = text[match.end(): index - 1]
        out.append((match.group(1), re.findall(r'"[^"]*"|[^\s()]+', body)))
        out[-1] = (out[-1][0], [a.strip('"') for a in out[-1][1]])
        position = index


def _read(path: Path) -> str | None:
    try:
        data = read_file(path, prefix=MAX_CMAKE_BYTES)
    except OSError:
        return None
    return data.decode("utf-8", "replace")
