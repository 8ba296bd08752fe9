"""Which ros2_control controller types exist: the ones a plugin description exports.

A controller manager loads a controller by its type (``diff_drive_controller/
DiffDriveController``) through pluginlib: the name of a ``<class>`` in a plugin
description that some package exports for ``controller_interface``
(``pluginlib_export_plugin_description_file(controller_interface <file>)``, which the
ament index lists). A type nothing exports makes the manager refuse the controller
(``Loader for controller '<name>' (type '<type>') not found``).

``ControllerTypes.missing`` says when that is a fact. The type's package (its part before
``/``) must be a workspace package whose CMake files and plugin descriptions were all read,
a released package whose models (``topology.shipped``) list every type its release exports
for the checked distribution (for any distribution: none of the releases does), or a
package that is gone (``RENAMED``). Anything else is not known, and never missing: a
vendor's package, a package whose CMake files are not all followed, a type that a
description of any package of the workspace or of an install prefix exports (under another
package's name too: gripper_controllers exports ``position_controllers/
GripperActionController``).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

from launchverify.models.distros import DISTROS
from launchverify.rule import Applicability
from launchverify.suggest import closest, sole_typo
from launchverify.topology.releases import MODEL_DISTROS
from launchverify.topology.shipped import released_model, shipped_packages
from launchverify.topology.sources import controller_classes
from launchverify.workspace.cmake_reader import Reader
from launchverify.workspace.cmake_scope import Scope
from launchverify.workspace.cmake_words import Command
from launchverify.workspace.packages import Package, PackageIndex, workspace_prefixes
from launchverify.workspace.reading import Unreadable, read_text

# Every ROS 2 distribution in order, those no check is made for included (when a type
# left the releases)
ORDER = ("foxy", "galactic", "humble", "iron", "jazzy", "kilted", "lyrical", "rolling")
EXPORT = "pluginlib_export_plugin_description_file"
BASE_PACKAGE = "controller_interface"  # the base class package controllers are exported for
# Where the ament index lists the descriptions exported for controller_interface
RESOURCE = "share/ament_index/resource_index/controller_interface__pluginlib__plugin"
MAX_RESOURCES = 2000


@dataclass(frozen=True, slots=True)
class Renamed:
    """A controller type that left ros2_controllers, and what replaces it.

    ``gone``: the first distribution without it; ``settled``: the change that removed it;
    ``fix``: how safe replacing the text alone is (``None``: it is not enough).
    """

    new: str
    gone: str
    settled: str
    fix: Applicability | None
    also: str = ""  # what else the replacement needs

    def gone_by(self, distro: str | None) -> bool:
        """Return whether the type is gone in ``distro`` (``None``: in every one checked)."""
        first = distro if distro is not None and distro in ORDER else DISTROS[0]
        return ORDER.index(first) >= ORDER.index(self.gone)


_GRIPPER = ("ros2_controllers#1652 removed gripper_controllers (migration guide, Jazzy to "
            "Kilted)")
_GROUPS = ("ros2_controllers#1913 deprecated it and #2016 removed it after kilted "
           "(migration guide, Kilted to Lyrical)")
# Controller types that ros2_controllers renamed or removed, from its history and
# migration guides
RENAMED: dict[str, Renamed] = {
    "joint_state_controller/JointStateController": Renamed(
        "joint_state_broadcaster/JointStateBroadcaster", "galactic",
        "ros2_controllers#160 renamed joint_state_controller, #230 removed it",
        Applicability.SAFE),
    "position_controllers/GripperActionController": Renamed(
        "parallel_gripper_action_controller/GripperActionController", "kilted", _GRIPPER,
        Applicability.UNSAFE, "; its action is control_msgs/action/ParallelGripperCommand"),
    "effort_controllers/GripperActionController": Renamed(
        "parallel_gripper_action_controller/GripperActionController", "kilted", _GRIPPER,
        None, "; it commands position, limiting effort with max_effort; its action is "
        "control_msgs/action/ParallelGripperCommand"),
    "position_controllers/JointGroupPositionController": Renamed(
        "forward_command_controller/ForwardCommandController", "lyrical", _GROUPS, None,
        " with interface_name: position"),
    "velocity_controllers/JointGroupVelocityController": Renamed(
        "forward_command_controller/ForwardCommandController", "lyrical", _GROUPS, None,
        " with interface_name: velocity"),
    "effort_controllers/JointGroupEffortController": Renamed(
        "forward_command_controller/ForwardCommandController", "lyrical", _GROUPS, None,
        " with interface_name: effort"),
}


@dataclass(frozen=True, slots=True)
class Missing:
    """Why nothing exports a type, the type probably meant, and how safe replacing it is."""

    why: str
    meant: str | None = None
    fix: Applicability | None = None
    named: bool = False  # ``why`` names ``meant`` already


@dataclass(frozen=True, slots=True)
class Release:
    """The controller types one distribution's models export."""

    types: dict[str, str]  # type -> the package exporting it
    packages: frozenset[str]  # the packages exporting one

    def closed(self, prefix: str) -> bool:
        """Return whether the models give every type exported under ``prefix``."""
        return prefix in self.packages or any(t.partition("/")[0] == prefix for t in self.types)

    def under(self, prefix: str) -> list[str]:
        """Return the types exported under ``prefix``."""
        return sorted(t for t in self.types if t.partition("/")[0] == prefix)

    def exporters(self, prefix: str) -> set[str]:
        """Return the packages exporting types under ``prefix`` (and ``prefix`` itself)."""
        found = {p for t, p in self.types.items() if t.partition("/")[0] == prefix}
        return found | ({prefix} if prefix in self.packages else set())


