"""Which source files make up each executable or component of a workspace package.

CMake packages: the sources of ``add_executable`` (and the in-package libraries it links),
the library of each ``rclcpp_components_register_node(s)`` plugin, read by
``package_executables.build_targets``, and the library of each ros2_control controller a
pluginlib description file exports (a controller runs as a node of its own inside the
controller manager); each source's ``#include "..."`` of the package's own headers is
followed. ament_python packages: the module of each ``console_scripts``
entry point (``pkg.module:main``) and the package modules it imports.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from launchverify.topology.files import CPP_SUFFIXES
from launchverify.topology.plugin_xml import descriptions, package_descriptions
from launchverify.workspace.package_executables import BuildTargets, build_targets
from launchverify.workspace.packages import Package
from launchverify.workspace.reading import Unreadable, read_text

MAX_FILES = 400  # source files followed for one target
MAX_HEADER_BYTES = 512 * 1024


@dataclass(frozen=True, slots=True)
class Target:
    """An executable (``ros2 run`` name) or a component plugin, and its source files."""

    executable: str
    component: str | None
    sources: tuple[Path, ...]
    problems: tuple[str, ...] = ()
    other_components: tuple[str, ...] = ()  # plugins sharing its library
    main_sources: tuple[Path, ...] = ()  # its own files, before the libraries it links


def package_targets(package: Package) -> list[Target]:
    """Return the executables and components of a package with its sources at hand."""
    source = package.source
    if source is None:
        return []
    if (source / "CMakeLists.txt").is_file():
        return _cmake(source, package.name)
    if (source / "setup.py").is_file() or (source / "setup.cfg").is_file():
        return _python(source)
    return []


# --------------------------------------------------------------------------- CMake


def _cmake(source: Path, name: str) -> list[Target]:
    targets = build_targets(source, name)
    if targets is None:
        return []
    out: list[Target] = []
    registered = {exe for _, _, exe in targets.components if exe}
    libraries = {library for library, _, _ in targets.components}
    for target in sorted(targets.executables):
        if target in libraries or target in registered:
            continue
        files, problems = _target_files(source, target, targets)
        own = tuple(path for word in targets.sources.get(target, ())
                    for path in _expand_word(source, word, []))
        out.append(Target(targets.output_names.get(target, target), None, files, problems,
                          main_sources=own))
    for library, plugin, executable in targets.components:
        files, problems = _target_files(source, library, targets)
        if library not in targets.sources:
            problems = (*problems, f"library '{library}' of {plugin} not found in CMakeLists.txt")
        others = tuple(p for lib, p, _ in targets.components if lib == library and p != plugin)
        out.append(Target(executable or plugin, plugin, files, problems, others))
    out.extend(_controllers(source, targets))
    return out


def _controllers(source: Path, targets: BuildTargets) -> list[Target]:
    """Return the ros2_control controllers the package's plugin description files export.

    Each is named as a controller manager's ``type`` parameter names it
    (``diff_drive_controller/DiffDriveController``); its class is the component.
    """
    found = [(e.library, e.type, e.cls) for e in package_descriptions(source) if e.controller]
    out = []
    for library, plugin, kind in found:
        files, problems = _target_files(source, library, targets)
        if library not in targets.sources:
            problems = (*problems, f"library '{library}' of {plugin} not found in CMakeLists.txt")
        others = tuple(k for lib, _, k in found if lib == library and k != kind)
        out.append(Target(plugin, kind, files, problems, others))
    return out


def library_files(package: Package, library: str) -> tuple[tuple[Path, ...], tuple[str, ...]]:
    """Return a CMake library's sources (with what it links) and what could not be read."""
    source = package.source
    targets = build_targets(source, package.name) if source is not None else None
    if source is None or targets is None or library not in targets.sources:
        return (), (f"library '{library}' not found in CMakeLists.txt",)
    return _target_files(source, library, targets)


def controller_classes(path: Path) -> list[tuple[str, str, str]] | None:
    """Return ``(library, pluginlib name, class)`` of each controller a plugin file exports.

    ``None`` when the file cannot be read as XML.
    """
    found = descriptions(path)
    return None if found is None else [(e.library, e.type, e.cls) for e in found
                                       if e.controller]


def _target_files(source: Path, target: str, targets: BuildTargets,
                  ) -> tuple[tuple[Path, ...], tuple[str, ...]]:
    """Return a target's sources, those of in-package libraries it links, and their headers."""
    problems: list[str] = []
    files: list[Path] = []
    seen_targets: set[str] = set()
    pending = [target]
    while pending:
        current = pending.pop()
        if current in seen_targets:
            continue
        seen_targets.add(current)
        for word in targets.sources.get(current, ()):
            files.extend(_expand_word(source, word, problems))
        pending.extend(link for link in targets.links.get(current, ()) if link in targets.sources)
    if not targets.sources_known(seen_targets):
        problems.append("CMakeLists.txt was not followed completely: sources may be missing")
    return tuple(_with_headers(source, files)), tuple(problems)


