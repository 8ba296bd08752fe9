"""The same file, the same findings, whatever the paths a check is given.

A file another launch file includes is judged by every launch that reaches it: a rule
that needs them all to agree (``every_context``), or polls them (``PollingRule``),
would otherwise answer differently for ``check src/nav2_bringup`` than for the whole
workspace, whose test launches include the same file with other arguments. So a check of
some paths also evaluates the workspace's launch files that include the paths' files
(found by the includers scan, transitively): their contexts vote, and what they report
about their own files stays out of this check.

A file outside the paths that the paths' launches reach (a vendor's included file) may
be included by still other launches of the workspace; evaluating those would mean the
whole workspace. A finding there that rests on every context agreeing says so in a note.
"""

from __future__ import annotations

import dataclasses
import os
from collections.abc import Callable, Iterable
from pathlib import Path

from launchverify.rule import Finding, PollingRule, Related, Rule
from launchverify.workspace.affected import affected_launch_files
from launchverify.workspace.includers import Includers

OUTSIDE_NOTE = ("judged by the launch files checked here only: other launch files of the "
                "workspace that include this file may decide otherwise (check the "
                "workspace to hear them all)")


def context_roots(roots: list[Path], includers: Includers,
                  excluded: Callable[[Path], bool]) -> list[Path]:
    """Return the workspace's launch files outside ``roots`` that include one of them."""
    given = set(roots)
    return [path for path in affected_launch_files(roots, includers)
            if path not in given and not excluded(path)]


def consensus(rule: type[Rule]) -> bool:
    """Return whether a rule's findings rest on every evaluation reaching the file."""
    return bool(getattr(rule, "every_context", False)) or issubclass(rule, PollingRule)


def in_scope(findings: Iterable[Finding], paths: Iterable[Path], reached: set[Path],
             context_only: set[Path], consensus_codes: set[str],
             unheard: Callable[[Path], bool]) -> list[Finding]:
    """Return the findings this check reports, with the note where the scope decided.

    ``reached``: the files the paths' own launches reached; ``context_only``: those only
    the including launches reached (their findings are theirs, not this check's);
    ``unheard(file)``: whether a launch file this check did not evaluate includes it.
    """
    folders = [Path(os.path.realpath(path)) for path in paths]

    def inside(file: Path) -> bool:
        return any(file.is_relative_to(folder) for folder in folders)

    kept = []
    for finding in findings:
        file = finding.span.file
        if file in context_only and file not in reached and not inside(file):
            continue
        if finding.code in consensus_codes and not inside(file) and unheard(file):
            finding = dataclasses.replace(
                finding, related=(*finding.related, Related(finding.span, OUTSIDE_NOTE)))
        kept.append(finding)
    return kept