@lru_cache(maxsize=len(MODEL_DISTROS))
def release(distro: str) -> Release:
    """Return the controller types of a distribution's shipped models (read once)."""
    types: dict[str, str] = {}
    for package in shipped_packages():
        model = released_model(package, distro)
        for interface in model.interfaces if model is not None else ():
            if "/" in interface.executable and interface.component:
                types[interface.executable] = package
    return Release(types, frozenset(types.values()))


@dataclass(frozen=True, slots=True)
class Exports:
    """The controller types a workspace package exports; ``open``: why maybe more."""

    types: frozenset[str]
    open: str | None = None


class ControllerTypes:
    """The controller types that can be known to exist, for one check (read lazily)."""

    def __init__(self, index: PackageIndex | None, distro: str | None) -> None:
        self.index = index if index is not None else PackageIndex()
        self.distro = distro
        self.checked = (distro,) if distro in MODEL_DISTROS else MODEL_DISTROS
        self._exports: dict[str, Exports] = {}
        self._anywhere: frozenset[str] | None = None

    def missing(self, kind: str) -> Missing | None:
        """Return why nothing exports controller type ``kind``; ``None`` when not a fact.

        Most types are quickly found: in the model of their own package, or in the
        descriptions of their workspace package.
        """
        prefix, slash, rest = kind.partition("/")
        if not slash or not prefix or not rest or self.released_as_named(kind, prefix):
            return None
        package = self.index.find(prefix)
        workspace = package if package is not None and package.source is not None else None
        if workspace is not None and kind in self.exports(workspace).types:
            return None
        releases = {d: release(d) for d in MODEL_DISTROS}
        renamed = RENAMED.get(kind)
        gone = renamed is not None and renamed.gone_by(self.distro)
        modelled = any(kind in releases[d].types for d in self.checked)
        # a distribution no model is extracted for checks every release's: the table
        # knows when the type left (gripper_controllers is not in kilted)
        if (modelled and not (gone and self.distro not in MODEL_DISTROS)) or \
                kind in self.anywhere():
            return None
        if workspace is not None:
            return self.in_workspace(kind, workspace)
        if renamed is not None and gone:
            return Missing(f"{renamed.settled}; use {renamed.new}{renamed.also}",
                           renamed.new, renamed.fix, named=True)
        return self.in_releases(kind, prefix, releases)

    def released_as_named(self, kind: str, prefix: str) -> bool:
        """Return whether the model of the type's own package has it (most types: quick)."""
        if self.distro not in MODEL_DISTROS and kind in RENAMED:
            return False  # the table may know it left (see ``missing``)
        for distro in self.checked:
            model = released_model(prefix, distro)
            if model is not None and any(i.executable == kind for i in model.interfaces):
                return True
        return False

    def in_workspace(self, kind: str, package: Package) -> Missing | None:
        """Return why a workspace package does not export ``kind``, if all is known."""
        exports = self.exports(package)
        if exports.open is not None:
            return None
        own = sorted(exports.types)
        listed = ", ".join(own) if own else "no controller"
        return self.meant(f"the plugin descriptions of workspace package {package.name} "
                          f"export {listed}", kind, own)

    def in_releases(self, kind: str, prefix: str, releases: dict[str, Release],
                    ) -> Missing | None:
        """Return why no checked release of ``prefix`` exports ``kind``, if that is a fact.

        Each checked distribution's release of ``prefix`` is modelled without it, or the
        distribution has none (another's models have ``prefix``, and its packages are
        neither modelled for that one nor to be found here).
        """
        closed = [d for d in self.checked if releases[d].closed(prefix)]
        absent = [d for d in self.checked if d not in closed and self.absent(prefix, d, releases)]
        if len(closed) + len(absent) < len(self.checked):
            return None
        parts = []
        if closed:
            parts.append(f"the {_joined(closed, 'and')} release of {prefix} does not export "
                         "it" if len(closed) == 1 else f"the {_joined(closed, 'and')} "
                         f"releases of {prefix} do not export it")
        if absent:
            parts.append(f"{_joined(absent, 'and')} {'has' if len(absent) == 1 else 'have'} "
                         f"no {prefix}")
        why = "; ".join(parts)
        elsewhere = [d for d in MODEL_DISTROS if kind in releases[d].types]
        if elsewhere:  # the type is right, for another distribution
            return Missing(f"{why} (the type {_since(elsewhere)})")
        own = sorted({t for d in closed for t in releases[d].under(prefix)})
        return self.meant(why, kind, own, [t for d in self.checked for t in releases[d].types])

    def absent(self, prefix: str, distro: str, releases: dict[str, Release]) -> bool:
        """Return whether ``distro`` surely has no package exporting types under ``prefix``."""
        exporters = {p for d in MODEL_DISTROS if d != distro
                     for p in releases[d].exporters(prefix)}
        return bool(exporters) and all(p not in releases[distro].packages
                                       and self.index.find(p) is None for p in exporters)

    def meant(self, why: str, kind: str, own: list[str],
              others: list[str] | None = None) -> Missing:
        """Return the finding's reason with the type probably meant.

        The closest type of the same package, else of all known ones; replacing the text
        is safe when it is the only one within two edits.
        """
        pool = frozenset(own)
        found = closest(kind, pool)
        if found is None:
            pool = frozenset([*own, *(others or ()), *self.anywhere()])
            found = closest(kind, pool)
        if found is None:
            return Missing(why)
        safe = sole_typo(kind, pool) == found
        return Missing(why, found, Applicability.SAFE if safe else Applicability.UNSAFE)

    # ------------------------------------------------------------------ reading

    def exports(self, package: Package) -> Exports:
        """Return what a workspace package's plugin descriptions export (read once)."""
        found = self._exports.get(package.name)
        if found is None:
            found = self._exports[package.name] = package_exports(package)
        return found

    def anywhere(self) -> frozenset[str]:
        """Return the types any description the workspace or an install prefix holds exports.

        Only to clear a type: what is read here need not be all (a description a CMake
        variable names is not found).
        """
        if self._anywhere is None:
            found: set[str] = set()
            for name in self.index.names():
                package = self.index.find(name)
                if package is not None and package.source is not None:
                    found.update(_described(package.source))
            prefixes = [*self.index.prefixes,
                        *(p for w in self.index.workspaces for p in workspace_prefixes(w))]
            for prefix in dict.fromkeys(prefixes):
                found.update(_installed(prefix))
            self._anywhere = frozenset(found)
        return self._anywhere


