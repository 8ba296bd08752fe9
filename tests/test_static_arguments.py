"""Static argument discovery answers the same whether included files' answers are reused."""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path

import pytest

from launchverify.evaluate.files import FileCache
from launchverify.evaluate.static_args import Found, StaticSubtree, static_arguments
from launchverify.isolation.confine import Limits
from launchverify.isolation.pool import IsolatedPython
from launchverify.problems import ProblemSink
from launchverify.workspace.discover import discover
from launchverify.workspace.packages import PackageIndex

CORPUS = Path(__file__).resolve().parent.parent / "corpus"
TREES = [p for p in sorted(CORPUS.glob("*/*")) if p.is_dir()
         and any(discover([p]))]


def _key(found: list[Found]) -> list[tuple[str, int, tuple[int, ...], bool]]:
    return [(d.name, d.span.line, tuple(id(i) for i in via), c) for d, via, c in found]


@pytest.mark.parametrize("group", ["arguments", "files", "python", "scoping", "realistic"])
def test_shared_answers_equal_fresh_ones(group: str) -> None:
    # One workspace for the whole group (a zygote per tree made this 30 s): answers shared
    # across every file of the group must equal fresh ones, which is the stronger claim
    folder = CORPUS / group
    assert any(t.parent == folder for t in TREES)
    index = PackageIndex([folder])
    # a file whose evaluation fails has nothing to compare: the endless loop's need not
    # take the default 10 s to fail
    python = IsolatedPython(index, folder, limits=Limits(seconds=2.0))
    cache = FileCache(index, folder, python)
    shared: dict[Path, StaticSubtree] = {}
    compared = 0
    try:
        for path in discover([folder]):
            loaded = cache(path.resolve())
            if loaded.launch is None:
                continue
            compared += 1
            fresh = _key(static_arguments(loaded.launch, cache, index))
            reused = _key(static_arguments(loaded.launch, cache, index, shared))
            assert reused == fresh, path
    finally:
        python.close()
    assert compared >= sum(1 for t in TREES if t.parent == folder)


class _Recorder:
    """A Python loader that records what it is asked, and when."""

    def __init__(self) -> None:
        self.events: list[tuple[str, str]] = []

    def prefetch(self, paths: Iterable[Path]) -> None:
        self.events += [("prefetch", path.name) for path in paths]

    def load(self, path: Path, sink: ProblemSink) -> None:
        self.events.append(("load", path.name))


def test_reading_ahead_starts_included_python_files_before_the_walk(tmp_path: Path) -> None:
    """root.xml -> mid.xml -> leaf.launch.py: the Python file is started, not loaded."""
    (tmp_path / "leaf.launch.py").write_text("def generate_launch_description(): ...\n")
    (tmp_path / "mid.launch.xml").write_text(
        f'<launch><group if="$(var x)"><include file="{tmp_path}/leaf.launch.py"/></group>'
        "</launch>")
    (tmp_path / "root.launch.xml").write_text(
        f'<launch><include file="{tmp_path}/mid.launch.xml"/>'
        f'<include file="{tmp_path}/missing.launch.py"/></launch>')
    python = _Recorder()
    cache = FileCache(PackageIndex([tmp_path]), tmp_path, python)
    cache.read_ahead([tmp_path / "root.launch.xml"])
    assert python.events == [("prefetch", "leaf.launch.py")]
    cache(tmp_path / "leaf.launch.py")  # the walk reaches it: loaded, not started again
    assert python.events == [("prefetch", "leaf.launch.py"), ("load", "leaf.launch.py")]
