"""The same file, the same findings, whatever the paths a check is given.

A file another launch file includes is judged by every launch that reaches it: a rule
that needs them all to agree (``every_context``), or polls them (``PollingRule``), would
otherwise answer differently for ``check src/nav2_bringup`` than for the whole workspace,
whose test launches include the same file with other arguments and parameter files. So a
check of some paths also evaluates the workspace's launch files that include the paths'
files (``context_roots``), as the whole workspace's check does: what they say of the
paths' files counts (an includer's context, agreeing, denying or finding), and what
they say of their own files is theirs, not this check's.

The includers scan finds includers by file name; one counts only when its evaluation
really loaded one of the paths' files (``confirmed``): a fixture elsewhere in the
workspace that includes another ``robot.launch.xml`` has no say.

A file outside the paths that the paths' launches reach (a vendor's included file) may
be included by still other launches of the workspace; evaluating those would mean the
whole workspace. A finding there that rests on every context agreeing is not this
check's to make: those launches were not heard (a check of the workspace hears them).
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable, Mapping
from pathlib import Path
from typing import TYPE_CHECKING

from launchverify.rule import Finding, PollingRule, Rule
from launchverify.workspace.affected import affected_launch_files
from launchverify.workspace.includers import Includers

if TYPE_CHECKING:
    from launchverify.findings.incremental import RootResult
    from launchverify.graph import LaunchGraph


def context_roots(roots: list[Path], includers: Includers,
                  excluded: Callable[[Path], bool]) -> list[Path]:
    """Return the workspace's launch files outside ``roots`` that may include one of them."""
    given = set(roots)
    return [path for path in affected_launch_files(roots, includers)
            if path not in given and not excluded(path)]


def confirmed(context: Iterable[Path], roots: Iterable[Path],
              reached: Callable[[Path], set[Path]]) -> list[Path]:
    """Return the context roots whose evaluation loaded one of ``roots`` (``reached``)."""
    wanted = set(roots)
    return [root for root in context if wanted & reached(root)]


def below(paths: Iterable[Path]) -> Callable[[Path], bool]:
    """Return whether a file lies below one of the paths (by their real paths)."""
    folders = [Path(os.path.realpath(path)) for path in paths]
    return lambda file: any(file.is_relative_to(folder) for folder in folders)


def files_of(root: Path, graphs: Mapping[Path, LaunchGraph],
             kept: Mapping[Path, RootResult]) -> set[Path]:
    """Return the launch and parameter files a root's evaluation read (or the kept one's)."""
    if root in graphs:
        return {*graphs[root].files, *graphs[root].param_files}
    if root in kept:
        return {*kept[root].verdicts.files, *map(Path, kept[root].reads or ())}
    return set()


def consensus(rule: type[Rule]) -> bool:
    """Return whether a rule's findings rest on every evaluation reaching the file."""
    return bool(getattr(rule, "every_context", False)) or issubclass(rule, PollingRule)


def in_scope(findings: Iterable[Finding], inside: Callable[[Path], bool],
             context_only: set[Path], consensus_codes: set[str],
             unheard: Callable[[Path], bool]) -> list[Finding]:
    """Return the findings this check reports.

    ``inside(file)``: whether a file is below the paths (``below``); ``context_only``:
    the files only their includers reached (what is said of them is theirs, not this
    check's); ``unheard(file)``: whether a launch file this check did not evaluate
    includes it.
    """
    kept = []
    for finding in findings:
        file = finding.span.file
        if file in context_only and not inside(file):
            continue
        if finding.code in consensus_codes and not inside(file) and unheard(file):
            continue  # every context must agree, and some were not asked
        kept.append(finding)
    return kept
