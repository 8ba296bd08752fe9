"""Runs a package's ``CMakeLists.txt`` as CMake would, for a reader that wants some commands.

What a build installs (Python modules, executables, targets) is written in commands
that may stand in a ``function`` called later, a ``foreach`` over a list, either branch
of an ``if`` or a subdirectory's file. This follows all of them once, the same way for
every reader: a function or macro body runs when it is called (its own scope, or the
caller's for a macro), a ``foreach`` runs its body for each item it can expand, every
branch of an ``if`` and one pass of a ``while`` run (a value they disagree on is unknown
after them, ``cmake_scope``), an unconditional ``return()`` ends the file or function,
and ``add_subdirectory`` inside the package reads that folder's file in a scope of its
own.

A subclass takes the commands it is about (``command``) and hears of what could not be
followed (``unfollowed``: a ``foreach`` over unknown items, a call too deep, a
subdirectory not read). Only reading: nothing runs, the limits bound a hostile file.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path

from launchverify.workspace import cmake_variables
from launchverify.workspace.cmake_scope import Scope, builtins, items, joined
from launchverify.workspace.cmake_words import Command, read_cmake
from launchverify.workspace.paths import resolved

MAX_CALL_DEPTH = 8
MAX_SUBDIRECTORIES = 32  # add_subdirectory followed per package, in all
MAX_SUBDIRECTORY_DEPTH = 4
# Steps per package: a command is one, copying the variables (at a branch, a call) one
# per variable; loops, calls and branches bounded together.
MAX_STEPS = 200_000
_BRANCHES = frozenset({"if", "elseif", "else", "endif", "while", "endwhile"})


@dataclass(frozen=True, slots=True)
class _Function:
    parameters: tuple[str, ...]
    body: tuple[Command, ...]
    macro: bool  # a macro runs in its caller's scope


class _Exhausted(Exception):
    """The package took more than ``MAX_STEPS``."""


class Reader:
    """Reads one package's CMake files; subclasses collect what the commands say."""

    def __init__(self, folder: Path, name: str | None = None,
                 variables: dict[str, str] | None = None) -> None:
        """Prepare to read ``folder``'s ``CMakeLists.txt``.

        ``name`` is the package's: ament_package() refuses a project named otherwise, so
        it stands for a ``project()`` whose name cannot be expanded.
        """
        self.folder = folder
        self.root = resolved(folder)  # nothing outside the package's real folder is read
        self.name = name
        self.start: dict[str, str | None] = {**builtins(folder), **(variables or {})}
        if name is not None:
            self.start["PROJECT_NAME"] = name
        self.functions: dict[str, _Function] = {}
        self.subdirectories = 0
        self.depth = 0  # of subdirectories
        self.calls = 0  # depth of function and macro calls
        self.budget = MAX_STEPS

    def read(self) -> bool:
        """Run the package's ``CMakeLists.txt``; ``False`` if CMake could not read it."""
        try:
            return self.run_file(Scope(self.folder, dict(self.start)))
        except _Exhausted:
            return True

    # ------------------------------------------------------------------ for subclasses

    def command(self, scope: Scope, command: Command) -> bool:
        """Take a command not run here (``install``, ``add_executable``); ``True`` if taken.

        A command not taken may set a variable its arguments name: it is forgotten.
        """
        return False

    def unfollowed(self, command: Command) -> None:
        """Hear of a command whose effect could not be followed."""

    def follows(self, folder: Path) -> bool:
        """Return whether to read ``add_subdirectory(folder)`` at all."""
        return True

    # ------------------------------------------------------------------ running

    def run_file(self, scope: Scope) -> bool:
        read = read_cmake(scope.folder / "CMakeLists.txt")
        if read is None:
            return False
        self.execute(scope, read)
        return True

    def execute(self, scope: Scope, commands: Sequence[Command]) -> bool:
        """Run commands in order; ``False`` once an unconditional ``return()`` ends them."""
        index = 0
        while index < len(commands):
            command = commands[index]
            index += 1
            name = command.name
            self.spend(command, len(scope.variables) if name in _BRANCHES else 1)
            if name in ("function", "macro", "foreach"):
                body, index = _block(commands, index, name)
                if name != "foreach":
                    self.define(scope, command, body)
                elif not self.loop(scope, command, body):
                    return False
            elif name in ("if", "while"):
                scope.open_branches()
            elif name in ("else", "elseif"):
                scope.next_branch(otherwise=name == "else")  # every branch is read
            elif name in ("endif", "endwhile"):
                scope.close_branches()
            elif name == "return":
                if not scope.branches:
                    return False
            elif not self.call(scope, command):
                return False
        return True

    def spend(self, command: Command, steps: int) -> None:
        self.budget -= steps
        if self.budget < 0:
            self.unfollowed(command)
            raise _Exhausted

    def call(self, scope: Scope, command: Command) -> bool:
        """Run one command; ``False`` when a macro's ``return()`` ends its caller."""
        name, arguments = command.name, command.arguments
        if (variables := cmake_variables.COMMANDS.get(name)) is not None:
            variables(scope, arguments)
        elif name == "project":
            cmake_variables.project(scope, arguments, self.name)
        elif name == "add_subdirectory":
            self.subdirectory(scope, command)
        elif name in self.functions:
            return self.invoke(scope, command, self.functions[name])
        elif not self.command(scope, command):
            for argument in arguments:  # string(... OUT), file(GLOB OUT ...): values lost
                if not argument.quoted:
                    scope.variables[argument.text] = None
        return True

    def define(self, scope: Scope, command: Command, body: tuple[Command, ...]) -> None:
        words = scope.words(command.arguments)
        if words:
            self.functions[words[0].lower()] = _Function(tuple(words[1:]), body,
                                                         command.name == "macro")

    def invoke(self, scope: Scope, command: Command, function: _Function) -> bool:
        """Call a function (a scope of its own) or a macro (its caller's)."""
        if self.calls >= MAX_CALL_DEPTH:
            self.unfollowed(command)
            return True
        self.spend(command, len(scope.variables))
        inner = scope if function.macro else Scope(scope.folder, dict(scope.variables), scope)
        bound = _arguments(function.parameters, scope.each(command.arguments))
        saved = _saved(inner, bound)
        inner.variables.update(bound)
        self.calls += 1
        try:
            finished = self.execute(inner, function.body)
        finally:
            self.calls -= 1
        if function.macro:
            _restore(inner, saved)
            return finished  # a macro's return() returns from where it was called
        return True

    def loop(self, scope: Scope, command: Command, body: tuple[Command, ...]) -> bool:
        """Run a ``foreach`` body for each item; once, uncertain, if they are unknown."""
        given = scope.each(command.arguments)
        variable = given[0] if given else None
        if variable is None:
            self.unfollowed(command)
            return True
        before = _saved(scope, [variable])
        items = _items(scope, given[1:])
        if items is None:
            self.unfollowed(command)
            self.spend(command, len(scope.variables))
            scope.variables[variable] = None
            scope.open_branches()
            self.execute(scope, body)  # what its body installs by literal names counts
            scope.close_branches()
        else:
            for item in items:
                scope.variables[variable] = item
                if not self.execute(scope, body):
                    return False
        _restore(scope, before)  # CMake restores the loop variable
        return True

    def subdirectory(self, scope: Scope, command: Command) -> None:
        """Follow ``add_subdirectory(<dir>)`` inside the package, in a scope of its own."""
        words = scope.words(command.arguments)
        if words and not self.follows(scope.path(words[0])):
            return
        if not words or "EXCLUDE_FROM_ALL" in words[1:] or \
                self.depth >= MAX_SUBDIRECTORY_DEPTH or \
                self.subdirectories >= MAX_SUBDIRECTORIES or \
                not resolved(scope.path(words[0])).is_relative_to(self.root):
            self.unfollowed(command)
            return
        folder = scope.path(words[0])
        self.spend(command, len(scope.variables))
        self.subdirectories += 1
        variables = dict(scope.variables)
        for name in ("CMAKE_CURRENT_SOURCE_DIR", "CMAKE_CURRENT_LIST_DIR"):
            variables[name] = str(folder)
        self.depth += 1
        try:
            if not self.run_file(Scope(folder, variables, scope)):
                self.unfollowed(command)
        finally:
            self.depth -= 1


