"""What ``import`` means inside a launch file being evaluated.

Three finders, in order of precedence:

- the launch API (``launch``, ``launch_ros``, ``ament_index_python``...) comes from our
  models, whatever is installed;
- Python packages of workspace packages come from the workspace
  (``from my_robot.launch_utils import ...``), as they do once the workspace is built and
  sourced; modules beside the launch file are importable only if the file puts its folder
  on ``sys.path`` (ros2 launch does not), and that change is undone afterwards;
- after Python's own finders (the standard library, installed libraries), anything still
  missing becomes an opaque stand-in, reported once per module as not modelled.

``ImportContext`` installs them for one evaluation and removes every module it loaded, so
one launch file's helpers never leak into the next.
"""

from __future__ import annotations

import builtins
import importlib
import importlib.abc
import importlib.machinery
import importlib.util
import os
import sys
import types
from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from launchverify.frontends.python.rewrite import compile_launch_file
from launchverify.models.launch_api import MODULES, QUIET_ROOTS, exports_for, is_modelled
from launchverify.models.launch_api.unknown import Opaque, OpaqueModule, launch_builtins
from launchverify.own_code import is_own_file
from launchverify.workspace.packages import PackageIndex


class _ModelLoader(importlib.abc.Loader):
    def __init__(self, report: Callable[[str], None]) -> None:
        self.report = report

    def create_module(self, spec: importlib.machinery.ModuleSpec) -> types.ModuleType:
        module = types.ModuleType(spec.name)
        module.__dict__.update(exports_for(spec.name) or {})
        module.__path__ = []  # every model module can have submodules
        report = self.report

        quiet = spec.name.partition(".")[0] in QUIET_ROOTS

        def missing(name: str) -> Any:
            if name.startswith("__"):
                raise AttributeError(name)
            if not quiet:
                report(f"{spec.name}.{name}")
            return Opaque(f"{spec.name}.{name}")

        module.__getattr__ = missing  # type: ignore[method-assign]
        return module

    def exec_module(self, module: types.ModuleType) -> None:
        # Like the real packages, a module imports its submodules: `import launch` is
        # enough to use `launch.actions.ExecuteProcess`.
        prefix = module.__name__ + "."
        for name in MODULES:
            if name.startswith(prefix) and "." not in name[len(prefix):]:
                setattr(module, name[len(prefix):], importlib.import_module(name))


class ModelFinder(importlib.abc.MetaPathFinder):
    """Serves the launch API models under their real module names."""

    def __init__(self, report: Callable[[str], None]) -> None:
        self.report = report

    def find_spec(self, fullname: str, path: Sequence[str] | None = None,
                  target: types.ModuleType | None = None) -> importlib.machinery.ModuleSpec | None:
        if not is_modelled(fullname):
            return None
        return importlib.machinery.ModuleSpec(fullname, _ModelLoader(self.report),
                                              is_package=True)


class WorkspaceFinder(importlib.abc.MetaPathFinder):
    """Finds modules beside the launch file and the Python packages a build would install.

    Those a workspace package's build installs come first (``index.python_sources``: an
    ament_python package's ``setup.py``, an ament_cmake package's ``CMakeLists.txt``), as
    they do once the workspace is built and sourced; then a module in the source folder
    of the package of that name, and those of installed prefixes. Pure Python only.
    """

    def __init__(self, folders: list[Path], index: PackageIndex) -> None:
        self.folders = folders
        self.index = index

    def find_spec(self, fullname: str, path: Sequence[str] | None = None,
                  target: types.ModuleType | None = None) -> importlib.machinery.ModuleSpec | None:
        if "." in fullname:  # a submodule of a workspace package is the workspace's too
            parent = sys.modules.get(fullname.rpartition(".")[0])
            spec = getattr(parent, "__spec__", None)
            if not isinstance(getattr(spec, "loader", None), UserCodeLoader) or path is None:
                return None
            return user_code(importlib.machinery.PathFinder.find_spec(fullname, path))
        if fullname not in sys.stdlib_module_names:
            for source in self.index.python_sources(fullname):
                spec = installed_spec(fullname, source)
                if spec is not None:
                    return user_code(spec)
        roots = list(self.folders)
        package = self.index.find(fullname)
        if package is not None and package.source is not None:
            roots.append(package.source)
        for root in roots:
            spec = importlib.machinery.PathFinder.find_spec(fullname, [str(root)])
            if spec is not None and spec.origin and not spec.origin.endswith((".so", ".pyd")):
                return user_code(spec)
        return None


