"""Frontends: launch files in, IR out. They record problems; they never report findings."""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Protocol

from launchverify.frontends.tags import TagParser, ros1_launch_file
from launchverify.frontends.xml_reader import read_xml
from launchverify.frontends.yaml_reader import read_yaml
from launchverify.ir.actions import LaunchFile
from launchverify.problems import Problem, ProblemSink
from launchverify.span import Span
from launchverify.workspace.reading import is_regular, outside, read_file

XML_SUFFIXES = (".xml",)
YAML_SUFFIXES = (".yaml", ".yml")
PYTHON_SUFFIXES = (".py",)


class PythonLoader(Protocol):
    """Evaluates Python launch files (in worker processes: ``launchverify.isolation``)."""

    def load(self, path: Path, sink: ProblemSink) -> LaunchFile | None:
        """Return the file's IR, recording its problems in ``sink``."""

    def prefetch(self, paths: Iterable[Path]) -> None:
        """Start on files that will be loaded soon, if the loader can work ahead."""


@dataclass
class LoadedFile:
    """The result of reading one launch file: its IR (when readable) and its problems.

    ``ros1``: the file is a ROS 1 (roslaunch) file; this info replaces ``problems`` when
    the file is checked on its own. Through an include ``problems`` stay: ros2 launch fails
    there.
    """

    path: Path
    format: str
    launch: LaunchFile | None
    problems: list[Problem] = field(default_factory=list)
    ros1: Problem | None = None


def launch_format(path: Path, data: bytes | None = None) -> str:
    """Return ``xml``, ``yaml`` or ``python`` for a launch file path (sniffing ``.launch``)."""
    name = path.name.lower()
    if name.endswith(XML_SUFFIXES):
        return "xml"
    if name.endswith(YAML_SUFFIXES):
        return "yaml"
    if name.endswith(PYTHON_SUFFIXES):
        return "python"
    if data is not None and data.lstrip()[:1] == b"<":
        return "xml"
    return "yaml"


def load_launch_file(path: Path, python: PythonLoader | None = None) -> LoadedFile:
    """Read and convert one launch file, recording every problem instead of raising.

    Python launch files need ``python`` (which knows the packages and the workspace).
    """
    sink = ProblemSink()
    if launch_format(path) == "python" and python is not None:
        if not is_regular(path) or outside(path):  # a FIFO would block the worker
            return _unreadable(path, "python", sink)
        return LoadedFile(path, "python", python.load(path, sink), sink.problems)
    try:
        data = read_file(path)
    except OSError as error:
        sink.cannot_read(error, Span.of_file(path))
        return LoadedFile(path, launch_format(path), None, sink.problems)
    fmt = launch_format(path, data)
    if fmt == "python":
        sink.unmodeled("Python launch files are evaluated only within a check",
                       Span.of_file(path))
        return LoadedFile(path, fmt, None, sink.problems)
    root = read_xml(path, data, sink) if fmt == "xml" else read_yaml(path, data, sink)
    if root is None:
        return LoadedFile(path, fmt, None, sink.problems)
    ros1 = ros1_launch_file(root, path) if fmt == "xml" else None
    launch = TagParser(path, sink).launch_file(root, fmt)
    return LoadedFile(path, fmt, launch, sink.problems, ros1)


def _unreadable(path: Path, fmt: str, sink: ProblemSink) -> LoadedFile:
    try:
        read_file(path, prefix=0)
    except OSError as error:
        sink.cannot_read(error, Span.of_file(path))
    return LoadedFile(path, fmt, None, sink.problems)
