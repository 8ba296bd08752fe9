"""Re-checking after an edit: only the roots that read an edited file are evaluated again.

A check keeps, beside its report, what each root gave (``RootResult``): its rules'
verdicts before the merge, the files it read, and what other roots' verdicts may depend
on (its include targets, its interface). After an edit, the roots that read no edited
file keep their verdicts; the others are evaluated and judged again, and the merge runs
over all of them as over a cold check's.

Exactness rests on what each result says it read:

- a root reads the launch and parameter files its evaluation asked for, and what the
  Python code among them opened (the workers report it; a worker that failed reports
  nothing, and its roots are evaluated every time);
- every other file launchverify read during the check (package manifests, node sources
  for the rules, a bridge's configuration) counts for every root: editing one re-checks
  everything, as does a file added, removed or renamed anywhere (a folder's listing
  changed: what exists decides includes and findings);
- a root's verdicts may depend on other roots in three ways, each re-checked: whether
  another root includes it (``included_elsewhere``), the interfaces of other launch
  files its rules consulted (``Interfaces.mirrored``, ``picked_by_name``), and the places
  another root settled for a rule asking every context (``Settled``).
"""

from __future__ import annotations

import dataclasses
import os
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from launchverify.findings.cache import Kept
from launchverify.findings.verdicts import Verdicts
from launchverify.frontends import launch_format
from launchverify.problems import NotFollowed
from launchverify.rule import Finding, Rule
from launchverify.span import Span
from launchverify.workspace.paths import real_path

if TYPE_CHECKING:
    from launchverify.engine import Report
    from launchverify.findings.cache import Entry
    from launchverify.graph import LaunchGraph
    from launchverify.workspace.interfaces import Interface, Picked


@dataclass
class RootResult:
    """What one root's evaluation and its rules gave, kept for the next check."""

    verdicts: Verdicts
    reads: frozenset[str] | None  # the files it rests on (None: unknown, evaluate again)
    includes: frozenset[Path]  # the files its includes reach (others' ``included_elsewhere``)
    included_elsewhere: bool
    interface: Interface
    picked: Picked  # what ``Interfaces.picked_by_name`` reads of it
    unseen: list[tuple[str, Span]] = field(default_factory=list)
    queries: int = 0
    unfollowed: list[NotFollowed] = field(default_factory=list)


@dataclass
class Plan:
    """What the last check left that this one may keep."""

    previous: dict[Path, RootResult]  # every root of the last check
    changed: frozenset[str]  # the files edited since

    def kept(self, roots: Iterable[Path]) -> dict[Path, RootResult]:
        """Return the results of the roots that read no edited file."""
        out = {}
        for root in roots:
            result = self.previous.get(root)
            if result is not None and result.reads is not None \
                    and not (result.reads & self.changed):
                out[root] = result
        return out


def plan(stored: tuple[Entry, Kept] | None, rules: Iterable[str]) -> Plan | None:
    """Return what may be kept of the last check's results (``None``: nothing).

    Nothing is kept when the rules differ, when a folder's listing changed, or when an
    edited file was read by anything but the roots' evaluations.
    """
    if stored is None:
        return None
    entry, kept = stored
    if not kept.roots or kept.rules != tuple(rules):
        return None
    changed = changed_files(entry, kept.started)
    if changed is None or changed & kept.other_reads:
        return None
    previous = {root: result for root, result in kept.roots.items()
                if isinstance(result, RootResult)}
    read_by_roots: set[str] = set()
    for result in previous.values():
        if result.reads is not None:
            read_by_roots |= result.reads
    if not changed <= read_by_roots:  # a file no root says it read: who did is not known
        return None
    return Plan(previous, frozenset(changed))


def changed_files(entry: Entry, started: float) -> set[str] | None:
    """Return the files modified since the entry's check started (``None``: more than that).

    A folder whose change time moved is listed again: an editor that saves by renaming a
    new file over the old one changes it, and the names are then the same. A file counts
    as changed when its size, modification time or change time says so: a file renamed
    over another (``mv``, ``cp -p``) may keep the old size and time, never the old change
    time.
    """
    from launchverify.findings.cache import content_hash, listing, moved

    if any(moved(folder, stamp) and listing(folder) != entry.listings.get(folder)
           for folder, stamp in entry.folder_stamps.items()):
        return None
    since = int(started * 1e9)
    changed = set()
    for path, (size, mtime, content) in entry.stamps.items():
        try:
            info = os.stat(path)  # noqa: PTH116 (string paths)
        except OSError:
            return None
        if (info.st_size, info.st_mtime_ns) != (size, mtime) or info.st_ctime_ns >= since \
                or (content is not None and content_hash(path) != content):
            changed.add(path)
    return changed


def unsettled(kept: dict[Path, RootResult], settled: dict[str, set[object]]) -> set[Path]:
    """Return the kept roots that skipped a place no root settles any longer."""
    return {root for root, result in kept.items()
            if any(not relied <= settled.get(code, set())
                   for code, (_, relied) in result.verdicts.settled.items())}


def settled_places(verdicts: Iterable[Verdicts]) -> dict[str, set[object]]:
    """Return, per rule, the places any of these graphs settled."""
    out: dict[str, set[object]] = {}
    for verdict in verdicts:
        for code, (places, _) in verdict.settled.items():
            out.setdefault(code, set()).update(places)
    return out


