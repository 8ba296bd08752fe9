"""The variables of a CMake file as it runs, and what its words expand to.

Every reader of ``CMakeLists.txt`` expands words here, so ``${PROJECT_NAME}`` or a list
means the same to all of them. A value this is not sure of is unknown (``None``), never
guessed: one set by a command not followed (``string``, ``file``) or from the
environment. Each branch of an ``if`` is read with the values it would see; after
``endif`` a variable keeps the value all branches agree on, or the list of one that
holds all the others' items (every branch's items count, as every branch's commands
do), else it is unknown. A variable never set here is unknown when expanded
(``find_package`` or ``include`` may have set it), but a list the file appends to
starts empty, as CMake's does. A list may hold unknown items among known ones
(``set(NODES talker ${EXTRA})``, a function's ``ARGN``). Whatever is built from an
unknown value is left out, or marks its reader's answer incomplete.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from launchverify.workspace.cmake_words import Argument

# What ${CMAKE_INSTALL_PREFIX} expands to: a destination below it is told apart.
PREFIX = "\x01CMAKE_INSTALL_PREFIX\x01"
UNKNOWN_ITEM = "\x00"  # an item of a variable's list that is not known
_VARIABLE = re.compile(r"\$\{([A-Za-z0-9_./+\-]*)\}")
_LIST_SEPARATOR = re.compile(r"(?<!\\);")


def builtins(folder: Path) -> dict[str, str]:
    """Return the variables CMake has set when it starts reading a ``CMakeLists.txt``."""
    text = str(folder)
    return {"CMAKE_CURRENT_SOURCE_DIR": text, "CMAKE_CURRENT_LIST_DIR": text,
            "PROJECT_SOURCE_DIR": text, "CMAKE_SOURCE_DIR": text,
            "CMAKE_INSTALL_PREFIX": PREFIX}


@dataclass
class Scope:
    """One variable scope: a ``CMakeLists.txt`` or a function call, and its folder."""

    folder: Path
    variables: dict[str, str | None]  # None: set, to a value not known here
    parent: Scope | None = None  # whose variables ``set(... PARENT_SCOPE)`` sets
    branches: list[_Branches] = field(default_factory=list)  # the blocks it is inside

    def expand(self, text: str) -> str | None:
        """Return ``text`` with its ``${...}`` expanded (innermost first); ``None`` if unknown."""
        for _ in range(16):
            match = _VARIABLE.search(text)  # ${${X}}: the inner one first
            if match is None:
                break
            value = self.variables.get(match.group(1))
            if value is None:
                return None
            text = text[:match.start()] + value + text[match.end():]
        if "${" in text or "$ENV{" in text or "$CACHE{" in text or "$<" in text:
            return None
        return text

    def argument(self, argument: Argument) -> list[str | None]:
        """Return the words one argument passes (an unquoted one is a list of them).

        An unknown one is ``None``, which stands for what may be any number of words.
        """
        expanded = argument.text if argument.bracket else self.expand(argument.text)
        if expanded is None:
            return [None]
        if argument.quoted:
            return [None if UNKNOWN_ITEM in expanded else expanded.replace("\\;", ";")]
        return items(expanded)

    def each(self, arguments: tuple[Argument, ...]) -> list[str | None]:
        """Return the words of the arguments, ``None`` in place of each unknown one."""
        return [word for argument in arguments for word in self.argument(argument)]

    def words(self, arguments: tuple[Argument, ...]) -> list[str] | None:
        """Return the words of the arguments as CMake passes them; ``None`` if one is unknown."""
        out: list[str] = []
        for word in self.each(arguments):
            if word is None:
                return None
            out.append(word)
        return out

    def assign(self, variable: str, value: str | None) -> None:
        """Set a variable (``None``: to a value not known)."""
        self.variables[variable] = value

    # ------------------------------------------------------------------ branches

    def open_branches(self) -> None:
        """Start an ``if`` (or a ``while`` or loop run once): its first branch."""
        self.branches.append(_Branches(dict(self.variables)))

    def next_branch(self, otherwise: bool) -> None:
        """Start the next branch (``elseif``, or ``else``), from the values before the block."""
        if self.branches:
            block = self.branches[-1]
            block.ends.append(self.variables)
            block.otherwise = block.otherwise or otherwise
            self.variables = dict(block.before)

    def close_branches(self) -> None:
        """End the block: each variable keeps the value all its branches agree on."""
        if not self.branches:
            return
        block = self.branches.pop()
        ends = [*block.ends, self.variables]
        if not block.otherwise:
            ends.append(block.before)  # no branch taken
        self.variables = {}
        for name in {name for end in ends for name in end}:
            if any(name not in end for end in ends):
                self.variables[name] = None  # set by some branch only
            else:
                self.variables[name] = _agreed([end[name] for end in ends])

    def path(self, word: str) -> Path:
        """Return a path as CMake takes it: relative to the current ``CMakeLists.txt``."""
        written = Path(word)
        return written if written.is_absolute() else self.folder / written


@dataclass
class _Branches:
    """An ``if`` block being read: the values before it, and at the end of each branch."""

    before: dict[str, str | None]
    ends: list[dict[str, str | None]] = field(default_factory=list)
    otherwise: bool = False  # an else() branch: some branch is always taken


def _agreed(values: list[str | None]) -> str | None:
    """Return the value branches agree on: the same, or the list holding all the others'."""
    if len(set(values)) == 1:
        return values[0]
    if None in values or any(UNKNOWN_ITEM in value for value in values if value):
        return None
    lists = [[item for item in value.split(";") if item] for value in values if value is not None]
    widest = max(lists, key=len)
    return ";".join(widest) if all(set(items) <= set(widest) for items in lists) else None


def items(value: str) -> list[str | None]:
    """Return the items of a CMake list, ``None`` for each unknown one."""
    return [None if UNKNOWN_ITEM in item else item.replace("\\;", ";")
            for item in _LIST_SEPARATOR.split(value) if item]


def joined(words: list[str | None]) -> str:
    """Return words as one CMake list, an unknown one as ``UNKNOWN_ITEM``."""
    return ";".join(UNKNOWN_ITEM if word is None else word for word in words)
