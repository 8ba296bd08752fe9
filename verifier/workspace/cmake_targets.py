"""The targets an ament_cmake package builds and the executables it installs into lib/.

``ros2 run``/``Node(executable=...)`` look in ``<prefix>/lib/<package>/``. This collects,
from the package's CMake files as ``cmake_reader`` runs them, ``add_executable`` +
``install(TARGETS ... DESTINATION lib/${PROJECT_NAME})``, ``install(PROGRAMS ...)``,
``ament_auto_add_executable`` and ``rclcpp_components_register_node(... EXECUTABLE x)``,
with each target's sources, linked libraries and ``OUTPUT_NAME``. Anything it cannot
follow (an ``include``, a command it does not know, a word it cannot expand) makes the
answer incomplete, and an incomplete answer never produces a finding.
"""

from __future__ import annotations

from pathlib import Path

from launchverify.workspace.cmake_reader import Reader
from launchverify.workspace.cmake_scope import PREFIX, Scope
from launchverify.workspace.cmake_words import Command

# Commands that install no executable into lib/<package> (anything else we do not
# understand makes the answer incomplete).
_HARMLESS = frozenset({
    "cmake_minimum_required", "cmake_policy", "find_package", "find_path", "find_library",
    "find_program", "string", "math", "option", "message", "include_directories",
    "link_directories", "link_libraries", "add_compile_options", "add_compile_definitions",
    "add_definitions", "add_library", "set_target_properties", "set_property",
    "get_target_property", "get_filename_component", "get_property", "configure_file",
    "add_dependencies", "add_custom_target", "add_custom_command", "enable_testing",
    "add_test", "add_launch_test", "break", "continue", "endfunction", "endmacro",
    "endforeach", "generate_parameter_library", "rclcpp_components_register_nodes",
    "pluginlib_export_plugin_description_file", "autoware_package",
    "autoware_ament_auto_package", "ament_auto_package", "ament_package",
    "ament_auto_find_build_dependencies", "ament_auto_add_library",
    "ament_python_install_package", "ament_target_dependencies", "ament_environment_hooks",
    "ament_index_register_resource", "ament_lint_auto_find_test_dependencies",
    "add_ros_test", "call_for_each_rmw_implementation",  # tests: nothing in lib/<package>
    "set_tests_properties", "ament_generate_version_header",  # a test's; a header's
})
# CMake's own modules, which define checks and helpers and build no target of the package
_CMAKE_MODULES = frozenset({
    "CheckSymbolExists", "CheckIncludeFile", "CheckIncludeFileCXX", "CheckIncludeFiles",
    "CheckFunctionExists", "CheckLibraryExists", "CheckCSourceCompiles",
    "CheckCXXSourceCompiles", "CheckCCompilerFlag", "CheckCXXCompilerFlag",
    "CheckTypeSize", "CheckStructHasMember", "CheckLanguage", "CheckIPOSupported",
    "CMakeDependentOption", "CMakePackageConfigHelpers", "CMakeParseArguments",
    "GNUInstallDirs", "GenerateExportHeader", "CTest", "FindPackageHandleStandardArgs",
    "ProcessorCount", "TestBigEndian", "FeatureSummary",
})
_HARMLESS_PREFIXES = ("target_", "ament_export_", "ament_add_", "ament_auto_add_gtest",
                      "ament_find_", "rosidl_", "ament_cmake_", "find_", "cuda_add_library")
_TEST_FOLDERS = frozenset({"test", "tests", "testing"})
_EXECUTABLE_COMMANDS = frozenset({"add_executable", "ament_auto_add_executable",
                                  "cuda_add_executable"})
_TARGET_COMMANDS = _EXECUTABLE_COMMANDS | {"add_library", "ament_auto_add_library",
                                           "target_sources"}
_TARGET_KEYWORDS = frozenset({"WIN32", "MACOSX_BUNDLE", "EXCLUDE_FROM_ALL", "STATIC", "SHARED",
                              "MODULE", "OBJECT", "INTERFACE", "PRIVATE", "PUBLIC",
                              "DIRECTORY", "NO_TARGET_LINK_LIBRARIES", "IMPORTED", "ALIAS"})
_INSTALL_KEYWORDS = frozenset({"TARGETS", "PROGRAMS", "FILES", "DESTINATION", "RUNTIME",
                               "LIBRARY", "ARCHIVE", "EXPORT", "PERMISSIONS", "OPTIONAL",
                               "COMPONENT"})

Words = list[str | None]  # a command's words, None for each one that cannot be expanded