class Incremental:
    """One check's part in re-checking: what it keeps of the last, and keeps for the next."""

    def __init__(self, stored: tuple[Entry, Kept] | None, other_reads: set[str], *,
                 keep: bool) -> None:
        self.stored = stored
        self.other_reads = other_reads  # filled as the check reads (``reading.recording``)
        self.on = keep
        self.plan: Plan | None = None
        self.reads: dict[Path, frozenset[str] | None] = {}

    def start(self, roots: list[Path], rules: list[type[Rule]]) -> dict[Path, RootResult]:
        """Return the results kept for roots that read no edited file."""
        from launchverify.parallel.fanout import graph_wise

        if self.stored is None or not all(graph_wise(rule) for rule in rules):
            return {}
        self.plan = plan(self.stored, [rule.code for rule in rules])
        return {} if self.plan is None else self.plan.kept(roots)

    def evaluated(self, graph: LaunchGraph, asked: set[Path],
                  python_reads: Callable[[Path], frozenset[str] | None]) -> None:
        """Note what a root's evaluation read: files asked for, and what Python code opened."""
        if not self.on:
            return
        paths = {*asked, *graph.files, *graph.param_files}
        read: set[str] = set()
        for path in paths:
            if launch_format(path) == "python":
                opened = python_reads(path)
                if opened is None:
                    self.reads[graph.root] = None
                    return
                read.update(opened)
        read.update(str(path) for path in paths)
        self.reads[graph.root] = frozenset(
            {real_path(p) for p in read} | {os.path.abspath(p) for p in read})  # noqa: PTH100

    def concerned(self, graphs: dict[Path, LaunchGraph], kept: dict[Path, RootResult],
                  included: dict[Path, bool]) -> set[Path]:
        """Take from ``kept`` the roots an evaluation of others concerns, and return them.

        A root another now includes, or no longer does; a root whose rules consulted the
        interfaces of a family whose member changed its interface (or stopped being a
        root), or an includer's picks that changed.
        """
        from launchverify.workspace.interfaces import concerns, interface_of, picks_of

        if self.plan is None:
            return set()
        again = {root for root, result in kept.items()
                 if included[root] != result.included_elsewhere}
        previous = self.plan.previous
        changed: dict[Path, set[str]] = {}  # root -> the file names its changed picks pick
        for root in set(previous) - set(included):  # no longer a root
            changed[root] = {pick[0][0] for pick in previous[root].picked}
        for root, graph in graphs.items():
            before = previous.get(root)
            picks = picks_of(graph)
            if before is None or interface_of(graph) != before.interface \
                    or picks != before.picked:
                old = before.picked if before is not None else ()
                changed[root] = {pick[0][0] for pick in set(picks) ^ set(old)}
        for other, result in kept.items():
            if any(concerns(asked, root, picks) for asked in result.verdicts.consulted
                   for root, picks in changed.items()):
                again.add(other)
        for root in again:
            kept.pop(root, None)
        return again

    def unsettled(self, kept: dict[Path, RootResult], judged: dict[Path, Verdicts]
                  ) -> set[Path]:
        """Take from ``kept`` the roots that skipped a place no root settles now."""
        settled = settled_places([*judged.values(), *(k.verdicts for k in kept.values())])
        again = unsettled(kept, settled)
        for root in again:
            kept.pop(root)
        return again

    def report(self, roots: list[Path], graphs: dict[Path, LaunchGraph],
               judged: dict[Path, Verdicts], kept: dict[Path, RootResult],
               rules: list[type[Rule]]) -> Report:
        """Return the check's report before its findings (and with what to keep, if asked)."""
        from launchverify.engine import Report

        report = Report([], 0, 0.0, {}, [graphs[r] for r in roots if r in graphs])
        if not self.on:
            return report
        results = {root: kept[root] if root in kept else self._result(graphs[root],
                                                                      judged[root])
                   for root in roots}
        unseen: list[tuple[str, Span]] = []
        seen: set[tuple[str, Path, int]] = set()
        for result in results.values():
            for reason, span in result.unseen:
                if (reason, span.file, span.line) not in seen:
                    seen.add((reason, span.file, span.line))
                    unseen.append((reason, span))
        report.unseen = unseen
        report.unfollowed = list(dict.fromkeys(item for result in results.values()
                                               for item in result.unfollowed))
        report.queries = sum(result.queries for result in results.values())
        report.loaded = {path for result in results.values() for path in result.verdicts.files}
        report.kept = Kept(dict(results), tuple(rule.code for rule in rules),
                           frozenset(self.other_reads))
        return report

    def _result(self, graph: LaunchGraph, verdicts: Verdicts) -> RootResult:
        """Return what to keep of a root judged now (findings without their path conditions).

        What a rule said nothing of is left out: the merge reads each by ``get``.
        """
        from launchverify.smt import solver_queries
        from launchverify.workspace.interfaces import interface_of, picks_of

        def bare(finding: Finding | None) -> Finding | None:
            return dataclasses.replace(finding, path=()) if finding and finding.path else finding

        verdicts = dataclasses.replace(
            verdicts,
            findings={code: [f for f in map(bare, found) if f is not None]
                      for code, found in verdicts.findings.items() if found},
            answers={code: [(q, bare(f)) for q, f in answers]
                     for code, answers in verdicts.answers.items() if answers},
            settled={code: both for code, both in verdicts.settled.items() if any(both)})
        return RootResult(
            verdicts, self.reads.get(graph.root),
            frozenset(t for inc in graph.includes if (t := inc.target) is not None),
            graph.included_elsewhere, interface_of(graph), picks_of(graph),
            list(graph.unseen()), solver_queries([graph]), graph.not_followed())
