"""The evaluation a model is running in: which packages exist, what to report.

The Python frontend sets ``current`` while it runs a launch file (or an OpaqueFunction);
models such as ``get_package_share_directory`` read it.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

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
    # Builds (perform, evaluate) for a LaunchContext the launch file makes itself.
    context_tools: Callable[[dict[str, str]], tuple[Any, Any]] | None = None


current: Runtime | None = None


def active() -> Runtime:
    """Return the running evaluation (models are only used inside one)."""
    if current is None:
        raise RuntimeError("launch API models are used outside a launchverify evaluation")
    return current