def _expand_word(source: Path, word: str, problems: list[str]) -> list[Path]:
    path = Path(word) if Path(word).is_absolute() else source / word
    if word.endswith("/"):
        if not path.is_dir():
            problems.append(f"source folder {word} not found")
            return []
        return sorted(p for p in path.rglob("*") if p.suffix.lower() in CPP_SUFFIXES
                      and p.is_file())[:MAX_FILES]
    if not path.suffix and not path.exists():  # CMake tries the usual extensions
        path = next((path.with_suffix(e) for e in (".cpp", ".cc", ".cxx")
                     if path.with_suffix(e).is_file()), path)
    if path.suffix.lower() not in CPP_SUFFIXES:
        return []  # generated files, object libraries, other languages
    if not path.is_file():
        problems.append(f"source {word} not found")
        return []
    return [path]


_INCLUDE = re.compile(r'^\s*#\s*include\s*["<]([^">]+)[">]', re.M)


def _with_headers(source: Path, files: list[Path]) -> list[Path]:
    """Add the package's own headers the sources include (transitively, bounded)."""
    include_dirs = [source / "include", source / "src", source]
    out: list[Path] = []
    seen: set[Path] = set()
    pending = list(files)
    while pending and len(out) < MAX_FILES:
        current = pending.pop(0)
        if current in seen:
            continue
        seen.add(current)
        out.append(current)
        try:
            code = read_text(current, prefix=MAX_HEADER_BYTES)
        except (Unreadable, OSError):
            continue
        for written in _INCLUDE.findall(code):
            for folder in (current.parent, *include_dirs):
                candidate = folder / written
                if candidate.is_file() and _inside(candidate, source):
                    pending.append(candidate)
                    break
    return out


def _inside(path: Path, folder: Path) -> bool:
    try:
        path.resolve().relative_to(folder.resolve())
    except (OSError, ValueError):
        return False
    return True


# --------------------------------------------------------------------------- ament_python

_ENTRY = re.compile(r"""['"]\s*([A-Za-z0-9_.\-]+)\s*=\s*([A-Za-z0-9_.]+)\s*:\s*(\w+)""")
_CFG_ENTRY = re.compile(r"^\s*([A-Za-z0-9_.\-]+)\s*=\s*([A-Za-z0-9_.]+)\s*:\s*(\w+)", re.M)
_IMPORT = re.compile(r"^\s*(?:from\s+([\w.]+)\s+import|import\s+([\w.]+))", re.M)


def entry_points(source: Path) -> list[tuple[str, str]]:
    """Return ``(executable, module)`` for each console script of setup.py / setup.cfg."""
    found: list[tuple[str, str]] = []
    for name, pattern in (("setup.py", _ENTRY), ("setup.cfg", _CFG_ENTRY)):
        try:
            text = read_text(source / name, prefix=MAX_HEADER_BYTES)
        except (Unreadable, OSError):
            continue
        if "console_scripts" not in text:
            continue
        section = text[text.index("console_scripts"):]
        if name == "setup.py":
            end = section.find("]")
            section = section[: end if end >= 0 else None]
        else:
            section = section.split("\n[", 1)[0]
        found.extend((exe, module) for exe, module, _ in pattern.findall(section))
    return found


def _python(source: Path) -> list[Target]:
    out = []
    for executable, module in entry_points(source):
        path = _module_file(source, module)
        if path is None:
            out.append(Target(executable, None, (), (f"module {module} not found",)))
            continue
        out.append(Target(executable, None, tuple(_with_imports(source, module, path)),
                          main_sources=(path,)))
    return out


def _module_file(source: Path, module: str) -> Path | None:
    relative = Path(*module.split("."))
    for root in (source, source / "src"):
        for candidate in (root / relative.with_suffix(".py"), root / relative / "__init__.py"):
            if candidate.is_file():
                return candidate
    return None


def _with_imports(source: Path, module: str, path: Path) -> list[Path]:
    """Add the modules of the same Python package the entry module imports (bounded)."""
    top = module.split(".", 1)[0]
    out: list[Path] = []
    pending = [(module, path)]
    while pending and len(out) < MAX_FILES:
        current, file = pending.pop(0)
        if file in out:
            continue
        out.append(file)
        try:
            code = read_text(file, prefix=MAX_HEADER_BYTES)
        except (Unreadable, OSError):
            continue
        package = current.rsplit(".", 1)[0] if "." in current else current
        for absolute, plain in _IMPORT.findall(code):
            imported = absolute or plain
            if imported.startswith("."):
                imported = package + "." + imported.lstrip(".") if imported.strip(".") else ""
            if not imported or imported.split(".", 1)[0] != top:
                continue
            found = _module_file(source, imported)
            if found is not None:
                pending.append((imported, found))
    return out