def _joined(items: list[str], word: str) -> str:
    return items[0] if len(items) == 1 else f"{', '.join(items[:-1])} {word} {items[-1]}"


def _since(distros: list[str]) -> str:
    """Return ``since jazzy`` for types released from one distribution on, else where."""
    first = MODEL_DISTROS.index(distros[0])
    if list(MODEL_DISTROS[first:]) == distros:
        return f"is released since {distros[0]}"
    return f"is released for {_joined(distros, 'and')}"


# ---------------------------------------------------------------------- a package's exports


class _Descriptions(Reader):
    """Reads which plugin descriptions a package's CMake files export for controllers.

    ``open`` says why they may be more: an export whose words are not known, a file
    ``include``d or a loop, call or subdirectory not followed, a command of another
    package that names an XML file or ``controller_interface`` (a wrapper exporting one).
    """

    def __init__(self, folder: Path, name: str) -> None:
        super().__init__(folder, name)
        self.files: list[Path] = []
        self.open: str | None = None

    def unfollowed(self, command: Command) -> None:
        self.open = self.open or f"its CMake command {command.name}() is not followed"

    def command(self, scope: Scope, command: Command) -> bool:
        name, words = command.name, scope.each(command.arguments)
        if name == EXPORT:
            if len(words) < 2 or None in words:
                self.open = self.open or f"an {EXPORT}() of it is not known"
            elif words[0] == BASE_PACKAGE:
                self.files.extend(scope.path(word) for word in words[1:] if word)
            return True
        if name == "include":
            module = words[0] if words else None
            if module is None or "/" in module or "." in module or "$" in module:
                self.open = self.open or "its CMake files include another file"
        elif not name.startswith(_KNOWN) and any(
                word is not None and (word.endswith(".xml") or word == BASE_PACKAGE)
                for word in words):
            self.open = self.open or f"its CMake command {name}() may export a description"
        return False


