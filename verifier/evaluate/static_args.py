"""launch's static argument discovery (``get_launch_arguments``), reproduced.

``ros2 launch -s`` and the include pre-check use it: walk a description's actions without
a context, follow includes whose path needs no configuration (a fresh context has none,
and no current file either), see arguments under conditions, timers and handlers as
conditional, stop a list at ``ResetLaunchConfigurations``; the first declaration of a name
wins.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass
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

    def config(self, name: str, default: s.Sub | None, where: Span | None = None,
               written: Span | None = None) -> s.Sub:
        if default is not None:
            return self.reduce(default)
        return Unknown(f"configuration {name}")

    def package_share(self, name: str, written: Span | None = None) -> s.Sub:
        package = self.index.find(name)
        return Unknown(name) if package is None else s.Text(str(package.share))


Found = tuple[a.DeclareArgument, tuple[a.Include, ...], bool]


@dataclass(frozen=True)
class StaticSubtree:
    """What one file's actions declare, includes followed (relative to that file).

    ``height``: how deep its includes go; ``cut``: whether a cycle or the depth limit cut
    it short, so the answer depends on where the file was reached and is not reused.
    """

    found: tuple[Found, ...]
    height: int
    cut: bool


def static_arguments(launch: a.LaunchFile, loader: Loader, index: PackageIndex,
                     memo: dict[Path, StaticSubtree] | None = None) -> list[Found]:
    """Return ``(declaration, nested includes, conditional)`` in discovery order.

    ``memo`` keeps each included file's answer between calls (every root of a check asks
    about the same included files): a file is walked once, not once per includer.
    """
    reducer = ContextFreeReducer(index)
    memo = {} if memo is None else memo

    def subtree(target: Path, stack: frozenset[Path], depth: int) -> StaticSubtree | None:
        known = memo.get(target)
        if known is not None and depth + known.height < MAX_DEPTH:
            return known
        loaded = loader(target)
        if loaded.launch is None:
            return None
        found = walk(loaded.launch.actions, False, stack | {target}, depth + 1)
        if not found.cut:
            memo[target] = found
        return found

    def walk(actions: tuple[a.Action, ...], conditional: bool, stack: frozenset[Path],
             depth: int) -> StaticSubtree:
        out: list[Found] = []
        height, cut = 0, False
        for action in actions:
            if isinstance(action, a.DeclareArgument):
                out.append((action, (), conditional or action.condition is not None))
            if isinstance(action, a.ResetConfigs):
                break
            nested = conditional or action.condition is not None
            inner: StaticSubtree | None = None
            if isinstance(action, a.Group):
                if action.scoped and not action.forwarding:
                    continue  # the group's actions come after a reset
                inner = walk(action.actions, nested, stack, depth)
            elif isinstance(action, a.Include):
                target = _resolve(action, reducer, index)
                if target is None:
                    continue
                if target in stack or depth >= MAX_DEPTH:
                    cut = True
                    continue
                child = subtree(target, stack, depth)
                if child is None:
                    continue
                out.extend((d, (action, *via), c or nested) for d, via, c in child.found)
                height, cut = max(height, child.height + 1), cut or child.cut
            elif isinstance(action, (a.Timer, a.RegisterEventHandler, a.ForLoop, a.ForEach)):
                inner = walk(action.sub_actions(), True, stack, depth)
            if inner is not None:
                out.extend(inner.found)
                height, cut = max(height, inner.height), cut or inner.cut
        return StaticSubtree(tuple(out), height, cut)

    found: list[Found] = []
    seen: set[str] = set()
    for declaration, via, conditional in walk(launch.actions, False, frozenset(), 0).found:
        if declaration.name not in seen:  # the first declaration of a name wins
            seen.add(declaration.name)
            found.append((declaration, via, conditional))
    return found


def included_files(actions: tuple[a.Action, ...], index: PackageIndex) -> Iterator[Path]:
    """Yield the files actions include by a path known without a context, in their order.

    Includes under conditions, groups, timers and handlers count: whether they run is not
    known here. (Static discovery follows the same paths.)
    """
    reducer = ContextFreeReducer(index)
    stack = list(reversed(actions))
    while stack:
        action = stack.pop()
        if isinstance(action, a.Include):
            target = _resolve(action, reducer, index)
            if target is not None:
                yield target
        stack.extend(reversed(action.sub_actions()))


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
