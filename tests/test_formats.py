"""The CI output formats: SARIF (schema-valid, stable fingerprints), JUnit XML, GitHub."""

from __future__ import annotations

import io
import json
import re
import shutil
import sys
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from jsonschema import validators  # type: ignore[import-untyped, unused-ignore]

from launchverify import __version__
from launchverify.engine import CheckOptions, Report, run_check
from launchverify.findings.fingerprint import fingerprint_fields
from launchverify.registry import all_rules
from launchverify.render import links
from launchverify.render import text as text_output
from launchverify.render.github import escape_data, escape_property, render_github
from launchverify.render.junit import render_junit
from launchverify.render.sarif import render_sarif
from launchverify.rule import Finding, Severity
from launchverify.span import Span

CORPUS = Path(__file__).resolve().parent.parent / "corpus"
SCHEMA = Path(__file__).resolve().parent / "data" / "sarif-schema-2.1.0.json"
DUPLICATES = CORPUS / "naming" / "duplicate_same_scope"
TRACE = CORPUS / "lifecycle" / "activate_at_start"
WITNESS = CORPUS / "conditions" / "path_sensitive_duplicates"
INCLUDES = CORPUS / "naming" / "duplicate_across_includes"


@pytest.fixture(autouse=True)
def _no_ros(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)


def check(*paths: Path, workspace: Path | None = None) -> Report:
    return run_check(CheckOptions(paths=list(paths), workspace=workspace or paths[0]))


def sarif_of(report: Report, root: Path | None = None) -> dict[str, Any]:
    out = io.StringIO()
    render_sarif(report, out, root=root)
    document: dict[str, Any] = json.loads(out.getvalue())
    return document


def validate(document: dict[str, Any]) -> None:
    schema = json.loads(SCHEMA.read_text(encoding="utf-8"))
    validator_class = validators.validator_for(schema)
    validator_class.check_schema(schema)
    errors = sorted(validator_class(schema).iter_errors(document), key=str)
    assert not errors, "\n".join(f"{list(e.absolute_path)}: {e.message}" for e in errors[:5])


def fingerprints(document: dict[str, Any]) -> list[str]:
    return [r["partialFingerprints"]["launchverify/v1"] for r in document["runs"][0]["results"]]


