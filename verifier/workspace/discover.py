"""Find the launch files below the paths a user gives."""

from __future__ import annotations

import os
import re
from collections.abc import Callable, Iterator
from pathlib import Path

from launchverify.workspace.packages import listing
from launchverify.workspace.reading import read_file

LAUNCH_SUFFIXES = ("launch.xml", "launch.yaml", "launch.yml")
PYTHON_SUFFIX = "launch.py"
FRONTEND_SUFFIXES = (".xml", ".yaml", ".yml")
_XML_ROOT = re.compile(rb"<launch[\s>/]")
_YAML_ROOT = re.compile(rb"^launch\s*:", re.MULTILINE)
# What ros2 launch runs: a generate_launch_description function (any spelling close to it,
# so a misspelt one in a file named for launch is checked and reported) or a name bound to one.
_PYTHON_ENTRY = re.compile(
    rb"^\s*(def\s+generate_launch_description\w*\s*\(|generate_launch_description\s*=)",
    re.MULTILINE)
# A .py file not named for launch counts only with the function at module level, exactly
# spelt: a test that nests one, or a helper whose docstring shows one, is not a launch file.
_MODULE_ENTRY = re.compile(
    rb"^(def\s+generate_launch_description\s*\(|generate_launch_description\s*=)",
    re.MULTILINE)


def is_launch_file(path: Path) -> bool:
    """Return whether a file looks like a launch file.

    Names ending in ``launch.xml``/``launch.yaml`` count; ``*launch.py`` files, and any
    ``.py`` file in a ``launch`` folder (``launch/include/control.py``,
    ``bringup_launch_distributed.py``), count when they define
    ``generate_launch_description`` (what ``ros2 launch`` runs, whatever the file's name;
    outside ``*launch.py`` only a module-level definition counts, and launch tests are
    left to ``launch_test``); other ``.xml``/``.yaml`` files count when
    they sit in a ``launch`` folder and their root is ``launch``. A ``.launch`` file (a
    roslaunch name) counts when it is XML with a ``launch`` root and ROS 2's spelling
    (``$(var)``, ``$(find-pkg-share)``, ``<node exec=>``, ``<let>``...): ROS 1 files stay
    out of a folder's walk.
    """
    return _looks_like_launch(os.fspath(path))


def _looks_like_launch(path: str) -> bool:
    """``is_launch_file`` on a path string (a walk over every file makes no Path)."""
    folder, _, name = path.rpartition(os.sep)
    lowered = name.lower()
    if lowered.endswith(LAUNCH_SUFFIXES):
        return True
    if lowered.endswith(PYTHON_SUFFIX):
        return _PYTHON_ENTRY.search(_head(path, 256 * 1024)) is not None
    if lowered.endswith(ROS1_SUFFIX):  # roslaunch's name: ROS 2 only by what it says
        head = _head(path, 256 * 1024)
        return _XML_ROOT.search(head[:8192]) is not None and \
            _ROS2_SPELLING.search(head) is not None
    if lowered.endswith(".py") and _in_launch_folder(folder):
        return _MODULE_ENTRY.search(_head(path, 256 * 1024)) is not None
    if not lowered.endswith(FRONTEND_SUFFIXES) or "launch" not in _name(folder).lower():
        return False
    pattern = _XML_ROOT if lowered.endswith(".xml") else _YAML_ROOT
    return pattern.search(_head(path, 8192)) is not None


# A parameter file, as rcl reads one: node keys over ``ros__parameters`` blocks.
_PARAMETERS = re.compile(rb"^\s*ros__parameters\s*:", re.MULTILINE)
# A file named otherwise is sniffed as ros2 launch reads any file: a launch file when it
# begins with its root (comments, an XML declaration or a YAML document start before it).
_STARTS_AS_LAUNCH = re.compile(
    rb"(?:\s|<\?xml[^>]*\?>|<!--.*?-->|#[^\n]*|---)*(?:<launch[\s>/]|launch\s*:)", re.DOTALL)
ROS1_SUFFIX = ".launch"  # roslaunch's files: checked to say so (LV003)
# What only ROS 2 writes in XML: a ``.launch`` file (roslaunch's name) with one of these
# is a ROS 2 launch file named the old way (ros_deep_learning's ``*.ros2.launch``).
_ROS2_SPELLING = re.compile(
    rb"\$\((?:var|find-pkg-share|find-pkg-prefix|exec-in-pkg)\s|<node\b[^>]*\sexec\s*="
    rb"|<(?:let|set_parameter|set-parameter|executable|push_ros_namespace|"
    rb"push-ros-namespace|node_container|node-container)\b")
