r"""The ``$(...)`` substitution grammar of the ROS 2 XML and YAML frontends.

A hand-written reader of the same language as ros2/launch's ``grammar.lark``: outside a
substitution any text is literal (``\\x`` escapes ``x``); a substitution is ``$(name``,
arguments each preceded by exactly one space, and ``)``. An argument is a run of unquoted
text and nested substitutions, or a single- or double-quoted string in which spaces and
nested substitutions are allowed. Unknown names and wrong argument counts are errors at
parse time, as in launch.
"""

from __future__ import annotations

import contextlib
import re
from collections.abc import Callable
from dataclasses import dataclass

from launchverify.ir import subst as s
from launchverify.span import Span

MAX_DEPTH = 64


class SubstitutionSyntaxError(ValueError):
    """A ``$(...)`` expression that launch would refuse to parse; ``offset`` is 0-based."""

    def __init__(self, message: str, offset: int) -> None:
        super().__init__(message)
        self.offset = offset


Builder = Callable[[list[s.Sub]], s.Sub]
Locate = Callable[[int, int], Span | None]  # offsets in the text -> where they are written


@dataclass(frozen=True)
class _Spec:
    low: int
    high: int | None
    build: Builder


def _opt(args: list[s.Sub], index: int) -> s.Sub | None:
    return args[index] if len(args) > index else None


SUBSTITUTIONS: dict[str, _Spec] = {
    "var": _Spec(1, 2, lambda a: s.LaunchConfig(a[0], _opt(a, 1))),
    "env": _Spec(1, 2, lambda a: s.EnvVar(a[0], _opt(a, 1))),
    "eval": _Spec(1, 2, lambda a: s.PythonExpr(a[0], _opt(a, 1))),
    "command": _Spec(1, 2, lambda a: s.Command(a[0], _opt(a, 1))),
    "find-exec": _Spec(1, 1, lambda a: s.FindExecutable(a[0])),
    "find-pkg-share": _Spec(1, 1, lambda a: s.FindPackageShare(a[0])),
    "find-pkg-prefix": _Spec(1, 1, lambda a: s.FindPackagePrefix(a[0])),
    "exec-in-pkg": _Spec(2, 2, lambda a: s.ExecutableInPackage(a[0], a[1])),
    "filename": _Spec(0, 0, lambda a: s.ThisLaunchFile()),
    "dirname": _Spec(0, 0, lambda a: s.ThisLaunchFileDir()),
    "launch_log_dir": _Spec(0, 0, lambda a: s.LaunchLogDir()),
    "log_dir": _Spec(0, 0, lambda a: s.LaunchLogDir()),
    "anon": _Spec(1, 1, lambda a: s.AnonName(a[0])),
    "not": _Spec(1, 1, lambda a: s.NotSub(a[0])),
    "and": _Spec(2, 2, lambda a: s.AndSub(a[0], a[1])),
    "or": _Spec(2, 2, lambda a: s.OrSub(a[0], a[1])),
    "any": _Spec(0, None, lambda a: s.AnySub(tuple(a))),
    "all": _Spec(0, None, lambda a: s.AllSub(tuple(a))),
    "equals": _Spec(2, 2, lambda a: s.EqualsSub(a[0], a[1])),
    "not-equals": _Spec(2, 2, lambda a: s.NotEqualsSub(a[0], a[1])),
    "if": _Spec(2, 3, lambda a: s.IfElse(a[0], a[1], _opt(a, 2) or s.EMPTY)),
    "file-content": _Spec(1, 1, lambda a: s.FileContent(a[0])),
    "param": _Spec(1, 2, lambda a: s.RosParameter(a[0], _opt(a, 1))),
    "for-var": _Spec(1, 2, lambda a: s.ForEachVar(a[0], _opt(a, 1))),
    "index": _Spec(1, 1, lambda a: s.ForLoopIndex(a[0])),
    "string-join": _Spec(2, None, lambda a: s.StringJoin(a[0], tuple(a[1:]))),
}

# ROS 1 spellings users carry over; named in the error so the fix is obvious.
ROS1_HINTS = {
    "arg": "var",
    "optenv": "env NAME default",
    "find": "find-pkg-share",
}


def _arity_text(spec: _Spec) -> str:
    if spec.high is None:
        return f"at least {spec.low}"
    if spec.low == spec.high:
        return str(spec.low)
    return f"{spec.low} to {spec.high}"


