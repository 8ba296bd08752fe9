"""Substitution expressions: what ``$(...)`` and launch's Substitution classes denote.

They stay expressions, never strings, so later stages can evaluate them under concrete
arguments or reason about them symbolically. One record per substitution of ROS 2 launch
and launch_ros; ``describe()`` prints the frontend spelling used in messages.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from launchverify.span import Span


class Sub:
    """Base of every substitution expression (immutable, compared by value)."""

    __slots__ = ()

    def describe(self) -> str:
        """Return the expression in ``$(...)`` frontend syntax."""
        raise NotImplementedError

    def children(self) -> tuple[Sub, ...]:
        """Return the direct sub-expressions, for generic walks."""
        return ()


_PLAIN_ARG = re.compile(r"[^\s'\"()\\$]+")


def _quote_text(text: str) -> str:
    """Escape literal text for use inside a single-quoted substitution argument."""
    return text.replace("\\", "\\\\").replace("'", "\\'").replace("$(", "\\$(")


def _arg(sub: Sub) -> str:
    """Spell one substitution argument so that the frontend grammar reads it back.

    The grammar has no spelling for a quoted argument holding a substitution whose own
    argument needs quotes (``$(var 'a $(var 'b c')')``); such expressions are shown as
    display text that does not read back.
    """
    parts = sub.parts if isinstance(sub, Concat) else (sub,)
    if all(not isinstance(p, Text) or _PLAIN_ARG.fullmatch(p.text) for p in parts) and parts != (
        Text(""),
    ):
        return "".join(p.describe() for p in parts)
    return "'" + "".join(
        _quote_text(p.text) if isinstance(p, Text) else p.describe() for p in parts
    ) + "'"


def _call(name: str, *args: Sub | None) -> str:
    shown = [_arg(a) for a in args if a is not None]
    return "$(" + " ".join([name, *shown]) + ")"


@dataclass(frozen=True, slots=True)
class Text(Sub):
    """Literal text.

    ``where``: the exact place of the text in the user's file, when a frontend read it
    there verbatim (each character of ``text`` at the next column, on one line: no escape,
    no entity, no quote inside). A fix may replace that span; not part of the value.
    """

    text: str
    where: Span | None = field(default=None, compare=False, repr=False)

    def describe(self) -> str:
        return self.text.replace("\\", "\\\\").replace("$(", "\\$(")


@dataclass(frozen=True, slots=True)
class Concat(Sub):
    """Parts performed one by one and joined with no separator."""

    parts: tuple[Sub, ...]

    def describe(self) -> str:
        return "".join(p.describe() for p in self.parts)

    def children(self) -> tuple[Sub, ...]:
        return self.parts


@dataclass(frozen=True, slots=True)
class LaunchConfig(Sub):
    """``$(var name [default])`` / ``LaunchConfiguration``.

    ``where``: the expression that created it in a Python file (a finding about the read
    points there, not at the action using it); not part of the value.
    """

    name: Sub
    default: Sub | None = None
    where: Span | None = field(default=None, compare=False, repr=False)

    def describe(self) -> str:
        return _call("var", self.name, self.default)

    def children(self) -> tuple[Sub, ...]:
        return tuple(s for s in (self.name, self.default) if s is not None)


@dataclass(frozen=True, slots=True)
class EnvVar(Sub):
    """``$(env NAME [default])`` / ``EnvironmentVariable``."""

    name: Sub
    default: Sub | None = None

    def describe(self) -> str:
        return _call("env", self.name, self.default)

    def children(self) -> tuple[Sub, ...]:
        return tuple(s for s in (self.name, self.default) if s is not None)


@dataclass(frozen=True, slots=True)
class PythonExpr(Sub):
    """``$(eval expression [modules])`` / ``PythonExpression``."""

    expression: Sub
    modules: Sub | None = None

    def describe(self) -> str:
        return _call("eval", self.expression, self.modules)

    def children(self) -> tuple[Sub, ...]:
        return tuple(s for s in (self.expression, self.modules) if s is not None)


@dataclass(frozen=True, slots=True)
class Command(Sub):
    """``$(command cmd [on_stderr])``: the stdout of a program; never run statically."""

    command: Sub
    on_stderr: Sub | None = None

    def describe(self) -> str:
        return _call("command", self.command, self.on_stderr)

    def children(self) -> tuple[Sub, ...]:
        return tuple(s for s in (self.command, self.on_stderr) if s is not None)


@dataclass(frozen=True, slots=True)
class FindExecutable(Sub):
    """``$(find-exec name)``: a PATH lookup on the machine that runs the launch."""

    name: Sub

    def describe(self) -> str:
        return _call("find-exec", self.name)

    def children(self) -> tuple[Sub, ...]:
        return (self.name,)


@dataclass(frozen=True, slots=True)
class FindPackageShare(Sub):
    """``$(find-pkg-share pkg)``."""

    package: Sub

    def describe(self) -> str:
        return _call("find-pkg-share", self.package)

    def children(self) -> tuple[Sub, ...]:
        return (self.package,)


@dataclass(frozen=True, slots=True)
class FindPackagePrefix(Sub):
    """``$(find-pkg-prefix pkg)``."""

    package: Sub

    def describe(self) -> str:
        return _call("find-pkg-prefix", self.package)

    def children(self) -> tuple[Sub, ...]:
        return (self.package,)


@dataclass(frozen=True, slots=True)
class ExecutableInPackage(Sub):
    """``$(exec-in-pkg exe pkg)``: note the executable comes first."""

    executable: Sub
    package: Sub

    def describe(self) -> str:
        return _call("exec-in-pkg", self.executable, self.package)

    def children(self) -> tuple[Sub, ...]:
        return (self.executable, self.package)


@dataclass(frozen=True, slots=True)
class ThisLaunchFile(Sub):
    """``$(filename)``: path of the launch file being executed."""

    def describe(self) -> str:
        return "$(filename)"


@dataclass(frozen=True, slots=True)
class ThisLaunchFileDir(Sub):
    """``$(dirname)``: folder of the launch file being executed."""

    def describe(self) -> str:
        return "$(dirname)"


@dataclass(frozen=True, slots=True)
class LaunchLogDir(Sub):
    """``$(launch_log_dir)`` / ``$(log_dir)``."""

    def describe(self) -> str:
        return "$(log_dir)"


@dataclass(frozen=True, slots=True)
class AnonName(Sub):
    """``$(anon name)``: a unique name per launch run."""

    name: Sub

    def describe(self) -> str:
        return _call("anon", self.name)

    def children(self) -> tuple[Sub, ...]:
        return (self.name,)


@dataclass(frozen=True, slots=True)
class NotSub(Sub):
    """``$(not value)``."""

    value: Sub

    def describe(self) -> str:
        return _call("not", self.value)

    def children(self) -> tuple[Sub, ...]:
        return (self.value,)


@dataclass(frozen=True, slots=True)
class AndSub(Sub):
    """``$(and left right)``."""

    left: Sub
    right: Sub

    def describe(self) -> str:
        return _call("and", self.left, self.right)

    def children(self) -> tuple[Sub, ...]:
        return (self.left, self.right)


@dataclass(frozen=True, slots=True)
class OrSub(Sub):
    """``$(or left right)``."""

    left: Sub
    right: Sub

    def describe(self) -> str:
        return _call("or", self.left, self.right)

    def children(self) -> tuple[Sub, ...]:
        return (self.left, self.right)


@dataclass(frozen=True, slots=True)
class AnySub(Sub):
    """``$(any a b ...)``."""

    args: tuple[Sub, ...]

    def describe(self) -> str:
        return _call("any", *self.args)

    def children(self) -> tuple[Sub, ...]:
        return self.args


@dataclass(frozen=True, slots=True)
class AllSub(Sub):
    """``$(all a b ...)``."""

    args: tuple[Sub, ...]

    def describe(self) -> str:
        return _call("all", *self.args)

    def children(self) -> tuple[Sub, ...]:
        return self.args


@dataclass(frozen=True, slots=True)
class EqualsSub(Sub):
    """``$(equals a b)``: boolean-, then number-, then string-equality."""

    left: Sub
    right: Sub

    def describe(self) -> str:
        return _call("equals", self.left, self.right)

    def children(self) -> tuple[Sub, ...]:
        return (self.left, self.right)


@dataclass(frozen=True, slots=True)
class NotEqualsSub(Sub):
    """``$(not-equals a b)``."""

    left: Sub
    right: Sub

    def describe(self) -> str:
        return _call("not-equals", self.left, self.right)

    def children(self) -> tuple[Sub, ...]:
        return (self.left, self.right)


@dataclass(frozen=True, slots=True)
class IfElse(Sub):
    """``$(if cond [then] [else])``."""

    condition: Sub
    if_value: Sub
    else_value: Sub

    def describe(self) -> str:
        return _call("if", self.condition, self.if_value, self.else_value)

    def children(self) -> tuple[Sub, ...]:
        return (self.condition, self.if_value, self.else_value)


@dataclass(frozen=True, slots=True)
class FileContent(Sub):
    """``$(file-content path)``."""

    path: Sub

    def describe(self) -> str:
        return _call("file-content", self.path)

    def children(self) -> tuple[Sub, ...]:
        return (self.path,)


@dataclass(frozen=True, slots=True)
class RosParameter(Sub):
    """``$(param name [default])``: the first SetParameter of that name in scope."""

    name: Sub
    default: Sub | None = None

    def describe(self) -> str:
        return _call("param", self.name, self.default)

    def children(self) -> tuple[Sub, ...]:
        return tuple(s for s in (self.name, self.default) if s is not None)


@dataclass(frozen=True, slots=True)
class ForEachVar(Sub):
    """``$(for-var name [default])`` (kilted, rolling)."""

    name: Sub
    default: Sub | None = None

    def describe(self) -> str:
        return _call("for-var", self.name, self.default)

    def children(self) -> tuple[Sub, ...]:
        return tuple(s for s in (self.name, self.default) if s is not None)


@dataclass(frozen=True, slots=True)
class ForLoopIndex(Sub):
    """``$(index name)`` (kilted, rolling)."""

    name: Sub

    def describe(self) -> str:
        return _call("index", self.name)

    def children(self) -> tuple[Sub, ...]:
        return (self.name,)


@dataclass(frozen=True, slots=True)
class StringJoin(Sub):
    """``$(string-join delimiter parts...)`` / ``StringJoinSubstitution``."""

    delimiter: Sub
    parts: tuple[Sub, ...]

    def describe(self) -> str:
        return _call("string-join", self.delimiter, *self.parts)

    def children(self) -> tuple[Sub, ...]:
        return (self.delimiter, *self.parts)


@dataclass(frozen=True, slots=True)
class PathJoin(Sub):
    """``PathJoinSubstitution``: ``os.path.join`` of the parts (Python only)."""

    parts: tuple[Sub, ...]

    def describe(self) -> str:
        return "/".join(p.describe() for p in self.parts)

    def children(self) -> tuple[Sub, ...]:
        return self.parts


@dataclass(frozen=True, slots=True)
class LocalSub(Sub):
    """``LocalSubstitution``: a value from ``context.locals`` (e.g. ``event.returncode``)."""

    expression: str

    def describe(self) -> str:
        return f"$(local {self.expression})"


@dataclass(frozen=True, slots=True)
class Rewritten(Sub):
    """A file a helper rewrites at launch time (nav2's ``RewrittenYaml``, ``ReplaceString``).

    Its path stands for its ``source`` file's; ``inputs`` are the values the rewrite reads
    (so their configurations count as used). For ``RewrittenYaml``, ``params`` are its
    ``param_rewrites`` (a key, or a dotted path, and the value it gets), ``root_key``
    the key its content moves under, ``values`` its ``value_rewrites`` (a value as text,
    and what replaces it), ``convert`` its ``convert_types``; ``exact`` is false when it
    also rewrites what launchverify does not follow (``key_rewrites``, a key that is not
    text).
    """

    source: Sub
    inputs: tuple[Sub, ...]
    description: str
    root_key: Sub | None = None
    params: tuple[tuple[str, Sub], ...] = ()
    values: tuple[tuple[str, Sub], ...] = ()
    exact: bool = True
    convert: bool = False

    def describe(self) -> str:
        return f"{self.description}({self.source.describe()})"

    def children(self) -> tuple[Sub, ...]:
        root = () if self.root_key is None else (self.root_key,)
        rewrites = (value for _, value in (*self.params, *self.values))
        return (self.source, *self.inputs, *rewrites, *root)


@dataclass(frozen=True, slots=True)
class AsBool(Sub):
    """nav2's ``LaunchConfigAsBool``: ``True`` for true/1/yes/on (any case), else ``False``."""

    value: Sub

    def describe(self) -> str:
        return f"AsBool({self.value.describe()})"

    def children(self) -> tuple[Sub, ...]:
        return (self.value,)


@dataclass(frozen=True, slots=True)
class Opaque(Sub):
    """A value launchverify cannot model (an arbitrary Python object or call)."""

    description: str

    def describe(self) -> str:
        text = self.description
        return text if text.startswith("<") and text.endswith(">") else f"<{text}>"


@dataclass(frozen=True, slots=True)
class PackageLookup(Opaque):
    """A folder of a package Python code looked up and nothing found (``package``)."""

    package: str = ""


@dataclass(frozen=True, slots=True)
class Raises(Sub):
    """A value launch raises on when it performs it, not before (``error`` says what).

    Launch takes some values as they are and normalizes them only when the action
    executes: an include's arguments (``SetLaunchConfiguration`` in ``execute``), a
    node's name. A value it rejects then fails only where the action runs, under its
    condition: the evaluator reports it on that path, never as the file failing to load.
    """

    error: str

    def describe(self) -> str:
        return f"<raises {self.error}>"


EMPTY = Text("")


def concat(parts: list[Sub] | tuple[Sub, ...]) -> Sub:
    """Join parts into one expression, merging adjacent text and dropping empty text."""
    merged: list[Sub] = []
    for part in parts:
        flat = part.parts if isinstance(part, Concat) else (part,)
        for item in flat:
            if isinstance(item, Text):
                if not item.text:
                    continue
                if merged and isinstance(merged[-1], Text):
                    merged[-1] = Text(merged[-1].text + item.text)
                    continue
            merged.append(item)
    if not merged:
        return EMPTY
    if len(merged) == 1:
        return merged[0]
    return Concat(tuple(merged))


def written_at(sub: Sub | None) -> Span | None:
    """Return where a literal value is written verbatim in its file, if a frontend knows."""
    return sub.where if isinstance(sub, Text) else None


def tail_at(sub: Sub, tail: str) -> Span | None:
    """Return where the last characters of an expression, ``tail``, are written verbatim.

    The expression must end with a literal that ends with ``tail`` (the file name at the
    end of a path) and that the frontend located; ``tail`` may not span lines.
    """
    last = sub
    while isinstance(last, (Concat, PathJoin)) and last.parts:  # a path's last component
        last = last.parts[-1]
    where = written_at(last)
    if (where is None or where.end_line is None or where.end_column is None or not tail
            or "\n" in tail or not isinstance(last, Text) or not last.text.endswith(tail)):
        return None
    column = where.end_column - len(tail)
    if column < 1 or (where.end_line == where.line and column < where.column):
        return None
    return Span(where.file, where.end_line, column, where.end_line, where.end_column)


def walk(sub: Sub) -> list[Sub]:
    """Return ``sub`` and every expression below it, depth first."""
    out: list[Sub] = []
    stack = [sub]
    while stack:
        item = stack.pop()
        out.append(item)
        stack.extend(reversed(item.children()))
    return out