class UserCodeLoader(importlib.machinery.SourceFileLoader):
    """Loads a workspace's Python module as a launch file is run: it is the user's code too.

    Compiled from its source (never from a ``__pycache__`` a pull request could fill),
    the way launch files are (``raise``/``except``/``match`` ask an unknown), with the
    launch file's builtins (``int``, ``ord``, ``isinstance``... of an unknown): a vendor's
    helper in the workspace meets unknown values as the launch file that calls it does.
    """

    def get_code(self, fullname: str) -> types.CodeType:
        return compile_launch_file(self.get_data(self.path), self.path)

    def exec_module(self, module: types.ModuleType) -> None:
        module.__dict__["__builtins__"] = launch_builtins()
        super().exec_module(module)


def user_code(spec: importlib.machinery.ModuleSpec | None
              ) -> importlib.machinery.ModuleSpec | None:
    """Return a source module's spec loading it as the user's code (others unchanged)."""
    if spec is None or not spec.origin or not spec.origin.endswith(".py") or not isinstance(
            spec.loader, importlib.machinery.SourceFileLoader):
        return spec
    spec.loader = UserCodeLoader(spec.name, spec.origin)
    return spec


def installed_spec(name: str, source: Path) -> importlib.machinery.ModuleSpec | None:
    """Return the spec of ``source`` imported as ``name``, the name its build installs it as.

    ``ament_python_install_package(fleet_names PACKAGE_DIR python/helpers)`` makes the
    folder ``helpers`` the package ``fleet_names``: the folder's name says nothing, so
    the spec is made from the path (its submodules are found in the folder).
    """
    if source.is_dir():
        return importlib.util.spec_from_file_location(
            name, source / "__init__.py", submodule_search_locations=[str(source)])
    return importlib.util.spec_from_file_location(name, source)


class InstalledFinder(importlib.abc.MetaPathFinder):
    """Finds what Python's own finders do not, in the installed prefixes' Python folders."""

    def __init__(self, index: PackageIndex) -> None:
        self.index = index

    def find_spec(self, fullname: str, path: Sequence[str] | None = None,
                  target: types.ModuleType | None = None) -> importlib.machinery.ModuleSpec | None:
        if "." in fullname or not self.index.site_packages():
            return None
        spec = importlib.machinery.PathFinder.find_spec(
            fullname, [str(folder) for folder in self.index.site_packages()])
        if spec is not None and spec.origin and not spec.origin.endswith((".so", ".pyd")):
            return spec
        return None


class _OpaqueLoader(importlib.abc.Loader):
    def create_module(self, spec: importlib.machinery.ModuleSpec) -> types.ModuleType:
        return OpaqueModule(spec.name)

    def exec_module(self, module: types.ModuleType) -> None:
        return None


