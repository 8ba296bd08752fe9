"""Applying the findings' fixes: what ``check --fix`` and ``check --diff`` do.

A fix names the exact text it replaces (``Edit``: a span, end exclusive, and the new
text). Fixes are applied to the files' contents in memory: every edit of a fix, or none;
a fix whose edits overlap one already taken waits for the next pass; edits go from the
end of each file backwards, so the spans of the others stay true. Everything outside the
edited spans is kept byte for byte (encoding, line endings, trailing newline). Then the
launch is checked again on the new contents, and fixed again, until nothing is left to
fix. A pass that makes a file unreadable (a new parse error) is undone for that file.

Nothing here writes a file: the command line decides (``--fix`` writes, ``--diff``
prints). Only files of the workspace are edited, never an installed copy.
"""

from __future__ import annotations

import dataclasses
import difflib
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from launchverify.rule import Applicability, Edit, Finding, Fix
from launchverify.workspace import reading

if TYPE_CHECKING:
    from launchverify.engine import Report

MAX_PASSES = 8  # fixes that uncover fixes; a fix that keeps coming back stops here
PARSE_ERROR = "LV001"
BOM = "\ufeff"
# Line breaks other than \n and \r\n: readers would number lines differently.
_OTHER_BREAKS = frozenset("\x0b\x0c\x1c\x1d\x1e\x85\u2028\u2029")

Key = tuple[object, ...]


def applicable(fix: Fix | None, unsafe: bool) -> bool:
    """Return whether ``--fix`` applies a fix (unsafe ones only with ``--unsafe-fixes``)."""
    return fix is not None and (unsafe or fix.applicability is Applicability.SAFE)


def fixable(findings: Iterable[Finding], unsafe: bool) -> int:
    """Return how many findings ``--fix`` would mend."""
    return sum(1 for finding in findings if applicable(finding.fix, unsafe))


def hidden(findings: Iterable[Finding], unsafe: bool) -> int:
    """Return how many findings have a fix that only ``--unsafe-fixes`` applies."""
    return 0 if unsafe else sum(
        1 for finding in findings
        if finding.fix is not None and finding.fix.applicability is Applicability.UNSAFE)


def fix_note(fix: Fix | None) -> str:
    """Return how a finding's fix is applied, for formats that have only text.

    Examples:
        >>> fix_note(Fix("x", ()))
        ' (fixable with --fix)'
        >>> fix_note(Fix("x", (), Applicability.UNSAFE))
        ' (fixable with --fix --unsafe-fixes)'
    """
    if fix is None:
        return ""
    unsafe = fix.applicability is Applicability.UNSAFE
    return f" (fixable with --fix{' --unsafe-fixes' if unsafe else ''})"


def editable(path: Path, workspace: Path) -> bool:
    """Return whether fixes may edit ``path``: a file of the workspace, not an installed copy.

    Examples:
        >>> editable(Path("/ws/src/a/launch/x.launch.xml"), Path("/ws"))
        True
        >>> editable(Path("/ws/install/a/share/a/x.launch.xml"), Path("/ws"))
        False
        >>> editable(Path("/opt/ros/jazzy/share/a/x.launch.xml"), Path("/ws"))
        False
    """
    if not path.is_relative_to(workspace):
        return False
    parts = path.relative_to(workspace).parts
    return not (len(parts) > 1 and parts[0] in ("install", "build", "log"))


def within(findings: list[Finding], workspace: Path) -> list[Finding]:
    """Return the findings with the fixes that would edit files outside the workspace dropped."""
    return [finding if finding.fix is None or all(
        editable(edit.span.file, workspace) for edit in finding.fix.edits)
        else dataclasses.replace(finding, fix=None) for finding in findings]


class Unfixable(ValueError):
    """A file or an edit that fixes cannot touch precisely; ``str()`` says why."""


