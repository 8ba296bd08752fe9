"""Python helpers an ament_cmake package installs are imported from the sources.

``CMakeLists.txt`` says which modules a build puts into ``PYTHON_INSTALL_DIR``; a launch
file importing one gets its real values. What the file does not say for sure (a
malformed file, a folder that is absent, a word that cannot be expanded) leaves the
module unknown, as before: never an error.
"""

from __future__ import annotations

from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from launchverify.engine import CheckOptions, run_check
from launchverify.workspace.cmake_python import python_modules
from launchverify.workspace.cmake_words import commands
from launchverify.workspace.packages import PackageIndex

MANIFEST = ("<package format='3'><name>{name}</name><version>0.0.0</version>"
            "<description>d</description><maintainer email='a@b.c'>a</maintainer>"
            "<license>MIT</license><export><build_type>ament_cmake</build_type></export>"
            "</package>")
HELPER = "def robot_names():\n    return ['driver', 'mapper', 'driver']\n"
LAUNCH = """\
from launch import LaunchDescription
from launch_ros.actions import Node
from fleet_names import robot_names


def generate_launch_description():
    return LaunchDescription([
        Node(package='demo_nodes_cpp', executable='talker', name=name)
        for name in robot_names()
    ])
"""


def package(root: Path, cmake: str, files: dict[str, str], name: str = "fleet_common") -> Path:
    """Write an ament_cmake package: its manifest, its CMakeLists.txt and other files."""
    folder = root / name
    folder.mkdir(parents=True)
    (folder / "package.xml").write_text(MANIFEST.format(name=name))
    (folder / "CMakeLists.txt").write_text(cmake)
    for relative, text in files.items():
        (folder / relative).parent.mkdir(parents=True, exist_ok=True)
        (folder / relative).write_text(text)
    return folder


def installed(folder: Path) -> dict[str, str]:
    """Return each installed module's name and its path relative to the package."""
    return {m.name: m.path.relative_to(folder).as_posix() for m in python_modules(folder)}


# ----------------------------------------------------------------- what CMakeLists.txt says

def test_install_package_default_folder_is_the_name_beside_cmakelists(tmp_path: Path) -> None:
    folder = package(tmp_path, "project(fleet_common)\n"
                     "ament_python_install_package(${PROJECT_NAME}_names)\n",
                     {"fleet_common_names/__init__.py": ""})
    assert installed(folder) == {"fleet_common_names": "fleet_common_names"}


def test_install_package_dir_installs_the_folder_under_the_given_name(tmp_path: Path) -> None:
    cmake = """
cmake_minimum_required(VERSION 3.8)
project(fleet_common)  # ament_python_install_package(commented_out)
#[[ ament_python_install_package(bracket_comment) ]]
set(HELPERS "python/${PROJECT_NAME}")
ament_python_install_package(fleet_names
  PACKAGE_DIR "${HELPERS}"   # the folder's name is not the module's
  VERSION 1.2.3 SETUP_CFG setup.cfg SCRIPTS_DESTINATION lib/${PROJECT_NAME} SKIP_COMPILE)
"""
    folder = package(tmp_path, cmake, {"python/fleet_common/__init__.py": ""})
    assert installed(folder) == {"fleet_names": "python/fleet_common"}


def test_install_directory_into_the_python_folder(tmp_path: Path) -> None:
    cmake = """
project(fleet_common)
ament_get_python_install_dir(PY_DIR)
install(DIRECTORY src/fleet_names/ DESTINATION ${PYTHON_INSTALL_DIR}/fleet_names
        PATTERN "*.pyc" EXCLUDE PATTERN __pycache__ EXCLUDE)
install(DIRECTORY tools DESTINATION "${CMAKE_INSTALL_PREFIX}/${PY_DIR}")
install(DIRECTORY lib/ DESTINATION lib/python3.12/site-packages/)
install(DIRECTORY config/ DESTINATION ${PYTHON_INSTALL_DIR} FILES_MATCHING PATTERN "*.yaml")
install(DIRECTORY share/ DESTINATION share/${PROJECT_NAME})
"""
    files = {"src/fleet_names/__init__.py": "", "tools/__init__.py": "",
             "lib/fleet_topics.py": "", "lib/fleet_maps/__init__.py": "",
             "lib/not_a_package/data.txt": "", "config/config_module.py": "",
             "share/shared.py": ""}
    folder = package(tmp_path, cmake, files)
    assert installed(folder) == {"fleet_names": "src/fleet_names", "tools": "tools",
                                 "fleet_maps": "lib/fleet_maps",
                                 "fleet_topics": "lib/fleet_topics.py"}


def test_install_module_and_files(tmp_path: Path) -> None:
    cmake = """
project(fleet_common)
find_package(ament_cmake_python REQUIRED)
ament_python_install_module(scripts/fleet_topics.py)
ament_python_install_module(scripts/nested.py DESTINATION_SUFFIX fleet_names)
install(FILES scripts/renamed.py DESTINATION ${PYTHON_INSTALL_DIR} RENAME fleet_maps.py)
"""
    files = {"scripts/fleet_topics.py": "", "scripts/nested.py": "", "scripts/renamed.py": ""}
    folder = package(tmp_path, cmake, files)
    assert installed(folder) == {"fleet_topics": "scripts/fleet_topics.py",
                                 "fleet_maps": "scripts/renamed.py"}


