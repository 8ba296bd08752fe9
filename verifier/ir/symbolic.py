"""Residual values: what evaluation leaves when something is not known statically.

The evaluator reduces every substitution as far as the launch files allow. What depends on
launch arguments, the environment of the machine, or things outside the workspace stays as
an input leaf (``Arg``, ``EnvInput``, ``Unknown``); values that depend on which path was
taken become ``Select``. Path conditions are conjunctions of ``Guard``s. Later stages (the
SMT layer) give these a meaning over every argument assignment.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from launchverify.ir.subst import Opaque as SubOpaque
from launchverify.ir.subst import Sub, walk
from launchverify.span import Span


@dataclass(frozen=True, slots=True)
class Arg(Sub):
    """A launch argument set by the user: its command-line value if given, else ``default``.

    ``default`` is ``None`` for arguments declared without default (required inputs).
    """

    name: str
    default: Sub | None = None

    def describe(self) -> str:
        return f"$(var {self.name})"

    def children(self) -> tuple[Sub, ...]:
        return () if self.default is None else (self.default,)


@dataclass(frozen=True, slots=True)
class EnvInput(Sub):
    """An environment variable of the machine that runs the launch."""

    name: str
    default: Sub | None = None

    def describe(self) -> str:
        if self.default is None:
            return f"$(env {self.name})"
        return f"$(env {self.name} {self.default.describe() or chr(39) * 2})"

    def children(self) -> tuple[Sub, ...]:
        return () if self.default is None else (self.default,)


@dataclass(frozen=True, slots=True)
class Unknown(Sub):
    """A value that cannot be known statically (command output, a file outside the tree)."""

    reason: str

    def describe(self) -> str:
        return f"<{self.reason}>"


@dataclass(frozen=True, slots=True)
class CommandOutput(Unknown):
    """What ``$(command ...)`` prints: unknown statically; ``launchverify run`` runs it.

    ``command`` is the command line as far as it could be reduced.
    """

    command: Sub = field(default=None)  # type: ignore[assignment]
    on_stderr: Sub | None = None

    def children(self) -> tuple[Sub, ...]:
        return tuple(s for s in (self.command, self.on_stderr) if s is not None)


@dataclass(frozen=True, slots=True)
class ExecutablePath(Unknown):
    """Where ``$(exec-in-pkg)`` finds an executable: unknown, but which one is known."""

    executable: str = ""
    package: str = ""


@dataclass(frozen=True, slots=True)
class PackageFolder(Unknown):
    """A folder of a package found nowhere (its share or prefix): which package is known."""

    package: str = ""


@dataclass(frozen=True, slots=True)
class Unset(Sub):
    """No value: a configuration not set on some path (reading it fails at run time)."""

    name: str

    def describe(self) -> str:
        return f"<unset {self.name}>"


class Guard:
    """One boolean fact of a path condition."""

    __slots__ = ()

    def describe(self) -> str:
        """Return a readable form for messages and ``graph --symbolic``."""
        raise NotImplementedError


@dataclass(frozen=True, slots=True)
class Truthy(Guard):
    """The expression is ``true``/``1`` by the condition rule (``false``/``0`` if negated).

    ``where`` is the condition's place in a file (for explanations; not part of equality).
    """

    expression: Sub
    negate: bool = False
    where: Span | None = field(default=None, compare=False)

    def describe(self) -> str:
        text = self.expression.describe()
        return f"not {text}" if self.negate else text


@dataclass(frozen=True, slots=True)
class StrEquals(Guard):
    """Exact string equality (``LaunchConfigurationEquals``); ``right=None`` means unset."""

    left: Sub
    right: Sub | None
    negate: bool = False
    where: Span | None = field(default=None, compare=False)

    def describe(self) -> str:
        op = "!=" if self.negate else "=="
        right = "<unset>" if self.right is None else repr(self.right.describe())
        return f"{self.left.describe()} {op} {right}"


@dataclass(frozen=True, slots=True)
class Opaque(Guard):
    """A guard with no model (Python predicate, event that may never happen)."""

    description: str
    where: Span | None = field(default=None, compare=False)

    def describe(self) -> str:
        return f"<{self.description}>"


PathCondition = tuple[Guard, ...]


@dataclass(frozen=True, slots=True)
class Select(Sub):
    """``then`` when every guard holds, else ``otherwise``: a value that depends on the path."""

    guards: PathCondition
    then: Sub
    otherwise: Sub

    def describe(self) -> str:
        cond = " and ".join(g.describe() for g in self.guards)
        return f"({self.then.describe()} if {cond} else {self.otherwise.describe()})"

    def children(self) -> tuple[Sub, ...]:
        return (self.then, self.otherwise)


def describe_placed(guard: Guard) -> str:
    """Return a guard in backquotes, with where it is written (``a.launch.xml:3``)."""
    span: Span | None = getattr(guard, "where", None)
    return f"`{guard.describe()}`" + (f" ({span.short()})" if span is not None else "")


def describe_path(path: PathCondition) -> str | None:
    """Return the text of a path condition, or ``None`` when it always holds."""
    if not path:
        return None
    return " and ".join(g.describe() for g in path)


@dataclass(frozen=True, slots=True)
class NsPrefix(Sub):
    """launch_ros ``prefix_namespace(base, ns)`` when either side is not yet known.

    ``absolute`` also applies ``make_namespace_absolute``; ``base=None`` means no base.
    """

    base: Sub | None
    ns: Sub
    absolute: bool = True

    def describe(self) -> str:
        if self.base is None:
            text = self.ns.describe()
            return text if not self.absolute or text.startswith("/") else "/" + text
        return f"{self.base.describe().rstrip('/')}/{self.ns.describe()}"  # "/" + "x": "/x"

    def children(self) -> tuple[Sub, ...]:
        return (self.ns,) if self.base is None else (self.base, self.ns)


def rests_on_unknowns(guard: Guard) -> bool:
    """Return whether a guard's truth depends on what launchverify cannot know.

    An ``Opaque`` guard, or a condition over a value of code it does not see, of a file
    outside the tree or of the machine's environment: no error may claim that it holds
    (or does not), as the user's arguments do not decide it.
    """
    if isinstance(guard, Opaque):
        return True
    expressions: tuple[Sub | None, ...] = (
        (guard.expression,) if isinstance(guard, Truthy)
        else (guard.left, guard.right) if isinstance(guard, StrEquals) else ())
    return any(depends_on_unknowns(e) for e in expressions if e is not None)


def depends_on_unknowns(value: Sub) -> bool:
    """Return whether a value holds what launchverify cannot know (not the user's inputs)."""
    return any(isinstance(part, (Unknown, EnvInput, SubOpaque)) for part in walk(value))
