"""One CMake reader for a package's executables, build targets and Python installs.

``cmake_reader`` runs ``CMakeLists.txt`` once, the same way for every question asked of
it. Each case here is one where the earlier readers differed (the executables' regex
reader, the Python installs' reader) and the more faithful answer was kept.
"""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from launchverify.topology.sources import package_targets
from launchverify.workspace.cmake_python import python_modules
from launchverify.workspace.package_executables import build_targets, executables
from launchverify.workspace.packages import Package

MANIFEST = ("<package format='3'><name>{name}</name><version>0.0.0</version>"
            "<description>d</description><maintainer email='a@b.c'>a</maintainer>"
            "<license>MIT</license><export><build_type>ament_cmake</build_type></export>"
            "</package>")
INSTALL_A = "add_executable(a src/a.cpp)\ninstall(TARGETS a DESTINATION lib/${PROJECT_NAME})\n"


def package(root: Path, cmake: str, files: dict[str, str] | None = None,
            name: str = "tools") -> Path:
    folder = root / name
    folder.mkdir(parents=True)
    (folder / "package.xml").write_text(MANIFEST.format(name=name))
    (folder / "CMakeLists.txt").write_text(f"project({name})\n{cmake}")
    for relative, text in (files or {}).items():
        (folder / relative).parent.mkdir(parents=True, exist_ok=True)
        (folder / relative).write_text(text)
    return folder


def provided(folder: Path, name: str = "tools") -> tuple[set[str], bool] | None:
    found = executables(Package(name, source=folder))
    return None if found is None else (set(found.names), found.complete)


def modules(folder: Path) -> set[str]:
    return {module.name for module in python_modules(folder)}


# ----------------------------------------------------------------- the words as CMake reads them

@pytest.mark.parametrize("cmake", [
    # a comment on a line holding a quote is still a comment
    'add_executable(a src/a.cpp)  # "old" install(PROGRAMS old.py DESTINATION lib/tools)\n'
    "install(TARGETS a DESTINATION lib/${PROJECT_NAME})\n",
    # a bracket comment of several lines
    "#[=[\ninstall(PROGRAMS scripts/old.py DESTINATION lib/${PROJECT_NAME})\n]=]\n"
    f"{INSTALL_A}",
    # a parenthesis inside a quoted argument closes nothing
    f'message(STATUS "done :(")\n{INSTALL_A}',
    # ${${KIND}_NODE}: the inner variable first
    "set(KIND gpu)\nset(gpu_NODE a)\nadd_executable(${${KIND}_NODE} src/a.cpp)\n"
    "install(TARGETS a DESTINATION lib/${PROJECT_NAME})\n",
], ids=["comment-after-quote", "bracket-comment", "quoted-parenthesis", "nested-variable"])
def test_words_are_read_as_cmake_reads_them(tmp_path: Path, cmake: str) -> None:
    assert provided(package(tmp_path, cmake)) == ({"a"}, True)


def test_the_folders_cmake_starts_with_are_known(tmp_path: Path) -> None:
    folder = package(tmp_path, (
        "add_executable(a src/a.cpp)\n"
        "install(TARGETS a DESTINATION ${CMAKE_INSTALL_PREFIX}/lib/${PROJECT_NAME})\n"
        "install(PROGRAMS ${CMAKE_CURRENT_SOURCE_DIR}/scripts/tool.py DESTINATION lib/tools)\n"))
    assert provided(folder) == ({"a", "tool.py"}, True)


def test_a_file_cmake_refuses_or_too_large_says_nothing(tmp_path: Path) -> None:
    unclosed = package(tmp_path / "unclosed", "add_executable(a src/a.cpp\n"
                       "install(TARGETS a DESTINATION lib/${PROJECT_NAME})\n")
    large = package(tmp_path / "large", INSTALL_A + "#" * (512 * 1024) + "\n")
    assert provided(unclosed) is None and build_targets(unclosed, "tools") is None
    assert provided(large) is None


# ----------------------------------------------------------------- variables