def test_a_subdirectory_installs_relative_to_its_own_folder(tmp_path: Path) -> None:
    cmake = "project(fleet_common)\nset(NAME fleet_names)\nadd_subdirectory(python)\n"
    files = {"python/CMakeLists.txt": "ament_python_install_package(${NAME})\n",
             "python/fleet_names/__init__.py": ""}
    folder = package(tmp_path, cmake, files)
    assert installed(folder) == {"fleet_names": "python/fleet_names"}


@pytest.mark.parametrize("cmake", [
    "ament_python_install_package(fleet_names",  # never closed: CMake stops
    'ament_python_install_package("fleet_names)\n',
    "project(a) garbage ament_python_install_package(fleet_names)\n",
    "ament_python_install_package(fleet_names) #[[ never closed\n",
    "ament_python_install_package(fleet_names PACKAGE_DIR)\n",  # a keyword without value
    "ament_python_install_package(fleet_names UNKNOWN_KEYWORD x)\n",
    "ament_python_install_package(fleet_names DESTINATION lib/elsewhere)\n",
    "ament_python_install_package($ENV{HELPERS})\n",
    "ament_python_install_package(${NEVER_SET})\n",
    "if(X)\n  set(N fleet_names)\nendif()\nament_python_install_package(${N})\n",
    "function(f)\n  ament_python_install_package(fleet_names)\nendfunction()\n",
    "ament_python_install_package(fleet_names PACKAGE_DIR ../../outside/fleet_names)\n",
    "ament_python_install_package(other_name)\n",  # its folder is absent
])
def test_what_is_not_certain_installs_nothing(tmp_path: Path, cmake: str) -> None:
    (tmp_path / "outside" / "fleet_names").mkdir(parents=True)
    (tmp_path / "outside" / "fleet_names" / "__init__.py").write_text("")
    folder = package(tmp_path / "ws", cmake, {"fleet_names/__init__.py": ""})
    assert installed(folder) == {}


def test_a_subdirectory_that_adds_itself_ends(tmp_path: Path) -> None:
    cmake = "add_subdirectory(.)\nadd_subdirectory(${CMAKE_CURRENT_SOURCE_DIR}/../..)\n" \
            "ament_python_install_package(fleet_names)\n"
    folder = package(tmp_path, cmake, {"fleet_names/__init__.py": ""})
    assert installed(folder) == {"fleet_names": "fleet_names"}


@settings(max_examples=150, deadline=None)
@given(st.text(alphabet='ament_python_install_package( )"#[]=${}\\;\n/PACKAGE_DIR',
               max_size=120))
def test_any_text_is_read_without_a_crash(text: str) -> None:
    commands(text)  # a command list or None, never an exception


def test_a_name_two_packages_install_differently_stays_unknown(tmp_path: Path) -> None:
    cmake = "ament_python_install_package(fleet_names)\n"
    package(tmp_path, cmake, {"fleet_names/__init__.py": ""}, name="first")
    package(tmp_path, cmake, {"fleet_names/__init__.py": ""}, name="second")
    assert PackageIndex([tmp_path]).python_sources("fleet_names") == []
    assert PackageIndex([tmp_path / "first"]).python_sources("fleet_names") == [
        (tmp_path / "first" / "fleet_names").resolve()]


# ----------------------------------------------------------------- what the launch file gets

def check(root: Path) -> list[tuple[str, str]]:
    launch = root / "fleet_bringup" / "launch" / "fleet.launch.py"
    launch.parent.mkdir(parents=True)
    (root / "fleet_bringup" / "package.xml").write_text(MANIFEST.format(name="fleet_bringup"))
    launch.write_text(LAUNCH)
    report = run_check(CheckOptions(paths=[launch], workspace=root))
    return [(f.code, f.message) for f in report.findings]


@pytest.mark.parametrize(("cmake", "files"), [
    ("project(fleet_common)\nament_python_install_package(fleet_names PACKAGE_DIR src/names)\n",
     {"src/names/__init__.py": HELPER}),
    ("install(DIRECTORY python/ DESTINATION ${PYTHON_INSTALL_DIR})\n",
     {"python/fleet_names/__init__.py": HELPER}),
    ("ament_python_install_module(fleet_names.py)\n", {"fleet_names.py": HELPER}),
])
def test_the_helper_runs_and_its_duplicate_is_found(tmp_path: Path, cmake: str,
                                                     files: dict[str, str]) -> None:
    package(tmp_path, cmake, files)
    codes = [code for code, _ in check(tmp_path)]
    assert codes.count("LV101") == 1 and "LV002" not in codes


@pytest.mark.parametrize(("cmake", "files"), [
    ("ament_python_install_package(fleet_names PACKAGE_DIR src/names\n",  # malformed
     {"src/names/__init__.py": HELPER}),
    ("ament_python_install_package(fleet_names PACKAGE_DIR src/names)\n", {}),  # absent
])
def test_a_helper_not_certainly_installed_stays_unknown(tmp_path: Path, cmake: str,
                                                        files: dict[str, str]) -> None:
    package(tmp_path, cmake, files)
    found = check(tmp_path)
    assert [code for code, _ in found] == ["LV003"]
    assert "'fleet_names' is not modelled and not installed" in found[0][1]
