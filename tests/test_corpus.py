"""The corpus is the test: each tree's findings must match its inline markers exactly."""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import pytest
from corpus_markers import read_markers

from launchverify.engine import CheckOptions, run_check
from launchverify.rule import Severity
from launchverify.workspace.discover import discover

CORPUS = Path(__file__).resolve().parent.parent / "corpus"
TREES = sorted(p for p in CORPUS.glob("*/*") if p.is_dir())


def test_corpus_is_large_enough() -> None:
    assert len(TREES) >= 40


@pytest.mark.parametrize("tree", TREES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_corpus_tree(tree: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    marks = read_markers(tree)
    if not discover([tree]) and not marks.expected and not marks.forbidden:
        pytest.skip("no launch files: a helper of other tests (executor/nodes)")
    # 4 s per Python file is far above what any corpus file takes on a loaded machine, and
    # the endless loop's LV002 need not wait the default 10 s
    report = run_check(CheckOptions(paths=[tree], workspace=tree, time_limit=4.0))
    actual: Counter[tuple[str, int, str]] = Counter()
    described = {}
    for finding in report.findings:
        key = (finding.span.file.relative_to(tree.resolve()).as_posix(), finding.span.line,
               finding.code)
        if (finding.severity is Severity.INFO and key not in marks.expected
                and key not in marks.forbidden):
            continue  # infos count only where a fixture marks them
        severity = marks.severities.get(key, finding.severity.value)
        if severity != finding.severity.value:
            key = (*key[:2], f"{key[2]} as {finding.severity.value}")  # the wrong severity
        actual[key] += 1
        described[key] = finding.message
    missing = marks.expected - actual
    unexpected = actual - marks.expected
    near_misses = {k for k in marks.forbidden if k in actual}
    lines = [f"missing   {k}" for k in sorted(missing)]
    lines += [f"unexpected {k}: {described[k]}" for k in sorted(unexpected)]
    lines += [f"expect-not reported {k}" for k in sorted(near_misses)]
    assert not lines, "\n".join(lines)
