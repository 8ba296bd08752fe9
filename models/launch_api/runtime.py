"""The evaluation a model is running in: which packages exist, what to report.

The Python frontend sets ``current`` while it runs a launch file (or an OpaqueFunction);
models such as ``get_package_share_directory`` read it.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path
from typing import TYPE_CHECKING, Any

from launchverify.own_code import is_own_file
from launchverify.span import Span

if TYPE_CHECKING:
    from launchverify.workspace.packages import PackageIndex


@dataclass
class Runtime:
    """What models may consult while a launch file runs."""

    index: PackageIndex
    workspace: Path
    unmodeled: Callable[[str, Span], None]
    launch_file: Path
    packages_seen: set[str] = field(default_factory=set)
    lookups: list[tuple[str, Span]] = field(default_factory=list)  # package lookups by call
    # configurations handed to code launchverify cannot see, which may read them
    handed_names: set[str] = field(default_factory=set)
    # Builds (perform, evaluate) for a LaunchContext the launch file makes itself.
    context_tools: Callable[[dict[str, str]], tuple[Any, Any]] | None = None
    # Where to point when no frame may be blamed (an OpaqueFunction whose body is in
    # another launch file: its OpaqueFunction's line)
    fallback: Span | None = None


current: Runtime | None = None


_ENTRY_POINTS = (b"def generate_launch_description", b"def generate_test_description")
_PYTHON = tuple(sorted({os.path.join(prefix, "lib") + os.sep  # noqa: PTH118
                        for prefix in (sys.prefix, sys.base_prefix, sys.exec_prefix)}))


def blamable(filename: str, launch_file: Path | None = None) -> bool:
    """Return whether a frame in ``filename`` is where a finding may point.

    Not launchverify's own code, and not another launch file the running one imported
    (its caller in the running file is blamed instead): launchverify accepts places only in
    the file evaluated and its helper modules, so that no launch file can put findings on
    another one.
    """
    if is_own_file(filename) or filename.startswith(("<", *_PYTHON)) \
            or filename == getattr(sys.modules.get("__main__"), "__file__", None):
        return False  # launchverify and the script running it, frozen, installed modules
    running = launch_file or (current.launch_file if current is not None else None)
    if running is None or filename == str(running):
        return True
    return not _is_launch_file(filename)


@lru_cache(maxsize=512)
def _is_launch_file(filename: str) -> bool:
    from launchverify.workspace.reading import read_file

    try:
        data = read_file(Path(filename), prefix=1 << 20)
    except OSError:  # a file launchverify may not read is no place to point at either
        return True
    return any(entry in data for entry in _ENTRY_POINTS)


def active() -> Runtime:
    """Return the running evaluation (models are only used inside one)."""
    if current is None:
        raise RuntimeError("launch API models are used outside a launchverify evaluation")
    return current
