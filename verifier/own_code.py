"""Which source files are launchverify's own.

Frames in these files are never blamed on the user: a finding points at the user's call,
not at the model that handled it. The packages are located where Python imported them
from (an editable install maps them to the source folders ``verifier/``, ``models/`` and
``rules/``, or links them into a build tree), so no prefix of a folder name is assumed.
"""

from __future__ import annotations

import os
import sys

_PACKAGES = ("launchverify", "launchverify.models", "launchverify.rules")


_roots: dict[tuple[bool, ...], tuple[str, ...]] = {}


def package_folders() -> list[str]:
    """Return the folders of launchverify's packages where Python finds them.

    Found, not imported (a cached run needs no rule): each package's ``__init__`` folder.
    """
    from importlib.util import find_spec

    specs = [find_spec(name) for name in _PACKAGES]
    return [os.path.dirname(spec.origin) for spec in specs  # noqa: PTH120
            if spec is not None and spec.origin]


def own_roots() -> tuple[str, ...]:
    """Return the folders (with a trailing separator) of launchverify's imported packages.

    Asked for every frame a model looks at; computed again only when another of the
    packages has been imported since (a worker never imports the rules).
    """
    imported = tuple(name in sys.modules for name in _PACKAGES)
    found = _roots.get(imported)
    if found is None:
        roots: list[str] = []
        for name in _PACKAGES:
            filename = getattr(sys.modules.get(name), "__file__", None)
            if filename:
                roots.append(os.path.dirname(os.path.abspath(filename)) + os.sep)  # noqa: PTH100, PTH120
        found = _roots[imported] = tuple(roots)
    return found


def is_own_file(filename: str) -> bool:
    """Return whether ``filename`` (as a code object names it) is launchverify's or frozen."""
    return filename.startswith("<frozen") or filename.startswith(own_roots())


def is_launchverify_file(filename: str) -> bool:
    """Return whether ``filename`` is launchverify's own (frozen modules are Python's)."""
    return filename.startswith(own_roots())


_STDLIB = os.path.dirname(os.__file__) + os.sep  # noqa: PTH120


def for_launchverify(depth: int) -> bool:
    """Return whether the code ``depth`` frames up runs on launchverify's behalf.

    Python's standard library works for whoever called it: the first frame up the stack
    that is not the standard library's (or frozen) decides.
    """
    frame = sys._getframe(depth + 1)
    while frame is not None:
        filename = frame.f_code.co_filename
        if not filename.startswith((_STDLIB, "<frozen")):
            return filename.startswith(own_roots())
        frame = frame.f_back  # type: ignore[assignment]
    return False