class OpaqueFinder(importlib.abc.MetaPathFinder):
    """Last resort: a module nothing else provides becomes an opaque stand-in.

    Only for imports written in the launch file or workspace code: libraries that probe
    for optional modules must keep getting ``ImportError``.
    """

    def __init__(self, report: Callable[[str], None], user_folders: list[str],
                 sibling_folders: list[str]) -> None:
        self.report = report
        self.user_folders = user_folders
        self.sibling_folders = sibling_folders

    def find_spec(self, fullname: str, path: Sequence[str] | None = None,
                  target: types.ModuleType | None = None) -> importlib.machinery.ModuleSpec | None:
        if not self.imported_by_user(fullname):
            return None  # libraries probe optional modules (try: import _winapi)
        if "." not in fullname and any(
            importlib.machinery.PathFinder.find_spec(fullname, [folder]) is not None
            for folder in self.sibling_folders
        ):
            return None  # beside the launch file but not importable: ros2 launch fails too
        self.report(fullname.partition(".")[0])
        return importlib.machinery.ModuleSpec(fullname, _OpaqueLoader(), is_package=True)

    def imported_by_user(self, fullname: str) -> bool:
        """Return whether the import statement is in the launch file or workspace code."""
        parent = fullname.rpartition(".")[0]
        if parent and isinstance(sys.modules.get(parent), OpaqueModule):
            return True
        frame = sys._getframe(1)
        while frame is not None:
            name = frame.f_code.co_filename
            if "importlib" not in name and not is_own_file(name):
                return any(name.startswith(folder) for folder in self.user_folders)
            frame = frame.f_back  # type: ignore[assignment]
        return False


# What the modules ablation keeps: the launch library, and Python's own.
KEPT_ROOTS = frozenset({"launch", "launch_ros"})


def absent_modules_asked() -> bool:
    """Return whether the check runs with every other module taken away (an ablation).

    ``LAUNCHVERIFY_ABLATE=modules`` is for ``bench/ablation.py``: what launchverify cannot
    see must never become an error, so taking knowledge away may add no error.
    """
    return "modules" in os.environ.get("LAUNCHVERIFY_ABLATE", "").split(",")


def absent_import(report: Callable[[str], None]) -> Callable[..., Any]:
    """Return an ``__import__`` for which only the launch library and Python's own exist.

    Every other module a launch file imports (a vendor's helpers, the workspace's, an
    installed library, launchverify's models of other packages) is an opaque stand-in, as
    a module nothing provides is.
    """
    real = builtins.__import__

    def ablated(name: str, globals: Any = None, locals: Any = None,
                fromlist: Sequence[str] = (), level: int = 0) -> Any:
        root = name.partition(".")[0]
        if level or root in KEPT_ROOTS or root in sys.stdlib_module_names:
            return real(name, globals, locals, fromlist, level)
        report(root)
        module = OpaqueModule(name if fromlist else root)
        return module

    return ablated


@contextmanager
def import_context(folders: list[Path], index: PackageIndex, report: Callable[[str], None],
                   report_name: Callable[[str], None]) -> Iterator[None]:
    """Install the finders for one evaluation and forget what it imported afterwards.

    ``report`` hears of modules nothing provides, ``report_name`` of names the launch API
    models do not have.
    """
    before = set(sys.modules)
    saved_path = list(sys.path)
    front = [ModelFinder(report_name), WorkspaceFinder([], index)]
    user_folders = [str(f) for f in folders] + [str(w) for w in index.workspaces]
    back = [InstalledFinder(index),
            OpaqueFinder(report, user_folders, [str(f) for f in folders])]
    sys.meta_path[:0] = front
    sys.meta_path.extend(back)
    try:
        yield
    finally:
        sys.path[:] = saved_path  # a launch file's sys.path.append must not reach the next
        sys.path_importer_cache.clear()
        for finder in (*front, *back):
            if finder in sys.meta_path:
                sys.meta_path.remove(finder)
        for name in set(sys.modules) - before:
            module = sys.modules.get(name)
            spec = getattr(module, "__spec__", None)
            loader = getattr(spec, "loader", None)
            origin = str(getattr(spec, "origin", "") or "")
            ours = isinstance(loader, (_ModelLoader, _OpaqueLoader))
            local = any(origin.startswith(str(folder)) for folder in folders) or (
                index.owner(Path(origin)) is not None if origin else False)
            if ours or local:
                del sys.modules[name]
