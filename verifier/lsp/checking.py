"""One check on behalf of the editor: what changed documents affect, with their buffers.

The command line's own pieces do the work: options are built as ``launchverify check
--affected DOCUMENT`` builds them (nearest configuration, ``AMENT`` excludes,
``ROS_DISTRO``), ``run_check`` checks the launch trees the documents affect (themselves
when they are launch files, their includers, the launch files loading a parameter file),
and the editor's buffers stand for their files (as ``check - --stdin-filename`` does).
Nothing is written: no cache, no baseline.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path

from launchverify.cli import build_parser, check_options
from launchverify.config import ConfigError, find_config
from launchverify.engine import UsageError, canonical, run_check
from launchverify.graph import LaunchGraph
from launchverify.registry import RegistryError
from launchverify.rule import Finding
from launchverify.workspace.packages import colcon_root
from launchverify.workspace.reading import unsaved_buffers
from launchverify.workspace.sources import source_lines


@dataclass
class Checked:
    """What one check found, and the text of every file it looked at, as it read them.

    ``covered``: the files whose findings this check decides (every file its launch
    trees loaded, and the documents asked about); ``problems``: why some documents could
    not be checked (a broken configuration), for the user to see.
    """

    findings: list[Finding] = field(default_factory=list)
    covered: set[Path] = field(default_factory=set)
    graphs: list[LaunchGraph] = field(default_factory=list)
    lines: dict[Path, tuple[str, ...]] = field(default_factory=dict)
    problems: list[str] = field(default_factory=list)


def check_documents(documents: Iterable[Path], buffers: Mapping[Path, bytes],
                    folders: list[Path]) -> Checked:
    """Check what the documents affect, reading ``buffers`` in place of their files.

    ``folders`` are the editor's workspace folders: the one holding a document is the
    workspace to find packages in, unless a configuration file names one.
    """
    checked = Checked()
    paths = sorted({canonical(p) for p in documents if p.is_file()})
    checked.covered.update(paths)
    with unsaved_buffers({canonical(p): data for p, data in buffers.items()}, only=True):
        for group in _by_configuration(paths, checked.problems):
            try:
                _check_group(group, folders, checked)
            except (UsageError, ConfigError, RegistryError) as error:
                checked.problems.append(str(error))
        files = checked.covered | {f.span.file for f in checked.findings}
        files |= {place.file for f in checked.findings
                  for place in (*f.chain, *(r.span for r in f.related))}
        checked.lines = {path: source_lines(path) for path in files}
    return checked


def _by_configuration(paths: list[Path], problems: list[str]) -> list[list[Path]]:
    """Group documents by their nearest configuration file (each group is one check)."""
    groups: dict[Path | None, list[Path]] = {}
    for path in paths:
        try:
            groups.setdefault(find_config(path), []).append(path)
        except ConfigError as error:
            problems.append(str(error))
    return list(groups.values())


def _check_group(paths: list[Path], folders: list[Path], checked: Checked) -> None:
    args = build_parser().parse_args(["check", "--affected", *(str(p) for p in paths)])
    options, config = check_options(args)
    if config.workspace is None:
        folder = next((f for f in folders if paths[0].is_relative_to(canonical(f))), None)
        # a repository opened from a colcon workspace's src/: its packages are all there
        colcon = colcon_root(canonical(folder)) if folder is not None else None
        options.workspace = colcon[0] if colcon is not None else folder
    report = run_check(options)
    checked.findings.extend(report.findings)
    checked.graphs.extend(report.graphs)
    for graph in report.graphs:
        checked.covered.update(graph.files)
        checked.covered.update(graph.param_files)
