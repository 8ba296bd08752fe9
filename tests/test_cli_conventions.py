"""The command line behaves as users expect of one (issue 44, items 3 to 7).

A file given by name is read for what it is (a parameter file through the launch files
that load it; anything else is a usage error); Ctrl-C exits 130 with nothing
half-written; ``-o -`` is standard output; ``--affected`` shows paths as every other
check does; ``run``'s own messages keep their line breaks while what they quote of the
checked files stays inert.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from launchverify.cli import main

ROOT = Path(__file__).resolve().parent.parent
DUPLICATE = ROOT / "corpus" / "naming" / "duplicate_same_scope" / "dup.launch.xml"

@pytest.fixture(autouse=True)
def _no_ros(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    monkeypatch.setenv("LAUNCHVERIFY_NO_CACHE", "1")


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


# 5. -o - is standard output


def test_output_dash_is_standard_output(tmp_path: Path, capsys: pytest.CaptureFixture[str],
                                        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    code, out, _ = run(capsys, "check", str(DUPLICATE), "-o", "-", "--format", "concise")
    assert code == 1 and "LV101" in out
    code, out, err = run(capsys, "report", str(DUPLICATE), "-o", "-")
    assert code == 1 and out.lstrip().lower().startswith("<!doctype html")
    assert "standard output" in err
    other = tmp_path / "other.launch.xml"
    other.write_text('<launch><node pkg="demo_nodes_cpp" exec="talker"/></launch>\n')
    code, out, _ = run(capsys, "diff", "--against", str(other), str(DUPLICATE), "-o", "-",
                       "--format", "json")
    assert code in (0, 1) and out.startswith("{")
    assert list(tmp_path.iterdir()) == [other]  # no file named '-'
    code, _, _ = run(capsys, "check", str(DUPLICATE), "-o", "./-")  # one named so
    assert code == 1 and (tmp_path / "-").read_text().startswith(str(DUPLICATE))
