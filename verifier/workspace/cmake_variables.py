"""The CMake commands that set variables, run on a ``cmake_scope.Scope``.

``set``, ``unset``, ``list``, ``project`` and ``cmake_parse_arguments``: each sets what
it can be sure of and leaves the rest unknown. ``set(X ... CACHE ...)`` takes the
default (a ``-D`` on the command line is not seen); ``list`` follows ``APPEND`` and
``REMOVE_ITEM`` only.
"""

from __future__ import annotations

from collections.abc import Callable

from launchverify.workspace.cmake_scope import Scope, items, joined
from launchverify.workspace.cmake_words import Argument

Arguments = tuple[Argument, ...]


def project(scope: Scope, arguments: Arguments, fallback: str | None) -> None:
    """``project(<name>)``; ``fallback`` names a project whose name is unknown."""
    words = scope.words(arguments[:1])
    scope.assign("PROJECT_NAME", words[0] if words else fallback)
    scope.assign("PROJECT_SOURCE_DIR", str(scope.folder))


def set_variable(scope: Scope, arguments: Arguments) -> None:
    """``set(<var> <values>... [PARENT_SCOPE | CACHE ...])``."""
    variable = scope.expand(arguments[0].text) if arguments else None
    if variable is None:
        return
    values = list(arguments[1:])
    target: Scope | None = scope
    if any(a.text == "PARENT_SCOPE" and not a.quoted for a in values):
        target = scope.parent  # this scope's variable stays as it is
        values = [a for a in values if a.text != "PARENT_SCOPE" or a.quoted]
    cache = next((i for i, a in enumerate(values) if a.text == "CACHE" and not a.quoted), None)
    if cache is not None:
        values = values[:cache]
    words = scope.each(tuple(values))
    value = None if not words or (target is not scope and scope.branches) else \
        joined(words)  # (a parent's value set in a branch here: not certain)
    if target is not None:
        target.assign(variable, value)


def unset(scope: Scope, arguments: Arguments) -> None:
    """``unset(<var> [PARENT_SCOPE])``: a list appended to it next starts empty."""
    words = scope.words(arguments)
    target = scope.parent if words and "PARENT_SCOPE" in words[1:] else scope
    if not words or target is None or "CACHE" in words[1:]:
        return
    if target is not scope and scope.branches:
        target.assign(words[0], None)
    else:
        target.variables.pop(words[0], None)


def list_variable(scope: Scope, arguments: Arguments) -> None:
    """``list(APPEND|REMOVE_ITEM <var> ...)``; another operation leaves it unknown."""
    words = scope.words(arguments[:2])
    if not words or len(words) < 2:
        return
    operation, variable = words[0], words[1]
    current = scope.variables.get(variable, "")  # a new list is empty
    given = scope.each(arguments[2:])
    if current is None or operation not in ("APPEND", "REMOVE_ITEM") or \
            (operation == "REMOVE_ITEM" and None in given):
        scope.assign(variable, None)
    elif operation == "APPEND":
        scope.assign(variable, ";".join(filter(None, [current, joined(given)])))
    else:
        scope.assign(variable, ";".join(w for w in current.split(";") if w not in given))


def parse_arguments(scope: Scope, arguments: Arguments) -> None:
    """``cmake_parse_arguments``: a function's keyword arguments as ``<prefix>_<KEYWORD>``.

    A keyword not given is left empty, as CMake leaves it undefined; an unknown word is
    an unknown item of the keyword it follows.
    """
    words = scope.each(arguments)
    head = scope.words(arguments[:6 if words[:1] == ["PARSE_ARGV"] else 4])
    if head is None or len(head) < 4:
        return
    if head[0] == "PARSE_ARGV":
        argv = scope.variables.get("ARGV")
        if len(head) < 6 or argv is None or not head[1].isdigit():
            return
        prefix, keywords, given = head[2], head[3:6], items(argv)[int(head[1]):]
    else:
        prefix, keywords, given = head[0], head[1:4], words[4:]
    options, single, multiple = (set(filter(None, k.split(";"))) for k in keywords)
    values: dict[str, list[str | None]] = {}
    current: str | None = None
    for word in given:
        if word in options:
            values[word], current = ["TRUE"], None
        elif word in single or word in multiple:
            values[word], current = [], word
        elif current is not None:
            values[current].append(word)
            if current in single:
                current = None
    for keyword in options | single | multiple:
        default = "FALSE" if keyword in options else ""
        scope.assign(f"{prefix}_{keyword}", joined(values.get(keyword, [default])))


COMMANDS: dict[str, Callable[[Scope, Arguments], None]] = {
    "set": set_variable, "unset": unset, "list": list_variable,
    "cmake_parse_arguments": parse_arguments,
}
