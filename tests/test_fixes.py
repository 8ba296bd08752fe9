"""Fixes: ``check --fix``, ``--diff`` and ``--unsafe-fixes``, and how each format shows them.

``tests/data/fixes/cases`` holds one launch file per fix kind and format, each with the
mistake its name starts with; ``expected`` holds the same file as ``--fix`` must leave it,
byte for byte. Each is fixed inside a copy of ``workspace`` (a package ``demo`` with the
executables ``talker`` and ``listener``, ``config/params.yaml`` and
``launch/sensors.launch.xml``).
"""

from __future__ import annotations

import io
import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from test_formats import sarif_of, validate

from launchverify.cli import main
from launchverify.engine import CheckOptions, Report, run_check
from launchverify.findings import cache as result_cache
from launchverify.findings.fixes import fix_all, plan
from launchverify.render.github import render_github
from launchverify.render.junit import render_junit
from launchverify.rule import Applicability, Edit, Finding, Fix, Severity
from launchverify.span import Span
from launchverify.workspace.reading import unsaved

DATA = Path(__file__).resolve().parent / "data" / "fixes"
CASES = sorted((DATA / "cases").iterdir())


@pytest.fixture(autouse=True)
def _no_ros(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)


def workspace(tmp_path: Path, *cases: Path) -> Path:
    """Return a copy of the fixtures' workspace with the cases in its launch folder."""
    root = tmp_path / "ws"
    shutil.copytree(DATA / "workspace", root)
    for case in cases:
        shutil.copy(case, root / "src" / "demo" / "launch" / case.name)
    return root


def launch_file(root: Path, name: str, content: bytes) -> Path:
    path = root / "src" / "demo" / "launch" / name
    path.write_bytes(content)
    return path


def run(capsys: pytest.CaptureFixture[str], root: Path, *argv: str) -> tuple[int, str, str]:
    code = main(["check", *argv, "--workspace", str(root)])
    out, err = capsys.readouterr()
    return code, out, err


def codes(root: Path, path: Path) -> list[str]:
    report = run_check(CheckOptions(paths=[path], workspace=root))
    return [f.code for f in report.findings if f.span.file == path.resolve()]


@pytest.mark.parametrize("case", CASES, ids=lambda case: case.name)
def test_fix_leaves_the_expected_file(case: Path, tmp_path: Path,
                                      capsys: pytest.CaptureFixture[str]) -> None:
    expected = (DATA / "expected" / case.name).read_bytes()
    assert case.read_bytes() != expected, "a fixture must need a fix"
    code = case.name.split("_")[0].upper()
    root = workspace(tmp_path, case)
    path = root / "src" / "demo" / "launch" / case.name
    assert code in codes(root, path)
    _, _, err = run(capsys, root, str(path), "--fix")
    assert path.read_bytes() == expected
    assert "Fixed " in err and code not in codes(root, path)


def test_diff_prints_the_changes_and_writes_nothing(tmp_path: Path,
                                                    capsys: pytest.CaptureFixture[str]) -> None:
    case = DATA / "cases" / "lv201_var.launch.xml"
    root = workspace(tmp_path, case)
    path = root / "src" / "demo" / "launch" / case.name
    status, out, err = run(capsys, root, str(path), "--diff")
    assert status == 1
    assert path.read_bytes() == case.read_bytes()
    assert out.startswith(f"--- a/{path}\n+++ b/{path}\n@@ ")
    assert '-  <node pkg="demo" exec="talker" name="talker"   if="$(var use_sim_tme)"/>\n' in out
    assert '+  <node pkg="demo" exec="talker" name="talker"   if="$(var use_sim_time)"/>\n' in out
    assert "Would fix 1 finding." in err
    path.write_bytes((DATA / "expected" / case.name).read_bytes())
    assert run(capsys, root, str(path), "--diff")[:2] == (0, "")