def _arguments(parameters: tuple[str, ...], given: list[str | None]) -> dict[str, str | None]:
    """Return the variables a call sets: its parameters, ``ARGC``, ``ARGV<n>``, ``ARGN``, ``ARGV``.

    An unknown argument may be any number of words: from it on, positions are unknown.
    """
    cut = given.index(None) if None in given else len(given)
    complete = cut == len(given)

    def at(index: int) -> str | None:
        return given[index] if index < cut else "" if complete else None

    bound = {parameter: at(index) for index, parameter in enumerate(parameters)}
    bound.update({f"ARGV{index}": at(index) for index in range(len(given))})
    bound["ARGC"] = str(len(given)) if complete else None
    bound["ARGN"] = joined(given[len(parameters):])
    bound["ARGV"] = joined(given)
    return bound


def _saved(scope: Scope, names: Iterable[str]) -> dict[str, tuple[bool, str | None]]:
    """Return whether each variable is set, and its value, to be restored."""
    return {name: (name in scope.variables, scope.variables.get(name)) for name in names}


def _restore(scope: Scope, saved: dict[str, tuple[bool, str | None]]) -> None:
    for name, (was_set, value) in saved.items():
        if was_set:
            scope.variables[name] = value
        else:
            scope.variables.pop(name, None)


def _items(scope: Scope, words: list[str | None]) -> list[str] | None:
    """Return the items a ``foreach`` runs over, or ``None`` if they are unknown.

    ``<items>``, ``IN ITEMS <items>`` and ``IN LISTS <variables>``; ``RANGE`` and
    ``ZIP_LISTS`` are not read.
    """
    if None in words or words[:1] == ["RANGE"]:
        return None
    known = [w for w in words if w is not None]
    if known[:1] != ["IN"]:
        return known
    out: list[str] = []
    section = ""
    for word in known[1:]:
        if word in ("LISTS", "ITEMS", "ZIP_LISTS"):
            section = word
        elif section == "ITEMS":
            out.append(word)
        elif section == "LISTS":
            value = scope.variables.get(word)
            listed = [None] if value is None else items(value)
            if None in listed:
                return None
            out.extend(item for item in listed if item is not None)
        else:
            return None
    return out


def _block(commands: Sequence[Command], index: int, opener: str,
           ) -> tuple[tuple[Command, ...], int]:
    """Return the body of a block opened before ``index``, and the index after its end."""
    depth, start = 1, index
    while index < len(commands):
        name = commands[index].name
        index += 1
        if name == opener:
            depth += 1
        elif name == "end" + opener:
            depth -= 1
            if depth == 0:
                return tuple(commands[start:index - 1]), index
    return tuple(commands[start:index]), index