@pytest.mark.parametrize(("cmake", "expected"), [
    # branches that disagree leave the value unknown after them
    ("if(WITH_GPU)\n  set(NODE gpu_node)\nelse()\n  set(NODE cpu_node)\nendif()\n"
     "add_executable(${NODE} src/node.cpp)\ninstall(TARGETS ${NODE} DESTINATION lib/tools)\n",
     None),
    # an unknown word leaves its item unknown, not dropped
    ("set(NODES a ${EXTRA_NODES})\nadd_executable(a src/a.cpp)\n"
     "install(TARGETS ${NODES} DESTINATION lib/${PROJECT_NAME})\n", ({"a"}, False)),
    # the value of a CACHE variable stops at CACHE; PARENT_SCOPE sets no variable here
    ('set(NODE a CACHE STRING "the node")\nset(NODE b PARENT_SCOPE)\n'
     "add_executable(${NODE} src/a.cpp)\ninstall(TARGETS ${NODE} DESTINATION lib/tools)\n",
     ({"a"}, True)),
    # list(REMOVE_ITEM) is followed, another operation leaves the list unknown
    ("set(NODES a b c)\nlist(REMOVE_ITEM NODES b)\nforeach(n ${NODES})\n"
     "  add_executable(${n} src/${n}.cpp)\nendforeach()\n"
     "install(TARGETS ${NODES} DESTINATION lib/${PROJECT_NAME})\n", ({"a", "c"}, True)),
    ("set(NODES b a)\nlist(SORT NODES)\nforeach(n ${NODES})\n"
     "  add_executable(${n} src/${n}.cpp)\n  install(TARGETS ${n} DESTINATION lib/tools)\n"
     "endforeach()\n", None),
    # a command not followed may set the variables its arguments name
    ("set(NAME a)\nget_filename_component(NAME src/other.cpp NAME_WE)\n"
     "add_executable(${NAME} src/other.cpp)\ninstall(TARGETS ${NAME} DESTINATION lib/tools)\n",
     None),
], ids=["branches-disagree", "unknown-item", "cache-and-parent-scope", "remove-item",
        "other-list-operation", "command-output"])
def test_variables(tmp_path: Path, cmake: str, expected: tuple[set[str], bool] | None) -> None:
    assert provided(package(tmp_path, cmake)) == expected


# ----------------------------------------------------------------- control flow

@pytest.mark.parametrize(("cmake", "expected"), [
    # foreach over an unknown list, or a RANGE: not followed
    (f"{INSTALL_A}foreach(n IN LISTS EXTRA_NODES)\n  add_executable(${{n}} src/${{n}}.cpp)\n"
     "  install(TARGETS ${n} DESTINATION lib/${PROJECT_NAME})\nendforeach()\n", ({"a"}, False)),
    ("foreach(i RANGE 1)\n  add_executable(node${i} src/node.cpp)\n"
     "  install(TARGETS node${i} DESTINATION lib/${PROJECT_NAME})\nendforeach()\n", None),
    # the loop variable has its value from before the loop again after it
    ("set(n main)\nforeach(n a b)\n  add_executable(${n} src/${n}.cpp)\nendforeach()\n"
     "add_executable(${n} src/main.cpp)\n"
     "install(TARGETS a b ${n} DESTINATION lib/${PROJECT_NAME})\n", ({"a", "b", "main"}, True)),
    # a macro sets its caller's variables; a function only with PARENT_SCOPE
    ("macro(pick)\n  set(FIRST a)\nendmacro()\nfunction(choose)\n  set(SECOND b PARENT_SCOPE)\n"
     "  set(THIRD c)\nendfunction()\npick()\nchoose()\n"
     "add_executable(${FIRST} a.cpp)\nadd_executable(${SECOND} b.cpp)\n"
     "install(TARGETS ${FIRST} ${SECOND} DESTINATION lib/${PROJECT_NAME})\n",
     ({"a", "b"}, True)),
    # a function named from a variable, reading ARGV0
    ("function(${PROJECT_NAME}_node)\n  add_executable(${ARGV0} src/${ARGV0}.cpp)\n"
     "  install(TARGETS ${ARGV0} DESTINATION lib/${PROJECT_NAME})\nendfunction()\n"
     "tools_node(a)\n", ({"a"}, True)),
    # return() ends the file: what follows it is never run
    (f"{INSTALL_A}return()\ninclude(cmake/more.cmake)\n", ({"a"}, True)),
], ids=["unknown-items", "range", "loop-variable", "macro-and-function-scopes",
        "function-name", "return"])
def test_control_flow(tmp_path: Path, cmake: str,
                      expected: tuple[set[str], bool] | None) -> None:
    assert provided(package(tmp_path, cmake)) == expected


