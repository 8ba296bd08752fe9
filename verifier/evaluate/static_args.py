"""launch's static argument discovery (``get_launch_arguments``), reproduced.

``ros2 launch -s`` and the include pre-check use it: walk a description's actions without
a context, follow includes whose path needs no configuration (a fresh context has none,
and no current file either), see arguments under conditions, timers and handlers as
conditional, stop a list at ``ResetLaunchConfigurations``; the first declaration of a name
wins.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from launchverify.evaluate.values import Reducer, text_of
from launchverify.frontends import LoadedFile
from launchverify.ir import actions as a
from launchverify.ir import subst as s
from launchverify.ir.symbolic import Unknown
from launchverify.span import Span
from launchverify.workspace.packages import PackageIndex

Loader = Callable[[Path], LoadedFile]
MAX_DEPTH = 32


class ContextFreeReducer(Reducer):
    """Reduces as a fresh ``LaunchContext`` would: no configurations, no current file."""

    def __init__(self, index: PackageIndex) -> None:
        super().__init__()
        self.index = index

    def config(self, name: str, default: s.Sub | None, where: Span | None = None) -> s.Sub:
        if default is not None:
            return self.reduce(default)
        return Unknown(f"configuration {name}")

    def package_share(self, name: str) -> s.Sub:
        package = self.index.find(name)
        return Unknown(name) if package is None else s.Text(str(package.share))


def static_arguments(
    launch: a.LaunchFile, loader: Loader, index: PackageIndex
) -> list[tuple[a.DeclareArgument, tuple[a.Include, ...], bool]]:
    """Return ``(declaration, nested includes, conditional)`` in discovery order."""
    reducer = ContextFreeReducer(index)
    found: list[tuple[a.DeclareArgument, tuple[a.Include, ...], bool]] = []
    seen: set[str] = set()
    visiting: set[Path] = set()

    def walk(actions: tuple[a.Action, ...], conditional: bool,
             includes: tuple[a.Include, ...], depth: int) -> None:
        for action in actions:
            if isinstance(action, a.DeclareArgument) and action.name not in seen:
                seen.add(action.name)
                found.append((action, includes, conditional or action.condition is not None))
            if isinstance(action, a.ResetConfigs):
                return
            nested_conditional = conditional or action.condition is not None
            if isinstance(action, a.Group):
                if action.scoped and not action.forwarding:
                    continue  # the group's actions come after a reset
                walk(action.actions, nested_conditional, includes, depth)
            elif isinstance(action, a.Include):
                target = _resolve(action, reducer, index)
                if target is None or target in visiting or depth >= MAX_DEPTH:
                    continue
                loaded = loader(target)
                if loaded.launch is None:
                    continue
                visiting.add(target)
                walk(loaded.launch.actions, nested_conditional, (*includes, action), depth + 1)
                visiting.discard(target)
            elif isinstance(action, (a.Timer, a.RegisterEventHandler, a.ForLoop, a.ForEach)):
                walk(action.sub_actions(), True, includes, depth)

    walk(launch.actions, False, (), 0)
    return found


def include_argument_names(include: a.Include, index: PackageIndex) -> set[str]:
    """Return the argument names an include passes, evaluated without a context."""
    reducer = ContextFreeReducer(index)
    names = set()
    for argument in include.arguments:
        name = text_of(reducer.reduce(argument.name))
        if name is not None:
            names.add(name)
    return names


def _resolve(include: a.Include, reducer: Reducer, index: PackageIndex) -> Path | None:
    location = text_of(reducer.reduce(include.path))
    if location is None:
        return None
    return index.locate(Path(location))
