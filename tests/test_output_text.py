"""What people read: the concise format, grouped repeats, links to each rule's docs."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from launchverify.cli import main
from launchverify.render import links

CORPUS = Path(__file__).resolve().parent.parent / "corpus"
REPEATED = """<launch>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>
  <node pkg="demo_nodes_cpp" exec="listener" name="listener"/>
  <node pkg="demo_nodes_cpp" exec="listener" name="listener"/>
</launch>
"""


def _check(capsys: pytest.CaptureFixture[str], *arguments: str) -> tuple[int, str]:
    status = main(["check", *arguments, "--no-cache", "--color", "never"])
    return status, capsys.readouterr().out


def test_concise_is_one_line_per_finding(capsys: pytest.CaptureFixture[str]) -> None:
    tree = str(CORPUS / "naming" / "duplicate_same_scope")
    status, out = _check(capsys, tree, "--format", "concise")
    # (the demo packages are in no underlay here: a last line says they were not followed)
    *findings, summary = [line for line in out.splitlines()
                          if not line.startswith("Not followed: ")]
    assert status == 1 and summary.startswith("Found 2 findings")
    pattern = re.compile(r"^\S+:\d+:\d+: (error|warning|info) LV\d{3}( \[\*\])? \S.*$")
    assert findings and all(pattern.match(line) for line in findings), findings
    _, json_out = _check(capsys, tree, "--format", "json")
    assert len(findings) == len(json.loads(json_out)["findings"])
    quiet = _check(capsys, tree, "--output-format", "concise", "-q")[1]
    assert quiet == "\n".join(findings) + "\n"


def test_a_fixable_finding_is_marked_in_concise(capsys: pytest.CaptureFixture[str]) -> None:
    tree = str(CORPUS / "arguments" / "unknown_include_argument")
    out = _check(capsys, tree, "--format", "concise")[1]
    assert re.search(r"top\.launch\.xml:3:5: error LV204 \[\*\] argument 'use_sim_tme'", out)


def test_the_fixable_mark_stands_after_the_code_in_text_and_concise(
        capsys: pytest.CaptureFixture[str]) -> None:
    # one convention: ``severity CODE [*]`` in both formats (text once had ``[*] CODE``)
    tree = str(CORPUS / "arguments" / "unknown_include_argument")
    text = _check(capsys, tree)[1]
    assert re.search(r"top\.launch\.xml:3:5: error LV204 \[\*\] \[[a-z-]+\] argument "
                     r"'use_sim_tme'", text), text
    assert "[*] LV204" not in text
    concise = _check(capsys, tree, "--format", "concise")[1]
    assert "error LV204 [*] argument 'use_sim_tme'" in concise


def test_repeats_are_grouped_under_the_first(tmp_path: Path,
                                             capsys: pytest.CaptureFixture[str]) -> None:
    launch = tmp_path / "many.launch.xml"
    launch.write_text(REPEATED)
    out = _check(capsys, str(launch))[1]
    # /talker twice more and /listener once more: the same message at three places is
    # one group; the listener's is another finding (another message), never folded in
    headers = [line for line in out.splitlines() if re.match(r"^\S+:\d+:\d+: error", line)]
    assert len(headers) == 2, out
    assert out.count("also at ") == 1 and re.search(r"also at \S+many\.launch\.xml:4:3", out)
    concise = _check(capsys, str(launch), "--format", "concise", "-q")[1]
    assert len(concise.splitlines()) == 3  # machines and greps get every place


def test_every_finding_links_to_its_rule(monkeypatch: pytest.MonkeyPatch,
                                         capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.setattr(links, "documentation_base", lambda: "https://example.org/rules.md")
    tree = str(CORPUS / "naming" / "duplicate_same_scope")
    findings = json.loads(_check(capsys, tree, "--format", "json")[1])["findings"]
    assert {f["url"] for f in findings} == {
        "https://example.org/rules.md#lv101-duplicate-node-name"}
    out = _check(capsys, tree)[1]
    lines = [line for line in out.splitlines() if not line.startswith("Not followed: ")]
    assert lines[-2] == ("Why each matters and how to fix it: launchverify "
                         "explain LV101, --explain, or https://example.org/rules.md.")
    explained = _check(capsys, tree, "--explain")[1]
    assert "https://example.org/rules.md#lv101-duplicate-node-name" in explained
