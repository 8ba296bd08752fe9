"""Configuration files, baselines, exit codes and the rule documentation commands."""

from __future__ import annotations

import json
import os
import re
import shutil
from pathlib import Path

import pytest

from launchverify.cli import main
from launchverify.config import find_config, load_config, matches

CORPUS = Path(__file__).resolve().parent.parent / "corpus"
DUPLICATE = CORPUS / "naming" / "duplicate_same_scope"

ROBOT = """\
<launch>
  <arg name="unused" default="x"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>
</launch>
"""


@pytest.fixture(autouse=True)
def _no_ros(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)


def codes(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, list[str]]:
    status = main(["check", *argv, "--format", "json"])
    findings = json.loads(capsys.readouterr().out)["findings"]
    return status, sorted(f"{Path(f['file']).name}:{f['line']}:{f['code']}:{f['severity']}"
                          for f in findings)


@pytest.fixture
def project(tmp_path: Path) -> Path:
    (tmp_path / "launch").mkdir()
    (tmp_path / "launch" / "robot.launch.xml").write_text(ROBOT)
    (tmp_path / "test").mkdir()
    (tmp_path / "test" / "dup.launch.xml").write_text(ROBOT)
    return tmp_path


def test_without_configuration_everything_is_reported(
        project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    status, found = codes(capsys, str(project))
    assert status == 1
    assert found == ["dup.launch.xml:2:LV202:warning", "dup.launch.xml:4:LV101:error",
                     "robot.launch.xml:2:LV202:warning", "robot.launch.xml:4:LV101:error"]


def test_pyproject_table_is_found_walking_up(project: Path,
                                             capsys: pytest.CaptureFixture[str]) -> None:
    (project / "pyproject.toml").write_text("""
[project]
name = "robot"

[tool.launchverify]
ignore = ["unused-argument"]
per-file-ignores = {"test/**" = ["LV101"]}
severity = {LV101 = "warning"}
""")
    status, found = codes(capsys, str(project / "launch"))
    assert found == ["robot.launch.xml:4:LV101:warning"]
    assert status == 0  # a warning does not fail by default
    _, found = codes(capsys, str(project))
    assert found == ["robot.launch.xml:4:LV101:warning"]


def test_launchverify_toml_wins_over_pyproject_and_sets_fail_on(
        project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (project / "pyproject.toml").write_text("[tool.launchverify]\nselect = ['LV101']\n")
    (project / "launchverify.toml").write_text(
        "select = ['LV2']\nfail-on = 'warning'\nexclude = ['test/']\n")
    status, found = codes(capsys, str(project))
    assert found == ["robot.launch.xml:2:LV202:warning"]
    assert status == 1
    assert main(["check", str(project), "--isolated", "-q", "--exit-zero"]) == 0
    capsys.readouterr()


def test_command_line_overrides_the_file(project: Path,
                                         capsys: pytest.CaptureFixture[str]) -> None:
    (project / "launchverify.toml").write_text("select = ['LV2']\n")
    _, found = codes(capsys, str(project / "launch"), "--select", "LV101")
    assert found == ["robot.launch.xml:4:LV101:error"]
    status, _ = codes(capsys, str(project / "launch"), "--select", "LV101",
                      "--fail-on", "info", "--ignore", "LV101")
    assert status == 0


def test_configured_arguments_are_pinned(tmp_path: Path,
                                         capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "sim.launch.xml").write_text("""<launch>
  <arg name="use_sim" default="false"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker" if="$(var use_sim)"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>
</launch>
""")
    (tmp_path / "launchverify.toml").write_text("arguments = {use_sim = true}\n")
    main(["graph", str(tmp_path / "sim.launch.xml")])
    capsys.readouterr()
    _, found = codes(capsys, str(tmp_path))
    assert found == ["sim.launch.xml:4:LV101:error"]
    assert codes(capsys, str(tmp_path), "--isolated")[1] == ["sim.launch.xml:4:LV101:error"]


@pytest.mark.parametrize(("text", "message"), [
    ("select = [", "launchverify.toml:1: invalid TOML: Invalid value"),
    ("# ours\n\nselcet = ['LV1']", "launchverify.toml:3: unknown key 'selcet' "
     "(did you mean 'select'?)"),
    ("jobs = 2\nfoo = 1", "launchverify.toml:2: unknown key 'foo' (known: arguments, "
     "distro, "),
    ("jobs = 2\nfoo = 1\nbar = 2", "launchverify.toml: 2 problems:\n  "),
    ("jobs = 2\nfoo = 1\nbar = 2", "launchverify.toml:3: unknown key 'bar'\n  (known keys: "),
    ("jobs = 2\nseverity = {LV101 = 'fatal'}", "launchverify.toml:2: severity of LV101 "
     "must be one of"),
    ("[severity]\nLV404 = 'error'\nLV101 = 'fatal'", "launchverify.toml:3: severity of "
     "LV101"),
    ("\nignore = 3", "launchverify.toml:2: ignore must be a list of strings"),
    ("arguments = {a = 'x', b = [1]}", "launchverify.toml:1: arguments.b must be a string"),
    ("distro = 'humbel'", "launchverify.toml:1: distro must be one of humble, iron, "),
    ("distro = 'humbel'", "(did you mean 'humble'?)"),
    ("fail-on = 'never'", "launchverify.toml:1: fail-on must be one of error, warning, info"),
    ("select = [\n  'LV1',\n  'XY9',\n]", "launchverify.toml:3: select: no rule is called "
     "'XY9' (`launchverify rules` lists every rule)"),
    ("per-file-ignores = {'a/**' = ['duplicate-node-nam']}", "launchverify.toml:1: "
     "per-file-ignores: no rule is called 'duplicate-node-nam' (did you mean "
     "'duplicate-node-name'?)"),
    ("severity = {LV10l = 'info'}", "launchverify.toml:1: severity: no rule is called "
     "'LV10l' (did you mean 'LV101'"),
])
def test_bad_configuration_is_a_clear_error(project: Path, text: str, message: str,
                                            capsys: pytest.CaptureFixture[str]) -> None:
    """Every configuration error names the file and, where TOML has one, the line."""
    (project / "launchverify.toml").write_text(text)
    assert main(["check", str(project)]) == 2
    err = capsys.readouterr().err
    assert message in err and f"{project.resolve()}{os.sep}launchverify.toml:" in err
    assert "Traceback" not in err


def test_every_wrong_key_of_a_configuration_is_named_at_once(
        project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """A user fixing a file meets all its mistakes in one run, each with a close key."""
    (project / "launchverify.toml").write_text(
        'selct = ["LV1"]\nignore = ["LV404"]\nper-file-ignore = {"test/**" = ["LV101"]}\n'
        'fail_on = "warning"\nfrobnicate = 3\njobs = "four"\n'
        'severity = {LV9999 = "error", LV101 = "fatal"}\ndistro = "jazy"\n')
    assert main(["check", str(project)]) == 2
    err = capsys.readouterr().err
    file = f"{project.resolve()}{os.sep}launchverify.toml"
    assert err.splitlines() == [
        f"launchverify: error: {file}: 8 problems:",
        f"  {file}:1: unknown key 'selct' (did you mean 'select'?)",
        f"  {file}:3: unknown key 'per-file-ignore' (did you mean 'per-file-ignores'?)",
        f"  {file}:4: unknown key 'fail_on' (did you mean 'fail-on'?)",
        f"  {file}:5: unknown key 'frobnicate'",
        f"  {file}:6: jobs must be a positive whole number",
        f"  {file}:7: severity of LV101 must be one of error, warning, info, not 'fatal'",
        f"  {file}:7: severity: no rule is called 'LV9999' (`launchverify rules` lists "
        "every rule)",
        f"  {file}:8: distro must be one of humble, iron, jazzy, kilted, rolling (did you "
        "mean 'jazzy'?)",
        "  (known keys: arguments, distro, environment, exclude, external-names, fail-on, "
        "ignore, jobs, max-file-size, package-paths, per-file-ignores, select, severity, "
        "single-writer-topics, time-limit, workspace)"]


def test_a_line_break_in_a_wrong_key_forges_no_line(
        project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (project / "launchverify.toml").write_text('"a\\nb" = 1\nfoo = 2\n')
    assert main(["check", str(project)]) == 2
    err = capsys.readouterr().err
    assert "unknown key 'a\\nb'" in err and len(err.splitlines()) == 4, err


@pytest.mark.parametrize(("text", "message"), [
    ('[project]\nname = "x"\nselct = 1\n\n[tool.launchverify]\nignore = ["LV2"]\n'
     "selct = []\n", "pyproject.toml:7: unknown key 'selct' (did you mean 'select'?)"),
    ('[project]\nselect = 1\n[tool.launchverify]\nignore = ["LV1"]\nselect = ["LV9"]\n',
     "pyproject.toml:5: select: no rule is called 'LV9'"),
    ('[tool.launchverify.severity]\nLV202 = "loud"\n', "pyproject.toml:2: severity of "
     "LV202 must be one of"),
    ("[tool]\nlaunchverify = 3\n", "pyproject.toml:2: [tool.launchverify] must be a table"),
])
def test_pyproject_errors_name_the_line_in_the_table(
        project: Path, text: str, message: str, capsys: pytest.CaptureFixture[str]) -> None:
    (project / "pyproject.toml").write_text(text)
    assert main(["check", str(project)]) == 2
    assert f"{project.resolve()}{os.sep}{message}" in capsys.readouterr().err


def test_unknown_rule_in_configuration_is_a_clear_error(
        project: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (project / "launchverify.toml").write_text("select = ['LV999']\n")
    assert main(["check", str(project)]) == 2
    assert "launchverify.toml:1: select: no rule is called 'LV999'" in capsys.readouterr().err


def test_find_config_ignores_pyproject_without_the_table(tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_text("[project]\nname = 'x'\n")
    (tmp_path / "sub").mkdir()
    assert find_config(tmp_path / "sub") is None
    (tmp_path / "launchverify.toml").write_text("")
    found = find_config(tmp_path / "sub")
    assert found == (tmp_path / "launchverify.toml").resolve()
    assert load_config(found).select is None


def test_a_malformed_launchverify_table_in_pyproject_is_an_error(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    shutil.copy(DUPLICATE / "dup.launch.xml", tmp_path / "dup.launch.xml")
    (tmp_path / "pyproject.toml").write_text(
        '[project]\nname = "x"\n\n[tool.launchverify]\nselect = ["LV1"\nignore = []\n')
    assert main(["check", str(tmp_path)]) == 2
    err = capsys.readouterr().err
    assert "pyproject.toml:6:1: invalid TOML" in err
    # someone else's broken pyproject is not ours: the check runs with the defaults
    (tmp_path / "pyproject.toml").write_text('[project\nname = "x"\n')
    assert main(["check", str(tmp_path)]) == 1


@pytest.mark.parametrize(("path", "pattern", "expected"), [
    ("test/a/dup.launch.xml", "test/**", True),
    ("test/a/dup.launch.xml", "test/", True),
    ("src/test/dup.launch.xml", "test/**", False),
    ("src/dup.launch.xml", "dup.launch.xml", True),
    ("src/dup.launch.xml", "*.launch.xml", True),
    ("src/dup.launch.py", "src/*.xml", False),
])
def test_patterns(path: str, pattern: str, expected: bool) -> None:
    assert matches(path, pattern) is expected


def test_baseline_survives_moved_lines_and_catches_new_findings(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    shutil.copytree(DUPLICATE, tmp_path / "tree")
    launch = tmp_path / "tree" / "dup.launch.xml"
    baseline = tmp_path / "baseline.json"
    assert main(["check", str(tmp_path / "tree"), "--write-baseline", str(baseline),
                 "-q"]) == 1
    capsys.readouterr()
    launch.write_text(launch.read_text().replace("<launch>", "<launch>\n\n  <!-- moved -->"))
    status, found = codes(capsys, str(tmp_path / "tree"), "--baseline", str(baseline))
    assert (status, found) == (0, [])
    launch.write_text(launch.read_text().replace(
        "</launch>", '  <node pkg="demo_nodes_cpp" exec="listener" name="talker"/>\n</launch>'))
    status, found = codes(capsys, str(tmp_path / "tree"), "--baseline", str(baseline))
    assert status == 1 and len(found) == 1


def test_the_summary_says_how_many_findings_the_baseline_hides(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """A clean run with a baseline says what it rests on: text, concise and JSON."""
    shutil.copytree(DUPLICATE, tmp_path / "tree")
    tree, baseline = str(tmp_path / "tree"), str(tmp_path / "baseline.json")
    assert main(["check", tree, "--write-baseline", baseline, "-q", "--no-cache"]) == 1
    capsys.readouterr()
    assert main(["check", tree, "--baseline", baseline, "--no-cache"]) == 0
    summary = next(line for line in capsys.readouterr().out.splitlines()
                   if line.startswith("No findings"))
    # (then what was not followed, on a line of its own: the demo packages are in no
    # underlay here)
    assert re.fullmatch(r"No findings in 1 file \(\d+\.\d\ds\); 2 hidden by the baseline\.",
                        summary), summary
    launch = tmp_path / "tree" / "dup.launch.xml"
    launch.write_text(launch.read_text().replace(
        "</launch>", '  <node pkg="demo_nodes_cpp" exec="listener" name="talker"/>\n</launch>'))
    assert main(["check", tree, "--baseline", baseline, "--no-cache", "--format",
                 "concise"]) == 1
    summary = next(line for line in capsys.readouterr().out.splitlines()
                   if line.startswith("Found"))
    assert summary.startswith("Found 1 finding (1 error) in 1 file (")
    assert re.search(r"s\); 2 hidden by the baseline[;.]", summary), summary
    main(["check", tree, "--baseline", baseline, "--no-cache", "--format", "json"])
    assert json.loads(capsys.readouterr().out)["summary"]["baselined"] == 2
    main(["check", tree, "--no-cache"])
    assert "baseline" not in capsys.readouterr().out  # none given: nothing said


def test_baseline_holds_from_another_working_directory(
        tmp_path: Path, capsys: pytest.CaptureFixture[str],
        monkeypatch: pytest.MonkeyPatch) -> None:
    """Messages show paths relative to the working directory; fingerprints do not."""
    tree = tmp_path / "ws" / "src" / "robot"
    tree.mkdir(parents=True)
    (tree / "robot.launch.xml").write_text(
        '<launch>\n  <node pkg="demo_nodes_cpp" exec="talker" name="talker">\n'
        '    <param from="$(dirname)/config/missing.yaml"/>\n  </node>\n</launch>\n')
    baseline = tmp_path / "ws" / "baseline.json"
    monkeypatch.chdir(tmp_path / "ws")
    assert main(["check", "src", "--write-baseline", str(baseline), "-q"]) == 1
    capsys.readouterr()
    monkeypatch.chdir(tree)  # as the ament_cmake recipe runs it, from the package
    status, found = codes(capsys, ".", "--baseline", str(baseline))
    assert (status, found) == (0, [])


def test_a_legacy_baseline_still_matches(tmp_path: Path,
                                         capsys: pytest.CaptureFixture[str]) -> None:
    from launchverify.engine import CheckOptions, run_check
    from launchverify.findings.fingerprint import fingerprints

    shutil.copytree(DUPLICATE, tmp_path / "tree")
    findings = run_check(CheckOptions(paths=[tmp_path / "tree"])).findings
    baseline = tmp_path / "baseline.json"
    baseline.write_text(json.dumps({"findings": [
        {"fingerprint": f} for f in fingerprints(findings, tmp_path, legacy=True)]}))
    assert codes(capsys, str(tmp_path / "tree"), "--baseline", str(baseline)) == (0, [])


def test_a_broken_baseline_is_a_clear_error(tmp_path: Path,
                                            capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "b.json").write_text("[]")
    assert main(["check", str(DUPLICATE), "--baseline", str(tmp_path / "b.json")]) == 2
    assert "is not a launchverify baseline" in capsys.readouterr().err


def test_statistics_quiet_and_output(tmp_path: Path,
                                     capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check", str(CORPUS / "naming"), "--statistics"]) == 1
    out = capsys.readouterr().out
    rows = [line.split() for line in out.splitlines() if line.split()[1:2] == ["LV101"]]
    assert rows and rows[0][2] == "duplicate-node-name" and int(rows[0][0]) > 1
    counts = [int(line.split()[0]) for line in out.splitlines() if line.split()[1:2]
              and line.split()[1].startswith("LV")]
    assert counts == sorted(counts, reverse=True)  # most frequent first
    assert any(line.startswith("solver: ") and "z3 queries" in line
               for line in out.splitlines())
    assert main(["check", str(DUPLICATE), "-q"]) == 1
    assert "Found" not in capsys.readouterr().out
    target = tmp_path / "out.json"
    assert main(["check", str(DUPLICATE), "--format", "json", "-o", str(target)]) == 1
    assert capsys.readouterr().out == ""
    assert json.loads(target.read_text())["findings"]


def test_explain_prints_why_and_fix(capsys: pytest.CaptureFixture[str]) -> None:
    main(["check", str(DUPLICATE), "--explain"])
    out = capsys.readouterr().out
    assert "    why: " in out and "    fix: " in out
    assert '3 | <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>' in out


def test_explain_says_what_was_not_judged(capsys: pytest.CaptureFixture[str]) -> None:
    setup = CORPUS / "python" / "opaque_function_errors" / "setup.launch.py"
    main(["check", str(setup), "--explain"])
    out = capsys.readouterr().out
    assert "Not judged where the evaluation is incomplete" in out
    assert "setup.launch.py:15: an OpaqueFunction stopped at configuration 'robot'" in out
    main(["check", str(DUPLICATE), "--explain"])
    assert "Not judged" not in capsys.readouterr().out
    main(["check", str(setup), "--format", "json"])  # the same list for machines
    listed = json.loads(capsys.readouterr().out)["not_judged"]
    assert {"file": str(setup), "line": 15,
            "reason": "an OpaqueFunction stopped at configuration 'robot', which nothing "
                      "sets here"} in listed


def test_rules_and_explain_commands(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["rules"]) == 0
    listing = capsys.readouterr().out.splitlines()
    assert any(line.startswith("LV505  lifecycle-manager-unknown-node") for line in listing)
    assert main(["rules", "--format", "json"]) == 0
    rules = json.loads(capsys.readouterr().out)
    assert {"code": "LV004", "slug": "unused-suppression", "severity": "warning",
            "summary": "A `launchverify: ignore` comment that silences nothing."} in rules
    assert main(["explain", "duplicate-node-name"]) == 0
    text = capsys.readouterr().out
    assert text.startswith("# LV101 duplicate-node-name (error)")
    assert "## Fix" in text
    assert main(["explain", "LV999"]) == 2
    assert "no rule is called" in capsys.readouterr().err


def test_docs_rules_md_is_up_to_date(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["rules", "--format", "markdown"]) == 0
    expected = (CORPUS.parent / "docs" / "rules.md").read_text(encoding="utf-8")
    assert capsys.readouterr().out == expected, \
        "docs/rules.md is stale: launchverify rules --format markdown > docs/rules.md"


def test_each_file_takes_its_nearest_configuration(tmp_path: Path,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    """As ruff: a package's own launchverify.toml holds for its files from the root."""
    root = tmp_path / "ws"
    for package in ("robot", "legacy"):
        shutil.copytree(DUPLICATE, root / "src" / package / "launch")
    (root / "launchverify.toml").write_text('fail-on = "error"\n')
    (root / "src" / "legacy" / "launchverify.toml").write_text(
        '[severity]\n"LV101" = "warning"\n[per-file-ignores]\n"other.launch.xml" = ["LV1"]\n')

    def found(*extra: str) -> list[str]:
        main(["check", str(root), "--workspace", str(root), "--format", "json", *extra])
        return sorted({f"{Path(f['file']).parts[-3]}:{f['code']}:{f['severity']}"
                       for f in json.loads(capsys.readouterr().out)["findings"]})

    assert found() == ["legacy:LV101:warning", "robot:LV101:error"]
    (root / "src" / "legacy" / "launchverify.toml").write_text('ignore = ["LV101"]\n')
    assert found() == ["robot:LV101:error"]
    assert found("--select", "LV101") == ["robot:LV101:error"]  # its ignore still holds
    # --isolated, or --config FILE: one configuration for every file
    assert found("--isolated") == ["legacy:LV101:error", "robot:LV101:error"]
    assert found("--config", str(root / "launchverify.toml")) == [
        "legacy:LV101:error", "robot:LV101:error"]


def test_an_argument_says_where_it_was_given(tmp_path: Path,
                                              capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "robot.launch.xml").write_text(
        '<launch>\n  <arg name="use_sim_time" default="false"/>\n'
        '  <node pkg="demo_nodes_cpp" exec="talker" name="talker">\n'
        '    <param name="use_sim_time" value="$(var use_sim_time)"/>\n  </node>\n</launch>\n')
    (tmp_path / "launchverify.toml").write_text('arguments = {use_sim_tme = "true"}\n')
    target = str(tmp_path / "robot.launch.xml")
    assert main(["check", target, "--format", "json", "--no-cache", "robot:=r2"]) == 1
    findings = json.loads(capsys.readouterr().out)["findings"]
    messages = {f["message"]: f["severity"] for f in findings if f["code"] == "LV204"}
    assert messages == {
        "argument 'robot:=r2' is not declared by robot.launch.xml (given on the command line)":
            "warning",
        "argument 'use_sim_tme:=true' is not declared by robot.launch.xml (given in "
        "launchverify.toml) (did you mean 'use_sim_time'?)": "error",
    }


# ---- a configuration file is untrusted input (issue 42) ----


def test_dots_and_brackets_in_strings_and_comments_are_no_depth(tmp_path: Path) -> None:
    """Only what nests counts towards the depth bound: not a string's or a comment's dots."""
    dots = "." * 300
    path = tmp_path / "launchverify.toml"
    path.write_text(f"# {dots} [[[[ {{{{\n"
                    f"arguments = {{a = '{dots}', b = \"{dots}[\", c = '''\n{dots}\n'''}}\n"
                    f"environment = {{D = \"\"\"{dots}\n{dots}\"\"\"}}\n"
                    + "".join(f"per-file-ignores.'x{n}{dots}y' = ['LV101']\n"
                              for n in range(200)))
    config = load_config(path)
    assert config.arguments["a"] == dots and config.arguments["c"] == dots + "\n"
    assert len(config.per_file_ignores) == 200


def test_tomllib_recursion_is_an_error_past_the_depth_bound(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The net under the bound: tomllib's RecursionError is a configuration error."""
    from launchverify import config

    monkeypatch.setattr(config, "MAX_DEPTH", 10 ** 9)
    path = tmp_path / "launchverify.toml"
    path.write_text("jobs = " + "[" * 100_000 + "]" * 100_000 + "\n")
    with pytest.raises(config.ConfigError, match="nested too deeply"):
        load_config(path)


def test_a_configuration_of_the_user_is_read_outside_the_confined_folders(
        tmp_path: Path) -> None:
    """A check confines reads to its tree; a configuration above it is still the user's."""
    from launchverify.workspace import reading

    (tmp_path / "ws").mkdir()
    (tmp_path / "launchverify.toml").write_text("jobs = 3\n")
    reading.confine([tmp_path / "ws"])
    assert load_config(tmp_path / "launchverify.toml").jobs == 3


def test_a_configuration_that_is_not_utf8_names_its_line(tmp_path: Path) -> None:
    from launchverify.config import ConfigError

    path = tmp_path / "launchverify.toml"
    path.write_bytes(b"select = ['LV1']\n# caf\xe9\n")
    with pytest.raises(ConfigError, match=r"launchverify.toml:2: invalid TOML: not UTF-8"):
        load_config(path)