class Document:
    """A file's text as edits address it: lines end at each newline, columns count characters."""

    def __init__(self, path: Path, data: bytes) -> None:
        self.path = path
        try:
            self.text = data.decode("utf-8")
        except UnicodeDecodeError:
            raise Unfixable("not UTF-8") from None
        if any(char in _OTHER_BREAKS for char in self.text) or "\r" in self.text.replace(
                "\r\n", ""):
            raise Unfixable("line breaks other than \\n and \\r\\n")
        self.starts = [0]
        for index, char in enumerate(self.text):
            if char == "\n":
                self.starts.append(index + 1)
        self.crlf = "\r\n" in self.text

    def offset(self, line: int, column: int) -> int:
        """Return the index of a place in the text (``Unfixable`` if there is no such place)."""
        if not 0 < line <= len(self.starts) or column < 1:
            raise Unfixable(f"no line {line}, column {column}")
        if line == 1 and self.text.startswith(BOM):
            raise Unfixable("columns of the first line after a byte-order mark are ambiguous")
        start = self.starts[line - 1]
        end = self.starts[line] - 1 if line < len(self.starts) else len(self.text)
        index = start + column - 1
        if index > end or (index > start and self.text[index - 1] == "\r" and index == end):
            raise Unfixable(f"no column {column} on line {line}")
        return index

    def region(self, edit: Edit) -> tuple[int, int]:
        """Return the start and end indexes an edit replaces."""
        span = edit.span
        if span.end_line is None or span.end_column is None:
            raise Unfixable("an edit without an end")
        start = self.offset(span.line, span.column)
        end = self.offset(span.end_line, span.end_column)
        if end < start:
            raise Unfixable("an edit that ends before it starts")
        return start, end

    def content(self, edit: Edit) -> str:
        """Return an edit's new text with the file's own line breaks."""
        text = edit.content
        return text.replace("\r\n", "\n").replace("\n", "\r\n") if self.crlf else text


Region = tuple[Path, int, int, str]  # a file, the start and end indexes, the new text


@dataclass
class _Taken:
    """The edits one pass takes."""

    regions: set[Region] = field(default_factory=set)

    def clashes(self, region: Region) -> bool:
        """Return whether a region overlaps one taken (two inserts at one place do)."""
        path, start, end, _ = region
        return any(path == other[0] and ((start < other[2] and other[1] < end)
                                         or start == other[1])
                   for other in self.regions)


@dataclass
class Pass:
    """The fixes one pass applies, and the new contents of the files they edit."""

    contents: dict[Path, bytes]
    fixed: list[Finding]
    notes: list[str]


def plan(findings: Iterable[Finding], read: Callable[[Path], bytes], *, unsafe: bool,
         skip: set[Key] | None = None, editable: Callable[[Path], bool] | None = None
         ) -> Pass:
    """Apply the findings' applicable fixes to the files ``read`` gives, in memory.

    Findings are taken in order; a fix is applied whole or not at all: one that overlaps
    a fix already taken waits for the next pass, one that cannot be placed exactly (a
    span beyond the text, a file that is not UTF-8) is left out with a note. A fix whose
    edits change nothing is left out (it would come back every pass); one whose edits
    another fix already made counts as fixed. ``editable`` limits the files edited.
    """
    documents: dict[Path, Document | None] = {}
    taken = _Taken()
    fixed: list[Finding] = []
    notes: list[str] = []
    for finding in findings:
        fix = finding.fix
        if fix is None or not applicable(fix, unsafe) or (skip and finding.key() in skip):
            continue
        if editable is not None and not all(editable(e.span.file) for e in fix.edits):
            continue
        try:
            regions = [_region(documents, read, edit) for edit in fix.edits]
        except Unfixable as error:
            notes.append(f"{finding.span.file}:{finding.span.line}: {finding.code} not "
                         f"fixed: {error}")
            continue
        fresh = [region for region in regions if region not in taken.regions]
        if _clash(taken, fresh):
            continue  # the next pass, on the new text
        if regions and not fresh:
            fixed.append(finding)  # another finding's fix made the same edits
        elif any(_text(documents, path)[start:end] != new for path, start, end, new in fresh):
            taken.regions.update(fresh)
            fixed.append(finding)
    contents = {}
    for path in sorted({region[0] for region in taken.regions}):
        document = documents[path]
        assert document is not None
        text = document.text
        for _, start, end, new in sorted((r for r in taken.regions if r[0] == path),
                                         key=lambda r: (r[1], r[2]), reverse=True):
            text = text[:start] + new + text[end:]
        contents[path] = text.encode("utf-8")
    return Pass(contents, fixed, notes)


def _clash(taken: _Taken, regions: list[Region]) -> bool:
    """Return whether regions overlap those taken, or each other."""
    own = _Taken()
    for region in regions:
        if taken.clashes(region) or own.clashes(region):
            return True
        own.regions.add(region)
    return False