def parse_substitution(text: str, locate: Locate | None = None) -> s.Sub:
    """Parse an attribute value into a substitution expression.

    ``locate`` says where a stretch of ``text`` is written in its file; literal parts
    written verbatim (no escape) then carry their place (``Text.where``), for fixes.

    Raises:
        SubstitutionSyntaxError: for text that ros2 launch would refuse.

    Examples:
        >>> parse_substitution("$(var ns)/robot").describe()
        '$(var ns)/robot'
    """
    reader = _Reader(text, locate)
    parts: list[s.Sub] = []
    literal: list[str] = []
    start = reader.pos
    while not reader.done():
        if reader.at_substitution():
            parts.append(reader.literal(literal, start))
            literal = []
            parts.append(reader.substitution(0, quote=None))
            start = reader.pos
        else:
            literal.append(reader.literal_run())
    parts.append(reader.literal(literal, start))
    return s.concat(parts)


def unescape(text: str) -> str:
    """Remove backslash escapes, as launch does for names, descriptions and choices."""
    out: list[str] = []
    index = 0
    while index < len(text):
        if text[index] == "\\" and index + 1 < len(text):
            out.append(text[index + 1])
            index += 2
        else:
            out.append(text[index])
            index += 1
    return "".join(out)


def variable_references(text: str) -> list[tuple[str, int, int]]:
    """Return ``(name, start, end)`` of each ``$(var name ...)`` in text (0-based, end exclusive).

    For pointing at references in a line as written (``if="$(var sim)"``), where an editor
    asks what is under the cursor: the text around substitutions may be anything, and a
    substitution launch would refuse (one being typed) is skipped, not an error. Names
    that are themselves substitutions are left out.

    Examples:
        >>> variable_references('ns="$(var robot)/$(var arm)"')
        [('robot', 4, 16), ('arm', 17, 27)]
    """
    found: set[tuple[str, int, int]] = set()
    start = text.find("$(")
    while start >= 0:
        escapes = len(text[:start]) - len(text[:start].rstrip("\\"))
        if escapes % 2 == 0:  # ``\$(`` is literal text
            reader = _Reader(text, variables=found)
            reader.pos = start
            with contextlib.suppress(SubstitutionSyntaxError):
                reader.substitution(0, quote=None)
        start = text.find("$(", start + 2)
    return sorted(found, key=lambda ref: (ref[1], ref[2]))


# Runs of characters that an argument reads one by one with the same outcome: none ends
# it, starts a substitution, escapes or is refused (keyed by the quote it is inside).
_PLAIN_ARGUMENT = {quote: re.compile("[^" + re.escape(" )($\\" + (quote or "'\"")) + "]+")
                   for quote in (None, "'", '"')}
_PLAIN_QUOTED = {quote: re.compile("[^" + re.escape("$\\" + quote) + "]+")
                 for quote in ("'", '"')}


# The rest of a substitution's name: what ``str.isalnum`` accepts, ``_`` and ``-``
# (``\w`` is exactly the characters ``isalnum`` accepts and ``_``).
_NAME_REST = re.compile(r"[\w-]*")