def test_unsafe_fixes_are_applied_only_when_asked(tmp_path: Path,
                                                  capsys: pytest.CaptureFixture[str]) -> None:
    root = workspace(tmp_path)
    text = ('<launch>\n  <arg name="robot_name" default="a"/>\n  <arg name="robot_nm" '
            'default="b"/>\n  <node pkg="demo" exec="talker" name="$(var robot_nme)"/>\n'
            '</launch>\n')
    path = launch_file(root, "two.launch.xml", text.encode())
    status, out, err = run(capsys, root, str(path), "--fix")
    assert status == 1 and path.read_text() == text
    assert "LV201 [undeclared-argument]" in out and "LV201 [*]" not in out
    assert "Fixed 0 findings" in err and "1 hidden fix can be enabled with --unsafe-fixes" in err
    _, out, _ = run(capsys, root, str(path), "--unsafe-fixes")
    assert "LV201 [*] [undeclared-argument]" in out
    assert "[*] 1 fixable with --fix --unsafe-fixes." in out
    run(capsys, root, str(path), "--fix", "--unsafe-fixes")
    assert path.read_text() == text.replace("robot_nme", "robot_name")


def test_comments_line_endings_and_other_characters_survive(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    root = workspace(tmp_path)
    xml = ('<?xml version="1.0"?>\r\n<launch>\r\n\t<arg name="use_sim_time"  default="false" '
           '/>\r\n  <!-- caf\u00e9 --> <node pkg="demo"\texec="talkr" name="talker" '
           'if="$(var use_sim_tme)"/><!-- \u00e9 -->\r\n</launch>')
    python = ("from launch import LaunchDescription\r\nfrom launch_ros.actions import Node\r\n"
              "\r\n\r\ndef generate_launch_description():\r\n"
              "    return LaunchDescription([Node(name='t\u00e9', package='demo', "
              "executable='talkr')])  # \u00e9\r\n")
    xml_path = launch_file(root, "crlf.launch.xml", xml.encode())
    python_path = launch_file(root, "crlf.launch.py", python.encode())
    run(capsys, root, str(xml_path), str(python_path), "--fix")
    fixed_xml = xml.replace('"talkr"', '"talker"').replace("use_sim_tme", "use_sim_time")
    assert xml_path.read_bytes() == fixed_xml.encode()
    assert python_path.read_bytes() == python.replace("'talkr'", "'talker'").encode()


def test_a_removed_suppression_keeps_the_rest_of_its_line(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    root = workspace(tmp_path)
    path = launch_file(root, "kept.launch.xml", (
        b'<launch>\n  <arg name="unused" default="1"/>  '
        b"<!-- launchverify: ignore[LV101, unused-argument, LV5] --> <!-- note -->\n"
        b"</launch>\n"))
    assert run(capsys, root, str(path), "--fix")[0] == 0
    assert path.read_bytes() == (b'<launch>\n  <arg name="unused" default="1"/>  '
                                 b"<!-- launchverify: ignore[unused-argument] --> "
                                 b"<!-- note -->\n</launch>\n")
    assert codes(root, path) == []


def test_a_hash_in_a_python_string_is_no_suppression(tmp_path: Path) -> None:
    root = workspace(tmp_path, DATA / "cases" / "lv004_suppression.launch.py")
    path = root / "src" / "demo" / "launch" / "lv004_suppression.launch.py"
    report = run_check(CheckOptions(paths=[path], workspace=root))
    assert [f.span.line for f in report.findings if f.code == "LV004"] == [8, 10]


def test_standard_input_is_fixed_to_standard_output(tmp_path: Path) -> None:
    case = DATA / "cases" / "lv304_executable.launch.yaml"
    root = workspace(tmp_path, case)
    path = root / "src" / "demo" / "launch" / case.name
    path.write_text("launch: []\n")  # what is on disk is not what is checked
    done = subprocess.run(
        [sys.executable, "-m", "launchverify", "check", "-", "--stdin-filename", str(path),
         "--workspace", str(root), "--fix"],
        input=case.read_bytes(), capture_output=True, check=False)
    assert done.returncode == 0, done.stderr
    assert done.stdout == (DATA / "expected" / case.name).read_bytes()
    assert b"Fixed 1 finding (0 remaining)." in done.stderr
    assert path.read_text() == "launch: []\n"


def test_a_fix_invalidates_the_cached_result(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                             capsys: pytest.CaptureFixture[str]) -> None:
    monkeypatch.delenv("LAUNCHVERIFY_NO_CACHE", raising=False)
    monkeypatch.setattr(result_cache, "CLOCK_SLACK", 0.0)  # the files were written just now
    case = DATA / "cases" / "lv303_package.launch.xml"
    root = workspace(tmp_path, case)
    path = root / "src" / "demo" / "launch" / case.name
    cache = ["--cache-dir", str(tmp_path / "cache")]
    assert run(capsys, root, str(path), *cache)[0] == 1
    status, out, _ = run(capsys, root, str(path), *cache)
    assert status == 1 and "unchanged since the cached run" in out
    assert run(capsys, root, str(path), *cache, "--fix")[0] == 0
    status, out, _ = run(capsys, root, str(path), *cache)
    assert status == 0 and "No findings" in out and "cached" not in out


# ----------------------------------------------------------------------------- exact places

XML = ('<launch>\n  <arg name="use_sim_time" default="false"/>\n'
       '  <node pkg="demo" exec="talker" {}/>\n</launch>\n')
YAML = ('launch:\n- arg: {{name: use_sim_time, default: "false"}}\n'
        "- node: {{pkg: demo, exec: talker, {}}}\n")
PYTHON = ("from launch import LaunchDescription\n"
          "from launch.actions import DeclareLaunchArgument\n"
          "from launch.conditions import IfCondition\n"
          "from launch.substitutions import LaunchConfiguration\n"
          "from launch_ros.actions import Node\n"
          "\n\ndef generate_launch_description():\n    name = 'use_sim_tme'\n"
          "    return LaunchDescription([\n"
          "        DeclareLaunchArgument('use_sim_time', default_value='false'),\n"
          "        Node(package='demo', executable='talker', condition=IfCondition({})),\n"
          "    ])\n")


@pytest.mark.parametrize(("name", "template", "written", "located"), [
    ("plain.launch.xml", XML, 'if="$(var use_sim_tme)"', True),
    ("quoted.launch.xml", XML, """if="$(var 'use_sim_tme')\"""", True),
    ("escaped.launch.xml", XML, 'if="$(var use_sim\\_tme)"', False),
    ("entity.launch.xml", XML, 'if="$(var use_sim_tme)&#x20;"', False),
    ("plain.launch.yaml", YAML, "if: $(var use_sim_tme)", True),
    ("quoted.launch.yaml", YAML, "if: '$(var use_sim_tme)'", True),
    ("anchored.launch.yaml", YAML, "if: &c $(var use_sim_tme)", False),
    ("literal.launch.py", PYTHON, "LaunchConfiguration('use_sim_tme')", True),
    ("joined.launch.py", PYTHON, "LaunchConfiguration('use_sim_' 'tme')", False),
    ("raw.launch.py", PYTHON, "LaunchConfiguration(r'use_sim_tme')", False),
    ("variable.launch.py", PYTHON, "LaunchConfiguration(name)", False),
])
def test_only_a_literal_written_verbatim_gets_a_fix(
        name: str, template: str, written: str, located: bool, tmp_path: Path) -> None:
    root = workspace(tmp_path)
    path = launch_file(root, name, template.format(written).encode())
    report = run_check(CheckOptions(paths=[path], workspace=root))
    (read,) = [f for f in report.findings if f.code == "LV201"]
    assert (read.fix is not None) is located
    if read.fix is not None:
        (edit,) = read.fix.edits
        line = path.read_text().splitlines()[edit.span.line - 1]
        assert line[edit.span.column - 1:edit.span.end_column - 1] == "use_sim_tme"


# ----------------------------------------------------------------------------- applying


def finding(path: Path, line: int, *edits: tuple[int, int, str]) -> Finding:
    """Return a finding on ``line`` whose fix replaces (column, end column) with text."""
    fix = Fix("edit", tuple(Edit(Span(path, line, start, line, end), text)
                            for start, end, text in edits))
    return Finding("LV201", "undeclared-argument", Severity.ERROR, f"at {edits}",
                   Span(path, line, edits[0][0]), fix=fix)


def test_overlapping_edits_wait_for_the_next_pass(tmp_path: Path) -> None:
    path = tmp_path / "x.launch.xml"
    path.write_bytes(b"0123456789\r\nabcdef\r\n")
    first = finding(path, 1, (3, 6, "<first>"))
    overlapping = finding(path, 1, (5, 9, "<second>"))
    after = finding(path, 1, (9, 10, "<third>"))
    same = finding(path, 1, (3, 6, "<first>"))
    elsewhere = finding(path, 2, (1, 1, "<"), (7, 7, ">"))
    step = plan([first, overlapping, after, same, elsewhere], Path.read_bytes, unsafe=False)
    assert step.fixed == [first, after, same, elsewhere]  # the re-check finds the other again
    assert step.contents == {path: b"01<first>567<third>9\r\n<abcdef>\r\n"}
    assert path.read_bytes() == b"0123456789\r\nabcdef\r\n"  # in memory only


def test_edits_that_cannot_be_placed_exactly_are_left_out(tmp_path: Path) -> None:
    path = tmp_path / "x.launch.yaml"
    path.write_bytes(b"ab\r\ncd\n")
    beyond = finding(path, 2, (2, 9, "x"))
    inside_crlf = finding(path, 1, (3, 4, "x"))
    unsafe = Finding("LV201", "undeclared-argument", Severity.ERROR, "unsafe",
                     Span(path, 1, 1), fix=Fix("x", (Edit(Span(path, 1, 1, 1, 2), "z"),),
                                               Applicability.UNSAFE))
    step = plan([beyond, inside_crlf, unsafe], Path.read_bytes, unsafe=False)
    assert step.contents == {} and step.fixed == [] and len(step.notes) == 2
    latin = tmp_path / "latin.launch.xml"
    latin.write_bytes(b"caf\xe9\n")
    step = plan([finding(latin, 1, (1, 2, "C"))], Path.read_bytes, unsafe=True)
    assert step.contents == {} and "not UTF-8" in step.notes[0]


def test_a_fix_that_breaks_the_file_is_undone(tmp_path: Path) -> None:
    path = tmp_path / "x.launch.xml"
    path.write_bytes(b"<launch/>\n")
    breaking = finding(path, 1, (2, 8, "oops"))

    def check() -> Report:  # what the parser would say of the buffered text
        current = unsaved(path) or path.read_bytes()
        broken = Finding("LV001", "parse-error", Severity.ERROR, "bad", Span(path, 1))
        return Report([broken] if b"oops" in current else [], 1, 0.0, {})

    outcome = fix_all(Report([breaking], 1, 0.0, {}), check, unsafe=False)
    assert outcome.fixed == {} and outcome.count == 0
    assert "would no longer parse" in outcome.notes[0]


# ----------------------------------------------------------------------------- formats


def fixture_report(tmp_path: Path) -> tuple[Path, Report]:
    root = workspace(tmp_path, *(DATA / "cases").glob("*.launch.xml"))
    return root, run_check(CheckOptions(paths=[root / "src"], workspace=root))


def test_json_gives_each_finding_its_fix(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                         capsys: pytest.CaptureFixture[str]) -> None:
    root = workspace(tmp_path, DATA / "cases" / "lv304_executable.launch.xml")
    monkeypatch.chdir(root)
    main(["check", "src", "--format", "json", "--workspace", "."])
    findings = json.loads(capsys.readouterr().out)["findings"]
    (fixed,) = [f for f in findings if f["code"] == "LV304"]
    assert fixed["fix"] == {
        "applicability": "safe", "message": "replace 'talkr' with 'talker'",
        "edits": [{"file": "src/demo/launch/lv304_executable.launch.xml", "line": 2,
                   "column": 26, "end_line": 2, "end_column": 31, "content": "talker"}]}
    assert all(f["fix"] is None for f in findings if f["code"] != "LV304")


def test_sarif_fixes_are_valid_and_replace_the_spans(tmp_path: Path) -> None:
    root, report = fixture_report(tmp_path)
    document = sarif_of(report, root=root)
    validate(document)
    results = document["runs"][0]["results"]
    fixes = [r["fixes"][0] for r in results if "fixes" in r]
    assert len(fixes) >= 8
    removal = next(f for f in fixes if f["description"]["text"].startswith("remove the"))
    (change,) = removal["artifactChanges"]
    assert change["artifactLocation"]["uri"] == "src/demo/launch/lv004_suppression.launch.xml"
    assert change["replacements"] == [{"deletedRegion": {
        "startLine": 2, "startColumn": 1, "endLine": 3, "endColumn": 1}}]
    assert {f["properties"]["applicability"] for f in fixes} == {"safe"}


def test_text_github_and_junit_say_what_is_fixable(tmp_path: Path) -> None:
    _, report = fixture_report(tmp_path)
    out = io.StringIO()
    render_github(report, out)
    assert "title=LV304 unknown-executable (fixable with --fix)::" in out.getvalue()
    out = io.StringIO()
    render_junit(report, out)
    assert "[unknown-executable] package 'demo' has no executable 'talkr' (did you mean " \
        "'talker'?) (fixable with --fix)" in out.getvalue()
