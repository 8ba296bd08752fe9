"""What the server knows between checks: findings per file, their text, the launch graphs.

Checks cover parts of the workspace (what a change affects), so each file's findings are
those of the newest check that covered it; files no check covered keep theirs.
"""

from __future__ import annotations

from collections import defaultdict
from pathlib import Path

from launchverify.graph import LaunchGraph
from launchverify.lsp.checking import Checked
from launchverify.rule import Finding
from launchverify.workspace.sources import source_lines


class Results:
    """The newest findings of each file, and what hover and definitions look things up in."""

    def __init__(self) -> None:
        self.findings: dict[Path, list[Finding]] = {}
        self.lines: dict[Path, tuple[str, ...]] = {}  # as the findings' checks read them
        self.graphs: dict[Path, LaunchGraph] = {}  # by root: the newest evaluation

    def update(self, checked: Checked) -> list[Path]:
        """Take in a check; return the files whose findings it decided (to publish)."""
        by_file: dict[Path, list[Finding]] = defaultdict(list)
        for finding in checked.findings:
            by_file[finding.span.file].append(finding)
        decided = checked.covered | set(by_file)
        for path in decided:
            self.findings[path] = by_file.get(path, [])
        self.lines.update(checked.lines)
        for graph in checked.graphs:
            self.graphs[graph.root] = graph
        return sorted(decided)

    def lines_of(self, path: Path) -> tuple[str, ...]:
        """Return a file's lines as last checked (else as on disk)."""
        known = self.lines.get(path)
        return known if known is not None else source_lines(path)

    def graphs_with(self, path: Path) -> list[LaunchGraph]:
        """Return the evaluations that loaded a file (launch or parameter file)."""
        return [graph for graph in self.graphs.values()
                if path in graph.files or path in graph.param_files]