def _text(documents: dict[Path, Document | None], path: Path) -> str:
    document = documents[path]
    assert document is not None
    return document.text


def _region(documents: dict[Path, Document | None], read: Callable[[Path], bytes],
            edit: Edit) -> Region:
    """Return what an edit replaces in its file, reading the file the first time."""
    path = edit.span.file
    if path not in documents:
        try:
            documents[path] = Document(path, read(path))
        except OSError as error:
            raise Unfixable(f"cannot read {path}: {error}") from None
        except Unfixable:
            documents[path] = None
            raise
    document = documents[path]
    if document is None:
        raise Unfixable(f"{path} cannot be edited precisely")
    start, end = document.region(edit)
    return path, start, end, document.content(edit)


@dataclass
class Outcome:
    """What fixing did: the check of the fixed contents and the files changed."""

    report: Report
    original: dict[Path, bytes] = field(default_factory=dict)
    fixed: dict[Path, bytes] = field(default_factory=dict)
    count: int = 0  # findings fixed
    notes: list[str] = field(default_factory=list)


def fix_all(report: Report, check: Callable[[], Report], *, unsafe: bool,
            editable: Callable[[Path], bool] | None = None) -> Outcome:
    """Fix, check again, and repeat until no fix is left (at most ``MAX_PASSES`` times).

    ``check`` checks the launch as the files read then (it runs inside ``buffered``).
    A pass that gives a file more parse errors than before is undone for that file (and
    for the other files its fixes edit), and those fixes are not tried again.
    """
    outcome = Outcome(report)
    current: dict[Path, bytes] = {}
    refused: set[Key] = set()

    def read(path: Path) -> bytes:
        if path in current:
            return current[path]
        data = reading.read_file(path)
        outcome.original.setdefault(path, data)
        return data

    for _ in range(MAX_PASSES):
        step = plan(outcome.report.findings, read, unsafe=unsafe, skip=refused,
                    editable=editable)
        outcome.notes += step.notes
        if not step.contents:
            break
        trial = {**current, **step.contents}
        with reading.unsaved_buffers(trial):
            checked = check()
        broken = _unreadable(step, checked, outcome.report)
        if broken:
            refused.update(f.key() for f in step.fixed if _touches(f, broken))
            outcome.notes += [f"{path}: fixes not applied: the file would no longer parse"
                              for path in sorted(broken)]
            for path in broken:
                trial.pop(path, None)
                if path in current:
                    trial[path] = current[path]
            if trial == current:
                continue
            with reading.unsaved_buffers(trial):
                checked = check()
        current = trial
        outcome.count += sum(1 for f in step.fixed if not _touches(f, broken))
        outcome.report = checked
    outcome.fixed = {path: data for path, data in current.items()
                     if data != outcome.original.get(path)}
    return outcome


def _unreadable(step: Pass, checked: Report, before: Report) -> set[Path]:
    """Return the files a pass made unparsable, and the others its fixes there edit."""
    broken = {path for path in step.contents
              if _parse_errors(checked, path) > _parse_errors(before, path)}
    while True:
        more = {edit.span.file for finding in step.fixed if _touches(finding, broken)
                for edit in (finding.fix.edits if finding.fix else ())} - broken
        if not more:
            return broken
        broken |= more


def _touches(finding: Finding, files: set[Path]) -> bool:
    return finding.fix is not None and any(e.span.file in files for e in finding.fix.edits)


def _parse_errors(report: Report, path: Path) -> int:
    return sum(1 for f in report.findings if f.code == PARSE_ERROR and f.span.file == path)


def unified_diff(outcome: Outcome, display: Callable[[Path], str]) -> str:
    """Return the changes as a unified diff, file by file (``check --diff``)."""
    parts = []
    for path in sorted(outcome.fixed):
        before = outcome.original[path].decode("utf-8").splitlines(keepends=True)
        after = outcome.fixed[path].decode("utf-8").splitlines(keepends=True)
        name = display(path)
        lines = list(difflib.unified_diff(before, after, f"a/{name}", f"b/{name}"))
        parts += [line if line.endswith("\n") else line + "\n\\ No newline at end of file\n"
                  for line in lines]
    return "".join(parts)