class _Reader:
    def __init__(self, text: str, locate: Locate | None = None,
                 variables: set[tuple[str, int, int]] | None = None) -> None:
        self.text = text
        self.pos = 0
        self.locate = locate
        self.variables = variables  # where ``$(var name)`` is, when asked

    def literal(self, chars: list[str], start: int) -> s.Text:
        """Return the literal read since ``start``, located when written without escapes."""
        text = "".join(chars)
        where = None
        if self.locate is not None and text and self.pos - start == len(text):
            where = self.locate(start, self.pos)
        return s.Text(text, where)

    def done(self) -> bool:
        return self.pos >= len(self.text)

    def peek(self, offset: int = 0) -> str:
        index = self.pos + offset
        return self.text[index] if index < len(self.text) else ""

    def at_substitution(self) -> bool:
        return self.peek() == "$" and self.peek(1) == "("

    def literal_run(self) -> str:
        """Read literal text up to the next ``$`` or escape (at least one character).

        Attribute values are mostly plain text: reading it a run at a time instead of a
        character at a time is most of what parsing them costs.
        """
        if self.peek() in ("$", "\\"):
            return self.literal_char(stop="")
        end = len(self.text)
        for mark in ("$", "\\"):
            found = self.text.find(mark, self.pos)
            if found != -1:
                end = min(end, found)
        run = self.text[self.pos:end]
        self.pos = end
        return run

    def literal_char(self, stop: str) -> str:
        """Read one literal character (an escape pair counts as one), honouring ``stop``."""
        char = self.peek()
        if char == "\\" and self.pos + 1 < len(self.text):
            self.pos += 2
            return self.text[self.pos - 1]
        if char in stop:
            raise SubstitutionSyntaxError(f"unexpected {char!r}", self.pos)
        self.pos += 1
        return char

    def substitution(self, depth: int, quote: str | None) -> s.Sub:
        """Read ``$(name args...)`` starting at ``$``."""
        if depth > MAX_DEPTH:
            raise SubstitutionSyntaxError("substitutions nested too deeply", self.pos)
        start = self.pos
        self.pos += 2
        name_start = self.pos
        if not self.peek().isalpha():
            raise SubstitutionSyntaxError("expected a substitution name after '$('", self.pos)
        self.pos = _NAME_REST.match(self.text, self.pos + 1).end()  # type: ignore[union-attr]
        name = self.text[name_start : self.pos]
        args: list[s.Sub] = []
        while self.peek() == " ":
            self.pos += 1
            if self.peek() in (" ", ")", ""):
                raise SubstitutionSyntaxError(
                    "arguments must be separated by exactly one space", self.pos
                )
            args.append(self.argument(depth, quote))
        if self.peek() != ")":
            if self.done():
                raise SubstitutionSyntaxError(f"unclosed substitution $({name}", start)
            raise SubstitutionSyntaxError(
                f"unexpected {self.peek()!r} in substitution $({name}", self.pos
            )
        self.pos += 1
        spec = SUBSTITUTIONS.get(name)
        if spec is None:
            hint = ROS1_HINTS.get(name)
            extra = f" (ROS 1 spelling; ROS 2 uses $({hint}))" if hint else ""
            raise SubstitutionSyntaxError(f"unknown substitution $({name}){extra}", start)
        if len(args) < spec.low or (spec.high is not None and len(args) > spec.high):
            raise SubstitutionSyntaxError(
                f"$({name}) expects {_arity_text(spec)} argument(s), got {len(args)}", start
            )
        if self.variables is not None and name == "var" and isinstance(args[0], s.Text):
            self.variables.add((args[0].text, start, self.pos))
        return spec.build(args)

    def argument(self, depth: int, quote: str | None) -> s.Sub:
        """Read one argument: quoted string, or unquoted text mixed with substitutions."""
        if quote is None and self.peek() in ("'", '"'):
            return self.quoted(depth, self.peek())
        stop = " '\"()" if quote is None else f" {quote}()"
        plain = _PLAIN_ARGUMENT[quote]
        parts: list[s.Sub] = []
        literal: list[str] = []
        start = self.pos
        while not self.done() and self.peek() not in (" ", ")"):
            run = plain.match(self.text, self.pos)
            if run is not None:  # a stretch with no character of note: taken whole
                literal.append(run.group())
                self.pos = run.end()
            elif self.at_substitution():
                parts.append(self.literal(literal, start))
                literal = []
                parts.append(self.substitution(depth + 1, quote))
                start = self.pos
            else:
                literal.append(self.literal_char(stop))
        parts.append(self.literal(literal, start))
        return s.concat(parts)

    def quoted(self, depth: int, quote: str) -> s.Sub:
        """Read ``'...'`` or ``"..."``: spaces allowed, nested substitutions still parsed."""
        start = self.pos
        self.pos += 1
        parts: list[s.Sub] = []
        literal: list[str] = []
        run = self.pos
        while True:
            if self.done():
                raise SubstitutionSyntaxError("unclosed quote", start)
            if self.peek() == quote:
                parts.append(self.literal(literal, run))
                self.pos += 1
                break
            plain = _PLAIN_QUOTED[quote].match(self.text, self.pos)
            if plain is not None:
                literal.append(plain.group())
                self.pos = plain.end()
            elif self.at_substitution():
                parts.append(self.literal(literal, run))
                literal = []
                parts.append(self.substitution(depth + 1, quote))
                run = self.pos
            else:
                literal.append(self.literal_char(stop=""))
        if self.peek() not in (" ", ")", ""):
            raise SubstitutionSyntaxError("a quoted argument must stand alone", self.pos)
        return s.concat(parts)
