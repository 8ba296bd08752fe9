"""The reducers the walker evaluates with, and the walk's position (``Ctx``).

``ScopeReducer`` looks values up in the walker's current scope and records reads, package
references and problems at the action being evaluated; ``DefaultsReducer`` re-evaluates a
value that depends on arguments with the arguments as given and the defaults, reporting
what would fail with them.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, TypeVar

from launchverify.evaluate.scope import GLOBAL_PARAMS
from launchverify.evaluate.values import BaseReducer, Reducer, is_unset, text_of
from launchverify.graph import Origin
from launchverify.ir import subst as s
from launchverify.ir.symbolic import (
    ExecutablePath,
    Guard,
    PackageFolder,
    PathCondition,
    Select,
    StrEquals,
    Truthy,
    Unknown,
    Unset,
)
from launchverify.problems import ProblemKind
from launchverify.span import Span

if TYPE_CHECKING:
    from launchverify.evaluate.walker import Walker


@dataclass(frozen=True, slots=True)
class Ctx:
    """Where the walk is: the file being executed, the include chain, the path condition."""

    file: Path
    chain: tuple[Span, ...]
    path: PathCondition
    deferred: bool = False
    loop: tuple[tuple[str, s.Sub, bool], ...] = ()

    def origin(self, span: Span) -> Origin:
        """Return the origin of something written at ``span`` here."""
        return Origin(span, self.chain, self.path)

    def guarded(self, guard: Guard) -> Ctx:
        """Return this context with one more guard."""
        return dataclasses.replace(self, path=(*self.path, guard))


R = TypeVar("R", bound="_Located")


class _Located:
    """Where a reducer's problems and records point, and how it reports them."""

    prefix = ""
    contextual = False  # its failures rest on argument values an includer may replace
    with_defaults = False  # its failures rest on the default arguments, whatever the path

    def __init__(self, walker: Walker) -> None:
        self.walker = walker
        self.ctx: Ctx | None = None
        self.span: Span | None = None

    def at(self: R, ctx: Ctx, span: Span) -> R:
        """Point problems and records at ``span`` in ``ctx``."""
        self.ctx, self.span = ctx, span
        return self

    def fail(self, message: str, rule: str | None = None) -> None:
        assert self.span is not None
        self.walker.problem(ProblemKind.EVALUATION, self.prefix + message, self.span, self.ctx,
                            contextual=self.contextual, rule=rule,
                            with_defaults=self.with_defaults)

    def unmodeled(self, message: str) -> None:
        assert self.span is not None
        self.walker.problem(ProblemKind.UNMODELED, message, self.span, self.ctx)