WHAT_IS_READ = ("launchverify reads launch files (*.launch.py, *.launch.xml, *.launch.yaml; "
                "a .py file defining generate_launch_description, an .xml or .yaml file whose "
                "root is launch) and parameter files (.yaml with ros__parameters)")


def named_kind(path: Path) -> str | None:
    """Return what a file given by name is to a check: ``launch``, ``parameters`` or None.

    Looser than a folder's walk (``is_launch_file``), as ``ros2 launch FILE`` is: any file
    named for launch, a ``.py`` file defining ``generate_launch_description`` wherever it
    is, an ``.xml``/``.yaml`` file whose root is ``launch``. A ``.yaml`` file with
    ``ros__parameters`` is a parameter file, checked through the launch files that load
    it. A file of any other name is a launch file when it begins with the root ``<launch>``
    or ``launch:``. Anything else (a README, C++ source, a URDF) is not for ``check`` to
    read as a launch file.
    """
    lowered = path.name.lower()
    if lowered.endswith((*LAUNCH_SUFFIXES, PYTHON_SUFFIX, ROS1_SUFFIX)):
        return "launch"
    if lowered.endswith(".py"):
        return "launch" if _PYTHON_ENTRY.search(_head(str(path), 256 * 1024)) else None
    if lowered.endswith(".xml"):
        return "launch" if _XML_ROOT.search(_head(str(path), 8192)) else None
    if lowered.endswith((".yaml", ".yml")):
        head = _head(str(path), 256 * 1024)
        if _YAML_ROOT.search(head):
            return "launch"
        return "parameters" if _PARAMETERS.search(head) else None
    return "launch" if _STARTS_AS_LAUNCH.match(_head(str(path), 8192)) else None


# A folder named for launch files: ``launch``, ``launches``, ``bringup_launch``,
# ``launch-files``; not a word that merely begins so (a clone named ``launchverify``)
_LAUNCH_FOLDER = re.compile(r"(?:^|[^a-z0-9])launch(?:es)?(?:$|[^a-z0-9])")


def _in_launch_folder(folder: str) -> bool:
    """Return whether a folder is (or is just below) one named for launch files."""
    parent, _, own = folder.rpartition(os.sep)
    return any(_LAUNCH_FOLDER.search(name.lower()) for name in (own, _name(parent)))


def _name(folder: str) -> str:
    return folder.rpartition(os.sep)[2]


def _head(path: str, size: int) -> bytes:
    try:
        return read_file(path, prefix=size)
    except OSError:
        return b""  # a FIFO, a device, unreadable: the loader says why


def _files(top: str) -> Iterator[str]:
    """Yield each file below ``top`` (path strings), in ``os.walk``'s order.

    Sorted, depth first; linked folders and skipped ones (build output, dot folders) are
    not entered, unreadable ones are passed over.
    """
    pending = [top]
    while pending:
        listed = listing(pending.pop(), links=False)
        if listed is None:
            continue
        folders, files = listed
        yield from sorted(entry.path for entry in files)
        pending.extend(reversed(folders))


def _real_names(top: str) -> Callable[[str], str]:
    """Return how to name a file walked from ``top`` by its folders' real names.

    A folder is judged by its name (``launch/x.py``): walking ``.`` from inside a
    ``launch`` folder must judge its files as walking ``launch`` from above does.
    """
    if Path(top).is_absolute():
        return lambda file: file
    real = os.path.normpath(Path(top).absolute())  # (names as given: no link followed)
    return lambda file: real + os.sep + file[len(top):].lstrip(os.sep)


def discover(paths: list[Path], *, filter_files: bool = False) -> list[Path]:
    """Return the launch files named by ``paths``: files as given, folders searched.

    ``filter_files`` applies the folder test to given files too (pre-commit passes every
    changed file whose name matches, launch tests included).
    """
    found: list[Path] = []
    for path in paths:
        if path.is_dir():
            top = str(path)
            named = _real_names(top)
            found.extend(Path(file) for file in _files(top) if _looks_like_launch(named(file)))
        elif not filter_files or is_launch_file(path):
            found.append(path)
    unique: dict[Path, Path] = {}
    for path in found:
        unique.setdefault(path.absolute(), path)
    return list(unique.values())
