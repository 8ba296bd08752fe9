"""CMake's syntax, read exactly enough to know each command and its arguments.

``CMakeLists.txt`` is read for what a build installs, and a misread word decides what a
launch file may import. So comments (``#`` and ``#[[...]]``), quoted arguments (their
escapes, the ``#`` and ``)`` inside them), bracket arguments (``[=[...]=]``) and nested
parentheses are read as CMake reads them. A file CMake itself would refuse (an unclosed
parenthesis, quote or bracket, text that is not a command) gives ``None``: its build
fails, so it installs nothing launchverify may count on. Only reading: nothing runs.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from launchverify.workspace.reading import read_file

MAX_CMAKE_BYTES = 512 * 1024

_IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_OPEN_BRACKET = re.compile(r"\[(=*)\[")
_SPACE = " \t\r\n"
_ESCAPES = {"n": "\n", "t": "\t", "r": "\r", "0": "\0"}


@dataclass(frozen=True, slots=True)
class Argument:
    """One argument as written: ``quoted`` ones are one word, unquoted ones a list."""

    text: str
    quoted: bool = False
    bracket: bool = False  # ``[[...]]``: no variable is expanded inside


@dataclass(frozen=True, slots=True)
class Command:
    """One command invocation, its name lowered (CMake's names ignore case)."""

    name: str
    arguments: tuple[Argument, ...]
    line: int


def read_cmake(path: Path) -> list[Command] | None:
    """Return the commands of a CMake file; ``None`` if unreadable, too large or malformed."""
    try:
        data = read_file(path, prefix=MAX_CMAKE_BYTES + 1)
    except OSError:
        return None
    if len(data) > MAX_CMAKE_BYTES:
        return None  # a truncated file would be read wrong
    return commands(data.decode("utf-8", "replace"))


class _Malformed(Exception):
    """The file is not CMake: its build would stop at configuration."""


def commands(text: str) -> list[Command] | None:
    r"""Return the commands of a CMake file in order, or ``None`` if CMake would refuse it.

    Examples:
        >>> [(c.name, [a.text for a in c.arguments]) for c in commands(
        ...     'project(demo) # a (comment "\n'
        ...     'SET(X "a b)#c" [=[raw ${X}]=])')]
        [('project', ['demo']), ('set', ['X', 'a b)#c', 'raw ${X}'])]
        >>> commands('install(DIRECTORY a') is None
        True
    """
    try:
        return _Reader(text).read()
    except _Malformed:
        return None


class _Reader:
    def __init__(self, text: str) -> None:
        self.text = text
        self.at = 0
        self.line, self.counted = 1, 0  # the line at ``counted``, counted once

    def read(self) -> list[Command]:
        out: list[Command] = []
        while True:
            self.skip_space_and_comments()
            if self.at >= len(self.text):
                return out
            match = _IDENTIFIER.match(self.text, self.at)
            if match is None:
                raise _Malformed
            self.line += self.text.count("\n", self.counted, self.at)
            self.counted, line = self.at, self.line
            self.at = match.end()
            while self.at < len(self.text) and self.text[self.at] in " \t":
                self.at += 1
            if self.at >= len(self.text) or self.text[self.at] != "(":
                raise _Malformed
            self.at += 1
            out.append(Command(match.group().lower(), self.arguments(), line))

    def skip_space_and_comments(self) -> None:
        while self.at < len(self.text):
            char = self.text[self.at]
            if char in _SPACE:
                self.at += 1
            elif char == "#":
                self.comment()
            else:
                return

    def comment(self) -> None:
        """Skip a ``#`` comment: to the end of the line, or a bracket comment to its end."""
        bracket = _OPEN_BRACKET.match(self.text, self.at + 1)
        if bracket is not None:
            self.at = bracket.end()
            self.bracket_end(bracket.group(1))
            return
        end = self.text.find("\n", self.at)
        self.at = len(self.text) if end < 0 else end + 1

    def bracket_end(self, equals: str) -> str:
        """Return the text up to the closing ``]=*]`` of a bracket, and step past it."""
        closing = "]" + equals + "]"
        end = self.text.find(closing, self.at)
        if end < 0:
            raise _Malformed
        inside = self.text[self.at:end]
        self.at = end + len(closing)
        return inside

    def arguments(self) -> tuple[Argument, ...]:
        """Read the arguments after ``(`` up to the matching ``)``."""
        out: list[Argument] = []
        depth = 1
        while True:
            self.skip_space_and_comments()
            if self.at >= len(self.text):
                raise _Malformed
            char = self.text[self.at]
            if char == "(":
                depth += 1  # if((a) AND b): grouping, not a word
                self.at += 1
            elif char == ")":
                depth -= 1
                self.at += 1
                if depth == 0:
                    return tuple(out)
            elif char == '"':
                self.at += 1
                out.append(Argument(self.quoted(), quoted=True))
            elif (bracket := _OPEN_BRACKET.match(self.text, self.at)) is not None:
                self.at = bracket.end()
                inside = self.bracket_end(bracket.group(1))
                out.append(Argument(inside.removeprefix("\n"), quoted=True, bracket=True))
            else:
                out.append(Argument(self.unquoted()))

    def quoted(self) -> str:
        """Read a quoted argument after its opening quote (escapes and continuations)."""
        pieces: list[str] = []
        while self.at < len(self.text):
            char = self.text[self.at]
            self.at += 1
            if char == '"':
                return "".join(pieces)
            if char == "\\" and self.at < len(self.text):
                escaped = self.text[self.at]
                self.at += 1
                if escaped == "\n":
                    continue  # a line continuation
                pieces.append(_escape(escaped))
            else:
                pieces.append(char)
        raise _Malformed

    def unquoted(self) -> str:
        """Read an unquoted argument: up to a space, a parenthesis, a quote or a comment."""
        pieces: list[str] = []
        while self.at < len(self.text):
            char = self.text[self.at]
            if char in _SPACE or char in '()#"':
                break
            self.at += 1
            if char == "\\" and self.at < len(self.text):
                pieces.append(_escape(self.text[self.at]))
                self.at += 1
            else:
                pieces.append(char)
        return "".join(pieces)


def _escape(char: str) -> str:
    r"""Return what an escaped character stands for (``\\;`` keeps its list separator)."""
    if char == ";":
        return "\\;"
    return _ESCAPES.get(char, char)