class ScopeReducer(_Located, Reducer):
    """Reduces expressions against the evaluator's current scope."""

    def __init__(self, walker: Walker) -> None:
        Reducer.__init__(self)
        _Located.__init__(self, walker)

    def _origin(self, where: Span | None = None) -> Origin:
        """Return where a record comes from: ``where``, if in the action's file, else the action.

        (The action's span is then the origin's ``call``.)
        """
        assert self.ctx is not None and self.span is not None
        if where is None or where.file != self.span.file or where == self.span:
            return self.ctx.origin(self.span)
        call = self.walker.calls[-1] if self.walker.calls else self.span
        return Origin(where, self.ctx.chain, self.ctx.path,
                      call=call if call.file == where.file else self.span)

    def config(self, name: str, default: s.Sub | None, where: Span | None = None,
               written: Span | None = None) -> s.Sub:
        value = self.walker.scopes.get(name)
        current = None if value is None else self.decided(value)
        # set on another path only (``Select``'s other branch): here, nothing set it
        found = current is not None and not isinstance(current, Unset)
        maybe = current if current is not None and found and is_unset(current) else None
        self.walker.record_read(name, self._origin(where), found, default is not None, written,
                                maybe)
        if value is None:
            return Unset(name) if default is None else self.reduce(default)
        if default is not None and is_unset(value):
            return fill_unset(value, self.reduce(default))
        return current if current is not None else value

    def decided(self, value: s.Sub) -> s.Sub:
        """Pick the branch of a path-dependent value that the current path decides.

        Shallow on purpose: values share structure, and reducing them whole would
        unfold that sharing.
        """
        while isinstance(value, Select) and self.ctx is not None and self.ctx.path:
            verdicts = [self.guard(g) for g in value.guards]
            if False in verdicts:
                value = value.otherwise
            elif all(v is True for v in verdicts):
                value = value.then
            else:
                break
        return value

    def environment(self, name: str, default: s.Sub | None) -> s.Sub:
        if name in self.walker.scopes.env:
            value = self.walker.scopes.env[name]
            if value is not None:
                return value
            if default is None:
                self.fail(f"environment variable {name!r} was unset by the launch file")
                return Unknown(f"unset environment variable {name}")
            return self.reduce(default)
        return super().environment(name, default)

    def package_share(self, name: str, written: Span | None = None) -> s.Sub:
        package = self.walker.index.find(name)
        self.walker.record_package(name, self._origin(), package is not None, "share", written)
        return PackageFolder(f"share folder of {name}", name) if package is None else s.Text(
            str(package.share)
        )

    def package_prefix(self, name: str, written: Span | None = None) -> s.Sub:
        package = self.walker.index.find(name)
        self.walker.record_package(name, self._origin(), package is not None, "prefix",
                                   written)
        if package is None or package.prefix is None:
            return PackageFolder(f"install prefix of {name}", name)
        return s.Text(str(package.prefix))

    def executable_path(self, executable: str, package: str,
                        written: Span | None = None) -> s.Sub:
        found = self.walker.index.find(package)
        self.walker.record_package(package, self._origin(), found is not None, "executable",
                                   written)
        return ExecutablePath(f"path of {executable} in {package}", executable, package)

    def this_file(self, directory: bool) -> s.Sub:
        current = self.walker.current_file
        return s.Text(str(current.parent if directory else current))

    def anon(self, name: str) -> s.Sub:
        key = "anon" + name
        value = self.walker.scopes.get(key)
        if value is None:
            clean = name.replace(".", "_").replace("-", "_").replace(":", "_")
            value = s.Text(f"{clean}_anon{next(self.walker.anon_counter)}")
            self.walker.scopes.set(key, value, ())
        return value

    def file_content(self, path: str) -> s.Sub:
        return self.walker.read_file_content(path, self._origin())

    def ros_parameter(self, name: str, default: s.Sub | None) -> s.Sub:
        for item in self.walker.scopes.shared(GLOBAL_PARAMS):
            if item.name is not None and text_of(item.name) == name:
                value = item.value
                return value if isinstance(value, s.Sub) else s.Text(str(value))
        if default is not None:
            return self.reduce(default)
        if not self.walker.incomplete:
            assert self.span is not None
            self.walker.problem(
                ProblemKind.EVALUATION,
                f"parameter {name!r} not found (no set_parameter with that name in scope)",
                self.span, self.ctx, contextual=True,
            )
        return Unknown(f"parameter {name}")

    def loop_variable(self, name: str, default: s.Sub | None, index: bool) -> s.Sub:
        assert self.ctx is not None
        for var, value, is_index in reversed(self.ctx.loop):
            if var == name and is_index == index:
                return value
        if default is not None:
            return self.reduce(default)
        self.fail(f"no value for loop variable {name!r}")
        return Unknown(f"loop variable {name}")

    def guard(self, guard: Guard) -> bool | None:
        """Guards on the current path are known to hold (and their negations not to)."""
        if self.ctx is not None and self.ctx.path:
            if guard in self.ctx.path:
                return True
            if isinstance(guard, (Truthy, StrEquals)) and (
                dataclasses.replace(guard, negate=not guard.negate) in self.ctx.path
            ):
                return False
        return super().guard(guard)

    def probe(self, residual: s.Sub) -> None:
        """A ``$(eval)`` over arguments: it must work with the default arguments too.

        Off the path the defaults take (under a condition false with them), launch
        evaluates it only with arguments that make the condition true: kept for LV002 to
        look for arguments that do and make it raise.
        """
        assert self.ctx is not None and self.span is not None
        if self.walker.graph.runs(self.ctx.origin(self.span)) is not False:
            self.walker.base_check.at(self.ctx, self.span).reduce(residual)
        else:
            self.walker.may_fail(residual, self.span, self.ctx)


class DefaultsReducer(_Located, BaseReducer):
    """Evaluates residual values under the given arguments and defaults, reporting failures.

    A condition that depends on arguments is explored both ways; with the arguments as
    given (defaults for the rest) it must still be valid, or ros2 launch fails right away.
    """

    prefix = "with the default arguments, "
    contextual = True  # an includer passes other values: reported where launched directly
    with_defaults = True

    def __init__(self, walker: Walker) -> None:
        BaseReducer.__init__(self, walker.graph.inputs())
        _Located.__init__(self, walker)


def fill_unset(value: s.Sub, fill: s.Sub) -> s.Sub:
    """Replace the "unset" branches of a path-dependent value with ``fill``."""
    if isinstance(value, Unset):
        return fill
    if isinstance(value, Select) and is_unset(value):  # a branch never unset stays as it is
        then = fill_unset(value.then, fill)
        return Select(value.guards, then, fill_unset(value.otherwise, fill))
    return value
