"""What is under the cursor, from what the evaluation recorded, and where it is defined.

References come from the launch graphs: reads of launch configurations (a Python
``LaunchConfiguration(...)`` is recorded at the expression; in XML and YAML a read is
recorded at its attribute, and the frontend's own ``$(...)`` grammar finds the
``$(var name)`` under the cursor on that line), ``<let>``/``SetLaunchConfiguration``
actions, includes with their resolved files and the arguments they pass, and parameter
files with where they were found. A configuration resolves to its declarations: in the
same file, else in the nearest includer that declares it, else wherever the launch
declares it (an argument leaking from a sibling include).
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path

from launchverify.frontends.subst_parser import variable_references
from launchverify.graph import ArgumentRecord, LaunchGraph
from launchverify.ir import actions as a
from launchverify.ir.subst import Text
from launchverify.ir.walk import iter_actions
from launchverify.span import Span

# What wins when several references hold the cursor: the most specific first.
VARIABLE, INCLUDE_ARGUMENT, LET, PARAMETER_FILE, INCLUDE = range(5)


@dataclass
class Reference:
    """Something written at the cursor, and what it refers to."""

    kind: int
    span: Span  # the reference itself
    name: str | None = None  # of a launch configuration
    file: Path | None = None  # an included or parameter file
    declarations: list[ArgumentRecord] = field(default_factory=list)
    settings: list[a.SetConfig] = field(default_factory=list)  # <let>s, when none declares
    graphs: Sequence[LaunchGraph] = ()  # the evaluations that loaded the file

    def targets(self) -> list[Span]:
        """Return where it is defined: declarations (else ``<let>``s), or the file."""
        if self.file is not None:
            return [Span.of_file(self.file)]
        if self.declarations:
            return [d.origin.span for d in self.declarations]
        return [s.span for s in self.settings]


def reference_at(graphs: Sequence[LaunchGraph], path: Path, lines: Sequence[str],
                 line: int, column: int) -> Reference | None:
    """Return the reference at a 1-based line and span column of a file, resolved."""
    found = [ref for graph in graphs for ref in _candidates(graph, path, lines, line, column)]
    if not found:
        return None
    best = min(found, key=lambda ref: (ref.kind, _size(ref.span)))
    best.graphs = graphs
    if best.name is not None and best.kind != INCLUDE_ARGUMENT:
        best.declarations = declarations(graphs, path, best.name)
        if not best.declarations:
            best.settings = settings(graphs, best.name)
    return best


def _candidates(graph: LaunchGraph, path: Path, lines: Sequence[str], line: int,
                column: int) -> Iterator[Reference]:
    exact = path.suffix.lower() == ".py"  # Python: recorded at the expression itself

    def holds(span: Span) -> bool:
        if span.file != path:
            return False
        if exact:
            return _within(span, line, column)
        return span.line <= line <= (span.end_line or span.line)

    for read in graph.reads:
        if exact and holds(read.origin.span):
            yield Reference(VARIABLE, read.origin.span, name=read.name)
    if not exact and path in graph.files and 0 < line <= len(lines):
        for name, start, end in variable_references(lines[line - 1]):
            if start < column <= end + 1:
                yield Reference(VARIABLE, Span(path, line, start + 1, line, end + 1),
                                name=name)
    for include in graph.includes:
        for passed, _value, span in include.arguments:
            if passed is not None and include.target is not None and holds(span):
                yield Reference(INCLUDE_ARGUMENT, span, name=passed,
                                declarations=[d for d in graph.arguments if d.name == passed
                                              and d.origin.span.file == include.target])
        where = [include.origin.span, include.action.at("file")]
        if include.target is not None and any(holds(span) for span in where):
            yield Reference(INCLUDE, include.origin.span, file=include.target)
    loaded = graph.files.get(path)
    if loaded is not None and loaded.launch is not None:
        for action in iter_actions(loaded.launch.actions):
            if isinstance(action, a.SetConfig) and isinstance(action.name, Text) \
                    and holds(action.span):
                yield Reference(LET, action.span, name=action.name.text)
    for node in graph.nodes:
        for parameter in node.parameters:
            if parameter.source is not None and holds(parameter.origin.span):
                yield Reference(PARAMETER_FILE, parameter.origin.span, file=parameter.source)


def declarations(graphs: Sequence[LaunchGraph], path: Path, name: str) -> list[ArgumentRecord]:
    """Return the declarations a configuration read in ``path`` refers to (see module)."""
    found: dict[Span, ArgumentRecord] = {}
    for graph in graphs:
        declared = [d for d in graph.arguments if d.name == name]
        for files in ([path], *_includers(graph, path), list(graph.files)):
            chosen = [d for d in declared if d.origin.span.file in files]
            if chosen:
                found.update((d.origin.span, d) for d in chosen)
                break
    return sorted(found.values(), key=lambda d: (str(d.origin.span.file), d.origin.span.line))


def settings(graphs: Sequence[LaunchGraph], name: str) -> list[a.SetConfig]:
    """Return the ``<let>``/``SetLaunchConfiguration`` actions that set a configuration."""
    found: dict[Span, a.SetConfig] = {}
    for graph in graphs:
        for loaded in graph.files.values():
            if loaded.launch is None:
                continue
            for action in iter_actions(loaded.launch.actions):
                if isinstance(action, a.SetConfig) and action.name == Text(name):
                    found.setdefault(action.span, action)
    return list(found.values())


def _includers(graph: LaunchGraph, path: Path) -> list[list[Path]]:
    """Return the files that include ``path``, level by level (the nearest first)."""
    levels: list[list[Path]] = []
    seen = {path}
    current = [path]
    while current:
        above = sorted({i.origin.span.file for i in graph.includes
                        if i.target in current and i.origin.span.file not in seen})
        if not above:
            break
        seen.update(above)
        levels.append(above)
        current = above
    return levels


def _within(span: Span, line: int, column: int) -> bool:
    """Return whether a position falls in a span with an end (its end included)."""
    if span.end_line is None or span.end_column is None:
        return False
    return (span.line, span.column) <= (line, column) <= (span.end_line, span.end_column)


def _size(span: Span) -> tuple[int, int]:
    lines = (span.end_line or span.line) - span.line
    return lines, (span.end_column or span.column) - span.column if not lines else 0
