"""The README's snippets work against this repository as it is (issue 44, item 8).

Tags do not travel with this repository: a snippet naming one (``rev: v0.1.0``,
``pip install git+...@v0.1.0``) fails for whoever copies it. The figures the first hour
quotes are what the quick start's check prints now.
"""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

import pytest

from launchverify.cli import main

ROOT = Path(__file__).resolve().parent.parent
README = (ROOT / "README.md").read_text(encoding="utf-8")


def _tags() -> set[str]:
    """Return the tags of the checkout (none where it is no git checkout)."""
    done = subprocess.run(["git", "tag", "--list"], cwd=ROOT, capture_output=True,
                          text=True, check=False)
    return set(done.stdout.split()) if done.returncode == 0 else set()


def test_no_snippet_needs_a_tag_the_repository_lacks() -> None:
    named = set(re.findall(r"github\.com/launchverify/launchverify@([^\s\"'`]+)", README))
    revs = set(re.findall(r"^\s*rev: (\S+)$", README, flags=re.M))
    assert revs == {"main"}, revs  # pre-commit: a branch, pinned by `pre-commit autoupdate`
    assert named <= {"main"} | _tags(), named  # a git URL installs main, or a tag there
    assert "pre-commit autoupdate" in README and "mutable reference" in README
    assert "pip install launchverify" not in README  # not on PyPI
    releasing = (ROOT / "docs" / "releasing.md").read_text(encoding="utf-8")
    assert "git tag -a" in releasing and "git push origin" in releasing


def test_the_first_hour_quotes_what_the_quick_start_prints(
        capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(ROOT)
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    monkeypatch.setenv("LAUNCHVERIFY_NO_CACHE", "1")
    first = re.search(r"```sh\n(.*?)\n```", README[README.index("## Quick start"):],
                      flags=re.S)
    assert first is not None and first[1].endswith("launchverify check corpus/naming")
    assert main(["check", "corpus/naming"]) == 1
    out = next((line for line in capsys.readouterr().out.splitlines()
                if line.startswith("Found ")), "")
    quoted = re.search(r"`(Found (\d+) findings \([^`]*\) in \d+ files)`", README)
    assert quoted is not None
    assert out.startswith(quoted[1]), (out, quoted[1])
    assert f"prints {quoted[2]} findings" in README


def test_the_readme_says_how_long_the_tests_take() -> None:
    section = README[README.index("## Quick start"):README.index("### The first hour")]
    assert re.search(r"(about|under) \d+ minutes on 2 cores", section)
    assert ".ci/run" in section
