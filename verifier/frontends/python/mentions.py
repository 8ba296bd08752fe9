"""The strings an OpaqueFunction's code mentions: names it may read on untaken paths.

An OpaqueFunction runs once, with the arguments' defaults: a read under
``if LaunchConfiguration('rs_compat').perform(context) == 'true':`` is not seen. Before
saying an argument is unused, rules ask whether the code mentions its name at all. The
answer comes from the code objects (constants, nested functions, and the module's own
functions it calls), never from running anything.
"""

from __future__ import annotations

import functools
import types
from collections.abc import Callable
from typing import Any

MAX_CODE_OBJECTS = 400
MAX_LENGTH = 200  # a configuration name, not a block of text


def mentioned_strings(function: Callable[..., Any]) -> frozenset[str]:
    """Return the short string constants of a function and the code it calls in its module."""
    while isinstance(function, functools.partial):
        function = function.func
    start = getattr(function, "__code__", None)
    module_globals = getattr(function, "__globals__", {})
    if not isinstance(start, types.CodeType) or not isinstance(module_globals, dict):
        return frozenset()
    found: set[str] = set()
    seen: set[int] = set()
    stack = [start]
    while stack and len(seen) < MAX_CODE_OBJECTS:
        code = stack.pop()
        if id(code) in seen:
            continue
        seen.add(id(code))
        for constant in code.co_consts:
            if isinstance(constant, str) and len(constant) <= MAX_LENGTH:
                found.add(constant)
            elif isinstance(constant, types.CodeType):
                stack.append(constant)
        for name in code.co_names:
            helper = module_globals.get(name)
            if isinstance(helper, types.FunctionType) and helper.__globals__ is module_globals:
                stack.append(helper.__code__)
    return frozenset(found)
