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


_roots: tuple[str, ...] = ()


def own_roots() -> tuple[str, ...]:
    """Return the folders (with a trailing separator) of launchverify's imported packages."""
    global _roots  # noqa: PLW0603 - computed once every package is imported
    if len(_roots) == len(_PACKAGES):
        return _roots
    roots: list[str] = []
    for name in _PACKAGES:
        filename = getattr(sys.modules.get(name), "__file__", None)
        if filename:
            roots.append(os.path.dirname(os.path.abspath(filename)) + os.sep)  # noqa: PTH100, PTH120
    _roots = tuple(roots)
    return _roots


def is_own_file(filename: str) -> bool:
    """Return whether ``filename`` (as a code object names it) is launchverify's or frozen."""
    return filename.startswith("<frozen") or filename.startswith(own_roots())
