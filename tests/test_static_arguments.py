"""Static argument discovery answers the same whether included files' answers are reused."""

from __future__ import annotations

from pathlib import Path

import pytest

from launchverify.evaluate.files import FileCache
from launchverify.evaluate.static_args import Found, StaticSubtree, static_arguments
from launchverify.workspace.discover import discover
from launchverify.workspace.packages import PackageIndex

CORPUS = Path(__file__).resolve().parent.parent / "corpus"
TREES = [p for p in sorted(CORPUS.glob("*/*")) if p.is_dir()
         and any(discover([p]))]


def _key(found: list[Found]) -> list[tuple[str, int, tuple[int, ...], bool]]:
    return [(d.name, d.span.line, tuple(id(i) for i in via), c) for d, via, c in found]


@pytest.mark.parametrize("group", ["arguments", "files", "python", "scoping", "realistic"])
def test_shared_answers_equal_fresh_ones(group: str) -> None:
    trees = [t for t in TREES if t.parent.name == group]
    assert trees
    for tree in trees:
        index = PackageIndex([tree])
        cache = FileCache(index, tree)
        shared: dict[Path, StaticSubtree] = {}
        try:
            for path in discover([tree]):
                loaded = cache(path.resolve())
                if loaded.launch is None:
                    continue
                fresh = _key(static_arguments(loaded.launch, cache, index))
                reused = _key(static_arguments(loaded.launch, cache, index, shared))
                assert reused == fresh, path
        finally:
            cache.close()