def write(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


# ----------------------------------------------------------------------------- SARIF


def test_sarif_is_valid_against_the_official_schema() -> None:
    report = check(DUPLICATES)
    report.findings += check(TRACE).findings + check(WITNESS).findings
    report.findings += check(INCLUDES).findings
    document = sarif_of(report, root=CORPUS.parent)
    assert document["version"] == "2.1.0"
    assert len(document["runs"][0]["results"]) == len(report.findings) >= 8
    validate(document)


def test_sarif_driver_lists_every_rule() -> None:
    driver = sarif_of(check(DUPLICATES))["runs"][0]["tool"]["driver"]
    assert driver["name"] == "launchverify" and driver["version"] == __version__
    assert driver["informationUri"].startswith("https://")
    assert [r["id"] for r in driver["rules"]] == [r.code for r in all_rules()]
    lv101 = next(r for r in driver["rules"] if r["id"] == "LV101")
    assert lv101["name"] == "DuplicateNodeName"
    assert lv101["shortDescription"]["text"].startswith("Two nodes that can run together")
    assert "## Why it matters" in lv101["help"]["markdown"]
    assert "## " not in lv101["fullDescription"]["text"]
    assert lv101["defaultConfiguration"]["level"] == "error"
    assert "naming" in lv101["properties"]["tags"]
    levels = {r["id"]: r["defaultConfiguration"]["level"] for r in driver["rules"]}
    assert {levels[r.code] for r in all_rules() if r.severity is Severity.INFO} == {"note"}


def test_sarif_results_point_at_findings(tmp_path: Path) -> None:
    report = check(DUPLICATES)
    run = sarif_of(report, root=CORPUS)["runs"][0]
    rules = run["tool"]["driver"]["rules"]
    first = run["results"][0]
    assert first["ruleId"] == "LV101" and rules[first["ruleIndex"]]["id"] == "LV101"
    assert first["level"] == "error"
    location = first["locations"][0]["physicalLocation"]
    assert location["artifactLocation"] == {
        "uri": "naming/duplicate_same_scope/dup.launch.xml", "uriBaseId": "%SRCROOT%",
    }
    assert location["region"]["startLine"] == 4 and location["region"]["startColumn"] == 3
    assert first["relatedLocations"][0]["message"]["text"] == "first started here"
    assert first["relatedLocations"][0]["physicalLocation"]["region"]["startLine"] == 3
    assert run["originalUriBaseIds"]["%SRCROOT%"]["uri"] == CORPUS.as_uri() + "/"
    outside = sarif_of(report, root=tmp_path)["runs"][0]["results"][0]["locations"][0]
    artifact = outside["physicalLocation"]["artifactLocation"]
    assert artifact == {"uri": (DUPLICATES / "dup.launch.xml").resolve().as_uri()}


def test_sarif_include_chain_witness_and_trace() -> None:
    results = sarif_of(check(INCLUDES))["runs"][0]["results"]
    related = results[0]["relatedLocations"]
    assert related[-1]["message"]["text"] == "included from here"
    assert len({place["id"] for place in related}) == len(related)

    witnessed = sarif_of(check(WITNESS))["runs"][0]["results"][0]
    assert witnessed["properties"]["witness"] == {"use_sim": "true"}
    assert witnessed["message"]["text"].endswith("(when: use_sim:=true)")

    traced = next(r for r in sarif_of(check(TRACE))["runs"][0]["results"]
                  if r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"]
                  .endswith(".py"))
    steps = traced["codeFlows"][0]["threadFlows"][0]["locations"]
    assert steps[0]["location"] == {"message": {"text": "the launch starts"}}
    assert all("physicalLocation" in step["location"] for step in steps[1:])
    assert steps[-1]["location"]["physicalLocation"]["region"]["startLine"] == 18


def test_sarif_help_uri_comes_from_the_documentation_url(
        monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    from launchverify.process import distributions

    info = tmp_path / "launchverify-9.0.dist-info"  # first on the path: it wins
    info.mkdir()
    (info / "METADATA").write_text(
        "Metadata-Version: 2.1\nName: launchverify\n"
        "Project-URL: Homepage, https://example.org/lv\n"
        "Project-URL: Documentation, https://example.org/docs/rules.md\n\nThe README.\n"
        "Project-URL: Body, https://example.org/not-a-header\n")
    monkeypatch.setattr(sys, "path", [str(tmp_path), *sys.path])
    distributions.distributions.cache_clear()
    links.project_urls.cache_clear()
    try:
        assert links.project_urls() == {"homepage": "https://example.org/lv",
                                        "documentation": "https://example.org/docs/rules.md"}
        driver = sarif_of(check(DUPLICATES))["runs"][0]["tool"]["driver"]
    finally:
        distributions.distributions.cache_clear()
        links.project_urls.cache_clear()
    lv101 = next(r for r in driver["rules"] if r["id"] == "LV101")
    assert lv101["helpUri"] == "https://example.org/docs/rules.md#lv101-duplicate-node-name"
    assert driver["informationUri"] == "https://example.org/lv"

    monkeypatch.setattr(links, "project_urls", dict)
    driver = sarif_of(check(DUPLICATES))["runs"][0]["tool"]["driver"]
    assert all("helpUri" not in rule for rule in driver["rules"])


@pytest.mark.parametrize("fixture", [DUPLICATES, WITNESS, TRACE], ids=lambda p: p.name)
def test_fingerprints_survive_lines_inserted_above(fixture: Path, tmp_path: Path) -> None:
    tree = tmp_path / "tree"
    shutil.copytree(fixture, tree)
    before = sarif_of(check(tree), root=tmp_path)
    for path in tree.iterdir():
        first, rest = path.read_text(encoding="utf-8").split("\n", 1)
        write(path, f"{first}\n\n\n\n{rest}")  # below <launch>, launch: or a docstring
    after = sarif_of(check(tree), root=tmp_path)
    old_lines = [r["locations"][0]["physicalLocation"]["region"]["startLine"]
                 for r in before["runs"][0]["results"]]
    new_lines = [r["locations"][0]["physicalLocation"]["region"]["startLine"]
                 for r in after["runs"][0]["results"]]
    assert new_lines == [line + 3 for line in old_lines]
    assert fingerprints(after) == fingerprints(before)
    assert len(set(fingerprints(before))) == len(fingerprints(before)) > 0


def test_fingerprints_tell_identical_findings_apart(tmp_path: Path) -> None:
    launch = write(tmp_path / "a.launch.xml", "<launch>\n  <node/>\n  <node/>\n</launch>\n")
    finding = Finding("LV101", "duplicate-node-name", Severity.ERROR, "same at a.xml:2",
                      Span(launch, 2, 3))
    twin = Finding("LV101", "duplicate-node-name", Severity.ERROR, "same at a.xml:3",
                   Span(launch, 3, 3))
    other = Finding("LV102", "invalid-name", Severity.ERROR, "same at a.xml:2",
                    Span(launch, 2, 3))
    report = Report([finding, twin, other], 1, 0.0, {})
    values = fingerprints(sarif_of(report, root=tmp_path))
    assert len(set(values)) == 3
    # blanking line numbers alone would make the first two equal; the counter separates them
    assert fingerprint_fields(finding, tmp_path) == fingerprint_fields(twin, tmp_path)


def test_sarif_of_a_missing_file_still_renders(tmp_path: Path) -> None:
    gone = Finding("LV001", "parse-error", Severity.ERROR, "broken", Span(tmp_path / "x.xml", 7))
    document = sarif_of(Report([gone], 1, 0.0, {}), root=tmp_path)
    validate(document)
    region = document["runs"][0]["results"][0]["locations"][0]["physicalLocation"]["region"]
    assert region == {"startLine": 7, "startColumn": 1}


# ----------------------------------------------------------------------------- text


class _ThroughRich(text_output.Lines):
    """The reference: every line printed by rich, even where it would only strip styles."""

    def __init__(self, out: Any, color: bool | None) -> None:
        super().__init__(out, color)
        from rich.console import Console

        self.styled = Console(file=out, highlight=False, soft_wrap=True, no_color=True)


def _text(report: Report, monkeypatch: pytest.MonkeyPatch, *, rich: bool) -> str:
    out = io.StringIO()
    with monkeypatch.context() as patch:
        if rich:
            patch.setattr(text_output, "Lines", _ThroughRich)
        text_output.render_text(report, out, explain=True)
    return out.getvalue()


def test_plain_text_is_what_rich_prints_without_colours(
        monkeypatch: pytest.MonkeyPatch) -> None:
    report = check(TRACE, WITNESS, INCLUDES, DUPLICATES, workspace=CORPUS)
    assert report.findings and text_output.Lines(io.StringIO(), None).styled is None
    assert _text(report, monkeypatch, rich=False) == _text(report, monkeypatch, rich=True)


_PIECES = st.sampled_from([*"ab :[]/\\*\t\u3042\r\x07\x08\x0b\x0c\x1b\u00e9\n", ":100:", ":smile:",
                           "[bold]", "[/]"])


@settings(max_examples=60, deadline=None)
@given(st.lists(st.lists(_PIECES, max_size=12).map("".join), min_size=1, max_size=4))
def test_any_message_prints_the_same_both_ways(messages: list[str]) -> None:
    findings = [Finding("LV101", "duplicate-node-name", Severity.ERROR, message,
                        Span(Path("/nowhere/a.launch.xml"), 100, 7)) for message in messages]
    report = Report(findings, 1, 0.0, {})
    with pytest.MonkeyPatch.context() as monkeypatch:
        assert _text(report, monkeypatch, rich=False) == _text(report, monkeypatch, rich=True)


def test_places_and_messages_print_verbatim() -> None:
    """rich would read ``:100:`` as an emoji code and ``[bold]`` as markup."""
    odd = Finding("LV101", "duplicate-node-name", Severity.ERROR, "see [bold]x[/] :smile:",
                  Span(Path("/nowhere/a.launch.xml"), 100, 7))
    for color in (None, True):
        out = io.StringIO()
        text_output.render_text(Report([odd], 1, 0.0, {}), out, color=color)
        assert "a.launch.xml" in out.getvalue()
        plain = re.sub(r"\x1b\[[0-9;]*m", "", out.getvalue())
        assert "a.launch.xml:100:7: error LV101 [duplicate-node-name] see [bold]x[/] :smile:" \
            in plain


# ----------------------------------------------------------------------------- JUnit


def junit_of(report: Report, checked: list[Path] | None = None) -> tuple[str, ET.Element]:
    out = io.StringIO()
    render_junit(report, out, checked=checked)
    return out.getvalue(), ET.fromstring(out.getvalue())


def test_junit_has_one_case_per_file_and_fails_files_with_errors(
        monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(CORPUS)
    report = check(Path("naming/duplicate_across_includes"))
    _, suite = junit_of(report)
    assert suite.tag == "testsuite" and suite.get("name") == "launchverify"
    cases = {case.get("name"): case for case in suite.iter("testcase")}
    folder = "naming/duplicate_across_includes"
    assert set(cases) == {f"{folder}/{name}" for name in
                          ("bringup.launch.xml", "camera.launch.xml", "robot.launch.xml")}
    assert all(case.get("classname") == "launchverify" for case in cases.values())
    failed = {name for name, case in cases.items() if case.find("failure") is not None}
    assert failed == {f"{folder}/camera.launch.xml"}
    failure = cases[f"{folder}/camera.launch.xml"].find("failure")
    assert failure is not None and failure.get("type") == "error"
    assert (failure.text or "").startswith("2:3 LV101 [duplicate-node-name] node name")
    assert suite.get("tests") == "3" and suite.get("failures") == "1"
    assert suite.get("errors") == "0" and suite.get("skipped") == "0"


def test_junit_checked_files_and_info_only_files_pass(tmp_path: Path) -> None:
    info = write(tmp_path / "info.launch.xml",
                 '<launch>\n  <node pkg="demo_nodes_cpp" exec="talker" name="talker"'
                 ' if="true"/>\n</launch>\n')
    clean = write(tmp_path / "clean.launch.xml", "<launch/>\n")
    report = check(tmp_path)
    assert [f.severity for f in report.findings] == [Severity.INFO]
    _, suite = junit_of(report, checked=[clean, info])
    cases = list(suite.iter("testcase"))
    assert [case.get("name") for case in cases] == [str(clean), str(info)]
    assert all(case.find("failure") is None for case in cases)
    assert "LV206" in (cases[1].findtext("system-out") or "")
    assert suite.get("failures") == "0"


def test_junit_escapes_names_and_messages(tmp_path: Path) -> None:
    evil = write(tmp_path / "r&d.launch.xml",
                 '<launch>\n  <node pkg="demo_nodes_cpp" exec="talker"'
                 ' name="&lt;script&gt;&amp;&quot;"/>\n</launch>\n')
    report = check(tmp_path)
    assert report.findings and '<script>&"' in report.findings[0].message
    text, suite = junit_of(report)
    assert "<script>" not in text
    case = next(suite.iter("testcase"))
    assert case.get("name") == str(evil)
    failure = case.find("failure")
    assert failure is not None and '<script>&"' in (failure.text or "")


def test_junit_drops_no_character_xml_cannot_hold(tmp_path: Path) -> None:
    odd = Finding("LV002", "evaluation-error", Severity.ERROR, "bell \x07 and \x1b[0m",
                  Span(tmp_path / "x.launch.xml", 1))
    _, suite = junit_of(Report([odd], 1, 0.0, {}))
    assert "\\x07" in (suite.findtext("testcase/failure") or "")


# ----------------------------------------------------------------------------- GitHub


def github_of(report: Report) -> list[str]:
    out = io.StringIO()
    render_github(report, out)
    return out.getvalue().splitlines()


def test_github_annotations(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(CORPUS)
    lines = github_of(check(Path("naming/duplicate_same_scope")))
    assert lines[0] == (
        "::error file=naming/duplicate_same_scope/dup.launch.xml,line=4,col=3,endLine=4,"
        "endColumn=58,title=LV101 duplicate-node-name::node name /talker is already used by "
        "the node at dup.launch.xml:3"
    )
    traced = github_of(check(Path("lifecycle/activate_at_start")))
    python = next(line for line in traced if "activate.launch.py" in line)
    assert ",line=18,endLine=20,title=" in python and "col=" not in python


def test_github_escaping(tmp_path: Path) -> None:
    folder = tmp_path / "a,b:c"
    folder.mkdir()
    write(folder / "x.launch.xml",
          '<launch>\n  <node pkg="demo_nodes_cpp" exec="talker" name="t" if="true"/>\n'
          "</launch>\n")
    report = check(folder)
    finding = report.findings[0]
    assert finding.severity is Severity.INFO
    odd = Finding(finding.code, finding.slug, Severity.WARNING, "50% done\r\nnext: a,b",
                  finding.span, witness={"x": "1"})
    report.findings.append(odd)
    notice, warning = github_of(report)
    assert notice.startswith("::notice file=") and "a%2Cb%3Ac/x.launch.xml," in notice
    assert warning.endswith("::50%25 done%0D%0Anext: a,b (when: x:=1)")
    assert escape_property("a:b,c%\n") == "a%3Ab%2Cc%25%0A"
    assert escape_data("a:b,c%\r") == "a:b,c%25%0D"


# ---- text that has no UTF-8 form (issue 42) ----


def test_lone_surrogates_are_shown_and_other_characters_kept() -> None:
    from launchverify.render.encodable import escape_surrogates, json_text
    from launchverify.render.inert import inert

    name = "caf\u00e9 \U0001f600 dup\udcff\udcfe x\ud800"
    shown = "caf\u00e9 \U0001f600 dup\\xff\\xfe x\\ud800"
    assert escape_surrogates(name) == shown
    assert inert(name) == shown
    assert json.loads(json_text({name: [name]})) == {shown: [shown]}
    exact = "caf\u00e9 \U0001f600"  # a character beyond U+FFFF is written as a pair: kept
    assert json.loads(json_text({"name": exact})) == {"name": exact}


def test_a_uri_names_a_file_by_its_bytes() -> None:
    from launchverify.render.sarif import file_uri

    assert file_uri(Path("/ws/dup\udcff\udcfe.launch.xml")) == \
        "file:///ws/dup%FF%FE.launch.xml"
    assert file_uri(Path("/ws/x\ud800 y.launch.py")) == "file:///ws/x%5Cud800%20y.launch.py"
    assert file_uri(Path("/ws/a b")) == Path("/ws/a b").as_uri()


def test_fingerprints_hash_a_file_name_by_its_bytes() -> None:
    """Baselines written before stay valid: an undecodable byte is hashed as itself."""
    from launchverify.findings.fingerprint import _field_bytes

    assert _field_bytes("dup\udcff.launch.xml") == b"dup\xff.launch.xml"
    assert _field_bytes("x\ud800") == "x\ud800".encode("utf-8", "surrogatepass")
