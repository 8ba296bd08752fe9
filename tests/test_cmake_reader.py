"""One CMake reader for a package's Python installs (and, next, its executables).

``cmake_reader`` runs ``CMakeLists.txt`` once, the same way for every question asked of
it. Each case here is one where the Python installs' reader did less than CMake.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from launchverify.workspace.cmake_python import python_modules

MANIFEST = ("<package format='3'><name>{name}</name><version>0.0.0</version>"
            "<description>d</description><maintainer email='a@b.c'>a</maintainer>"
            "<license>MIT</license><export><build_type>ament_cmake</build_type></export>"
            "</package>")


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


def modules(folder: Path) -> set[str]:
    return {module.name for module in python_modules(folder)}


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