def test_a_subdirectory_is_read_with_its_sources_from_its_folder(tmp_path: Path) -> None:
    folder = package(tmp_path, "add_subdirectory(src)\nadd_subdirectory(test)\n", {
        "src/CMakeLists.txt": "add_executable(a a.cpp)\n"
                              "install(TARGETS a DESTINATION lib/${PROJECT_NAME})\n",
        "test/CMakeLists.txt": "include(never_read.cmake)\n"})
    assert provided(folder) == ({"a"}, True)
    built = build_targets(folder, "tools")
    assert built is not None and built.sources == {"a": ("src/a.cpp",)}
    (folder / "CMakeLists.txt").write_text("project(tools)\nadd_subdirectory(src)\n"
                                           "add_subdirectory(absent)\n")
    built = build_targets(folder, "tools")
    assert built is not None and not built.complete
    # a target of the test folder (not read), installed by the package's own file
    tests = package(tmp_path / "tests", "add_subdirectory(test)\n"
                    "install(TARGETS cancel DESTINATION lib/${PROJECT_NAME})\n",
                    {"test/CMakeLists.txt": "add_executable(cancel cancel.cpp)\n"})
    assert provided(tests) is None


def test_a_file_running_too_long_is_cut_short(tmp_path: Path) -> None:
    calls = " ".join(["f()"] * 10)
    folder = package(tmp_path, f"{INSTALL_A}function(f)\n  {calls}\nendfunction()\nf()\n")
    started = time.monotonic()
    assert provided(folder) == ({"a"}, False)
    assert time.monotonic() - started < 30


# ----------------------------------------------------------------- build targets

def test_an_unknown_source_word_leaves_only_its_target_partial(tmp_path: Path) -> None:
    folder = package(tmp_path, "add_executable(a ${GENERATED_SOURCES})\n"
                     "add_executable(b src/b.cpp)\n"
                     "install(TARGETS a b DESTINATION lib/${PROJECT_NAME})\n",
                     {"src/b.cpp": "int main() {}\n"})
    assert provided(folder) == ({"a", "b"}, True)  # a source hides no executable
    built = build_targets(folder, "tools")
    assert built is not None and built.complete and built.partial == {"a"}
    problems = {target.executable: target.problems
                for target in package_targets(Package("tools", source=folder))}
    assert problems["b"] == () and problems["a"]


def test_components_and_keyword_arguments_are_expanded(tmp_path: Path) -> None:
    folder = package(tmp_path, (
        "function(library name)\n"
        '  cmake_parse_arguments(ARG "" "" "FILES;DEPENDENCIES" ${ARGN})\n'
        "  add_library(${name} SHARED ${ARG_FILES})\n"
        "  target_link_libraries(${name} ${ARG_DEPENDENCIES})\n"
        "endfunction()\n"
        "add_library(core SHARED src/core.cpp)\n"
        "library(camera FILES src/camera.cpp DEPENDENCIES ${rclcpp_TARGETS} core)\n"
        'rclcpp_components_register_nodes(camera "${PROJECT_NAME}::Camera")\n'))
    built = build_targets(folder, "tools")
    assert built is not None
    assert built.sources["camera"] == ("src/camera.cpp",)
    assert built.links["camera"] == ("core",)
    assert built.components == (("camera", "tools::Camera", None),)


# ----------------------------------------------------------------- Python installs

@pytest.mark.parametrize(("cmake", "files"), [
    # a function's body runs where it is called
    ("function(install_helpers)\n  ament_python_install_package(fleet_names)\nendfunction()\n"
     "install_helpers()\n", {}),
    # foreach runs its body for each item; a list appended to in a branch keeps its items
    ("set(PACKAGES fleet_names)\nif(WITH_MAPS)\n  list(APPEND PACKAGES fleet_maps)\nendif()\n"
     "foreach(name ${PACKAGES})\n  ament_python_install_package(${name})\nendforeach()\n",
     {"fleet_maps/__init__.py": ""}),
    # a value set in a branch is known in the rest of that branch
    ("if(WITH_HELPERS)\n  set(NAME fleet_names)\n  ament_python_install_package(${NAME})\n"
     "endif()\n", {}),
    # a list the file appends to starts empty
    ("list(APPEND FOLDERS fleet_names)\n"
     "install(DIRECTORY ${FOLDERS} DESTINATION ${PYTHON_INSTALL_DIR})\n", {}),
    # a subdirectory sets its parent's variable with PARENT_SCOPE
    ("add_subdirectory(config)\nament_python_install_package(${HELPERS})\n",
     {"config/CMakeLists.txt": "set(HELPERS fleet_names PARENT_SCOPE)\n"}),
], ids=["function", "foreach-and-branch-list", "branch-value", "new-list", "parent-scope"])
def test_python_installs_follow_the_same_reader(tmp_path: Path, cmake: str,
                                                files: dict[str, str]) -> None:
    files = {"fleet_names/__init__.py": "", **files}
    expected = {"fleet_names", "fleet_maps"} if "fleet_maps" in cmake else {"fleet_names"}
    assert modules(package(tmp_path, cmake, files, name="fleet_common")) == expected
