"""What the SMT-backed rules promise on the command line: witnesses, pins, explanations."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from launchverify.cli import main

CORPUS = Path(__file__).resolve().parent.parent / "corpus" / "conditions"
DUPLICATES = CORPUS / "path_sensitive_duplicates" / "robot.launch.xml"
UNREACHABLE = CORPUS / "unreachable_conditions" / "robot.launch.xml"


def findings(capsys: pytest.CaptureFixture[str], *argv: str) -> list[dict[str, object]]:
    main(["check", *argv, "--format", "json"])
    result: list[dict[str, object]] = json.loads(capsys.readouterr().out)["findings"]
    return result


def test_witness_names_the_arguments(capsys: pytest.CaptureFixture[str]) -> None:
    found = {f["line"]: f["witness"] for f in findings(capsys, str(DUPLICATES))
             if f["code"] == "LV101"}
    assert found == {11: {"use_sim": "true"}, 20: {"mode": "mapping"},
                     34: {"mode": "mapping"}}


def test_pinned_arguments_are_not_varied(capsys: pytest.CaptureFixture[str]) -> None:
    found = {f["line"]: f["witness"] for f in findings(
        capsys, str(DUPLICATES), "use_sim:=false", "mode:=mapping") if f["code"] == "LV101"}
    # use_sim is pinned to false: the simulated talker never runs; mode is pinned to
    # mapping: those collisions happen under the arguments as given (no witness).
    assert found == {20: None, 34: None}


def test_text_output_shows_the_witness(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check", str(DUPLICATES)]) == 1
    out = capsys.readouterr().out
    assert "when: use_sim:=true" in out
    assert "when: mode:=mapping" in out


def test_unreachable_condition_explains_itself(capsys: pytest.CaptureFixture[str]) -> None:
    messages = {f["line"]: f["message"] for f in findings(capsys, str(UNREACHABLE))
                if f["code"] == "LV205" and str(f["file"]).endswith("robot.launch.xml")}
    assert set(messages) == {11, 18}
    assert "`$(var use_sim)` (robot.launch.xml:8)" in str(messages[11])
    assert "`not $(var use_sim)` (robot.launch.xml:11)" in str(messages[11])
    assert "mode is one of ['slow', 'safe']" in str(messages[18])


def test_z3_is_imported_only_when_needed() -> None:
    import subprocess
    import sys

    code = ("import sys; from launchverify.cli import main; "
            f"main(['check', {str(CORPUS.parent / 'naming' / 'duplicate_same_scope')!r}]); "
            "print('z3' in sys.modules)")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          check=False)
    assert done.stdout.strip().endswith("False"), done.stdout + done.stderr


def test_environment_can_be_pinned(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    launch = tmp_path / "env.launch.xml"
    launch.write_text(
        '<launch>\n'
        '  <node pkg="demo_nodes_cpp" exec="talker" name="talker" namespace="$(env ROBOT r1)"/>\n'
        '  <node pkg="demo_nodes_cpp" exec="talker" name="talker" namespace="r2"/>\n'
        '</launch>\n')
    assert findings(capsys, str(launch)) == []
    pinned = findings(capsys, str(launch), "--env", "ROBOT=r2")
    assert [(f["code"], f["line"]) for f in pinned] == [("LV101", 3)]
    assert main(["check", str(launch), "--env", "ROBOT"]) == 2