class CMakeTargets(Reader):
    """What one package's CMake files build and install.

    ``complete`` says whether ``installed`` is all; ``built`` whether the components are
    too; ``partial`` names the targets whose sources may be more (an unknown source word
    hides no executable, nor another target's sources). A command not understood may add
    sources only to a target it names: ``touched`` holds what such commands name, and
    ``sources_open`` says one may have named any (an unknown word, a loop or subdirectory
    not followed, a file included).
    """

    def __init__(self, source: Path, name: str) -> None:
        super().__init__(source, name)
        self.targets: set[str] = set()
        self.installed: set[str] = set()
        self.complete = True  # of the executables installed
        self.built = True  # of the components registered, when complete
        self.partial: set[str] = set()  # targets with a source word not known
        self.sources: dict[str, list[str]] = {}
        self.components: list[tuple[str, str, str | None]] = []
        self.links: dict[str, list[str]] = {}
        self.output_names: dict[str, str] = {}  # target -> its file's name
        self.touched: set[str] = set()  # words of commands not understood
        self.sources_open = False  # whether such a command may have named any target

    def unfollowed(self, command: Command) -> None:
        self.complete = False
        self.sources_open = True

    def follows(self, folder: Path) -> bool:
        return folder.name not in _TEST_FOLDERS  # tests install nothing into lib/<package>

    def command(self, scope: Scope, command: Command) -> bool:
        name, args = command.name, scope.each(command.arguments)
        if name in _TARGET_COMMANDS and args:
            self.record_sources(scope, args)
            if name in _EXECUTABLE_COMMANDS:
                self.add_executable(name, args)
        elif name == "target_link_libraries" and args:
            if args[0] is not None:
                self.links.setdefault(args[0], []).extend(w for w in args[1:] if w)
        elif name == "rclcpp_components_register_nodes" and len(args) > 1:
            self.register_nodes(args)
        elif name == "install":
            self.install(args)
        elif "EXECUTABLE" in args:  # rclcpp_components_register_node and its wrappers
            self.register(args)
        elif name in ("set_target_properties", "set_property"):
            self.properties(name, args)
        elif name.endswith("_package") and not args:
            pass  # a project's setup macro (nav2_package()): compiler flags, no targets
        else:
            if name not in _HARMLESS and not name.startswith(_HARMLESS_PREFIXES):
                self.complete = False  # include(), unknown macros...
                self.not_understood(name, args)
            return False  # (it may set a variable its arguments name)
        return True

    def not_understood(self, name: str, args: Words) -> None:
        """Note what a command not understood may have changed of the targets' sources."""
        if name == "include" and len(args) >= 1 and args[0] in _CMAKE_MODULES:
            return
        if name == "include" or any(word is None for word in args):
            self.sources_open = True
        self.touched.update(word for word in args if word)

    def record_sources(self, scope: Scope, args: Words) -> None:
        """Remember the source words of a target (keywords dropped, variables expanded).

        A word is kept relative to the package (or absolute), wherever its file says it.
        """
        target = args[0]
        if target is None:
            return
        words = self.sources.setdefault(target, [])
        directory = False
        for word in args[1:]:
            if word in _TARGET_KEYWORDS:
                directory = word == "DIRECTORY"
                continue
            if word is None:
                self.partial.add(target)
                continue
            if scope.folder != self.folder:  # a subdirectory's file: its own folder's word
                word = _from_package(self.folder, scope.path(word))
            words.append(word.rstrip("/") + "/" if directory else word)

    def add_executable(self, name: str, args: Words) -> None:
        """``add_executable`` and its variants: a target that may be installed."""
        target = args[0]
        if target is None:
            self.complete = False
            return
        self.targets.add(target)
        if name == "ament_auto_add_executable":
            self.installed.add(target)

    def register_nodes(self, args: Words) -> None:
        """``rclcpp_components_register_nodes(<library> <plugin>...)``: no executable."""
        library = args[0]
        for plugin in args[1:]:
            if plugin is None:
                self.built = False
            elif library is not None and plugin != "NO_TARGET_LINK_LIBRARIES":
                self.components.append((library, plugin, None))

    def install(self, args: Words) -> None:
        """``install(TARGETS|PROGRAMS ... DESTINATION lib/<package>)``."""
        destinations = [args[i + 1] for i, word in enumerate(args[:-1]) if word == "DESTINATION"]
        if not any(_lib_folder(d) == f"lib/{self.name}" for d in destinations if d):
            return
        kind = args[0] if args else ""
        for word in args[1:]:
            if word in _INSTALL_KEYWORDS:
                break
            if word is None or (kind == "TARGETS" and word not in self.sources
                                and word not in self.installed):
                self.complete = False  # a target of a file not read (a test folder's)
            elif kind == "TARGETS" and word in self.targets:
                self.installed.add(word)
            elif kind == "PROGRAMS":
                self.installed.add(Path(word).name)

    def properties(self, name: str, args: Words) -> None:
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
        for key, renamed in pairs:
            if key is None:
                self.complete = False
            if key not in ("OUTPUT_NAME", "RUNTIME_OUTPUT_NAME"):
                continue
            for target in targets:
                if renamed is None or target is None:
                    self.complete = False
                else:
                    self.output_names[target] = renamed

    def register(self, args: Words) -> None:
        """``rclcpp_components_register_node(<library> PLUGIN <class> EXECUTABLE <name>)``."""
        position = args.index("EXECUTABLE") + 1
        name = args[position] if position < len(args) else None
        if name is None:
            self.complete = False
        else:
            self.installed.add(name)
        plugin = args.index("PLUGIN") + 1 if "PLUGIN" in args else 0
        library = args[0]
        if plugin and plugin < len(args) and library is not None:
            written = args[plugin]
            if written is None:
                self.built = False
            else:
                self.components.append((library, written, name))


def _lib_folder(destination: str) -> str:
    """Return a destination as written relative to the install prefix (``lib/<package>``)."""
    if destination.startswith(PREFIX):
        destination = destination[len(PREFIX):].lstrip("/")
    return destination.rstrip("/")


def _from_package(folder: Path, path: Path) -> str:
    """Return a source path relative to the package's folder, else as it is."""
    try:
        return str(path.relative_to(folder))
    except ValueError:
        return str(path)