# Commands that name XML files or controller_interface and export no plugin description
_KNOWN = ("install", "find_package", "ament_", "target_", "add_", "set_", "get_",
          "generate_", "rosidl_", "configure_file", "file", "list", "string", "message")


def package_exports(package: Package) -> Exports:
    """Return the controller types a workspace package exports, and why maybe more.

    Those of the descriptions its CMake files export for ``controller_interface``, and of
    any XML file at its root (as ``topology.sources`` reads controllers).
    """
    source = package.source
    if source is None or not (source / "CMakeLists.txt").is_file():
        return Exports(frozenset(), "it has no CMakeLists.txt")
    reader = _Descriptions(source, package.name)
    if not reader.read():
        return Exports(frozenset(), "its CMakeLists.txt cannot be read")
    types: set[str] = set()
    for path in reader.files:
        classes = controller_classes(path)
        if classes is None:
            return Exports(frozenset(), f"its plugin description {path.name} cannot be read")
        types.update(name for _, name, _ in classes)
    types.update(_described(source))
    return Exports(frozenset(types), reader.open)


_EXPORTED = re.compile(EXPORT + r'\s*\(\s*"?' + BASE_PACKAGE + r'"?\s+"?([^\s")$]+)"?',
                       re.IGNORECASE)
MAX_CMAKE_BYTES = 512 * 1024


def _described(source: Path) -> frozenset[str]:
    """Return the types of a package's root XML files and the descriptions it exports.

    Those its ``CMakeLists.txt`` names literally: a quick look, to clear a type.
    """
    paths = [p for p in sorted(source.glob("*.xml")) if p.name != "package.xml"]
    try:
        cmake = read_text(source / "CMakeLists.txt", prefix=MAX_CMAKE_BYTES)
    except (Unreadable, OSError):
        cmake = ""
    paths.extend(source / written for written in _EXPORTED.findall(cmake))
    return frozenset(name for path in dict.fromkeys(paths)
                     for _, name, _ in controller_classes(path) or ())


def _installed(prefix: Path) -> frozenset[str]:
    """Return the types of the descriptions an install prefix's ament index lists."""
    folder = prefix / RESOURCE
    if not folder.is_dir():
        return frozenset()
    found: set[str] = set()
    try:
        entries = sorted(folder.iterdir())[:MAX_RESOURCES]
    except OSError:
        return frozenset()
    for entry in entries:
        try:
            listed = read_text(entry, prefix=MAX_CMAKE_BYTES)
        except (Unreadable, OSError):
            continue
        for line in re.split(r"[\n;]", listed):
            if line.strip():
                found.update(name for _, name, _ in
                             controller_classes(prefix / line.strip()) or ())
    return frozenset(found)


@dataclass
class _Kept:
    """The check's ``ControllerTypes``, by distribution."""

    by_distro: dict[str | None, ControllerTypes] = field(default_factory=dict)


def controller_types(memo: dict[object, object], index: PackageIndex | None,
                     distro: str | None) -> ControllerTypes:
    """Return the check's controller types for ``distro`` (kept in a rule's memo)."""
    kept = memo.get("controller_types")
    if not isinstance(kept, _Kept):
        kept = memo["controller_types"] = _Kept()
    found = kept.by_distro.get(distro)
    if found is None:
        found = kept.by_distro[distro] = ControllerTypes(index, distro)
    return found
