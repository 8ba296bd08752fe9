"""The command line as a newcomer meets it: help everywhere, short errors, suggestions."""

from __future__ import annotations

import argparse
import json
from pathlib import Path

import pytest

from launchverify.cli import build_parser, main
from launchverify.render.completion import commands_of

CORPUS = Path(__file__).resolve().parent.parent / "corpus"
DUPLICATE = CORPUS / "naming" / "duplicate_same_scope" / "dup.launch.xml"
ROBOT = """<launch>
  <arg name="use_sim" default="false"/>
  <arg name="unused" default="x"/>
  <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>
  <node pkg="demo_nodes_cpp" exec="listener" name="talker" if="$(var use_sim)"/>
</launch>
"""

@pytest.fixture(autouse=True)
def _no_ros(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)


def _subcommands() -> list[tuple[str, argparse.ArgumentParser, str | None]]:
    """Return every subcommand: name, parser and the help its listing shows."""
    found = []
    for action in build_parser()._actions:
        if isinstance(action, argparse._SubParsersAction):
            helps = {choice.dest: choice.help for choice in action._choices_actions}
            found += [(name, sub, helps.get(name)) for name, sub in action.choices.items()]
    return found


def test_every_subcommand_and_option_has_help() -> None:
    """What ``--help`` shows is complete: a new option without help fails here."""
    missing = []
    for name, sub, listed in _subcommands():
        if not listed:
            missing.append(f"{name}: no help in the command list")
        if not sub.description:
            missing.append(f"{name}: no description")
        for action in sub._actions:
            label = action.option_strings[-1] if action.option_strings else action.dest
            if not action.help or action.help == argparse.SUPPRESS:
                missing.append(f"{name} {label}: no help")
    assert missing == []


def usage_error(capsys: pytest.CaptureFixture[str], *argv: str) -> list[str]:
    """Run a command line that argparse refuses; return the lines on stderr."""
    with pytest.raises(SystemExit) as stop:
        main(list(argv))
    assert stop.value.code == 2
    out, err = capsys.readouterr()
    assert out == ""
    return err.splitlines()


@pytest.mark.parametrize(("argv", "lines"), [
    (["check", "corpus/naming", "--format", "xx"],
     ["launchverify check: error: argument --format/--output-format: invalid choice: 'xx' "
      "(choose from text, concise, json, sarif, junit, github)",
      "see 'launchverify check --help'"]),
    (["check", "corpus/naming", "--output-format", "jsn"],
     ["launchverify check: error: argument --format/--output-format: invalid choice: 'jsn' "
      "(did you mean 'json'?)", "see 'launchverify check --help'"]),
    (["chek", "corpus/naming"],
     ["launchverify: error: argument COMMAND: invalid choice: 'chek' (did you mean "
      "'check'?)", "see 'launchverify --help'"]),
    (["check", "corpus/naming", "--selct", "LV1"],
     ["launchverify check: error: unrecognized arguments: --selct (did you mean "
      "'--select'?)", "see 'launchverify check --help'"]),
    (["report", "--fail-on=warnnig", "corpus"],
     ["launchverify report: error: argument --fail-on: invalid choice: 'warnnig' (did you "
      "mean 'warning'?)", "see 'launchverify report --help'"]),
    (["graph", "--colour", "never", str(DUPLICATE)],
     ["launchverify graph: error: unrecognized arguments: --colour", "see 'launchverify "
      "graph --help'"]),
    (["check", "-j", "0"],
     ["launchverify check: error: argument -j/--jobs: must be at least 1",
      "see 'launchverify check --help'"]),
    (["graph"], ["launchverify graph: error: the following arguments are required: "
                 "FILE|name:=value", "see 'launchverify graph --help'"]),
])
def test_usage_errors_are_short_and_suggest(argv: list[str], lines: list[str],
                                            capsys: pytest.CaptureFixture[str]) -> None:
    """One line saying what is wrong (and what was meant), one saying where help is."""
    assert usage_error(capsys, *argv) == lines


@pytest.mark.parametrize(("argv", "message"), [
    (["explain", "LV9999"], "no rule is called 'LV9999' (`launchverify rules` lists every "
     "rule)"),
    (["explain", "duplicate-node-nam"], "no rule is called 'duplicate-node-nam' (did you "
     "mean 'duplicate-node-name'?)"),
    (["explain", "lv1011"], "(did you mean 'LV101'?)"),
    (["check", str(DUPLICATE), "--select", "LV101,duplicate-node-nam"],
     "--select: no rule is called 'duplicate-node-nam' (did you mean "
     "'duplicate-node-name'?)"),
    (["report", str(DUPLICATE), "--ignore", "LV9"], "--ignore: no rule is called 'LV9'"),
])
def test_rules_that_do_not_exist_get_the_closest(argv: list[str], message: str,
                                                 capsys: pytest.CaptureFixture[str]) -> None:
    assert main(argv) == 2
    assert message in capsys.readouterr().err


@pytest.fixture
def robot(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    (tmp_path / "robot.launch.xml").write_text(ROBOT)
    monkeypatch.chdir(tmp_path)
    return tmp_path


def findings(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, list[str]]:
    status = main(["check", *argv, "--format", "json", "--no-cache"])
    document = json.loads(capsys.readouterr().out)
    return status, [f"{f['file']}:{f['code']}" for f in document["findings"]]


def test_check_without_a_path_checks_the_working_folder(
        robot: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert findings(capsys) == (1, ["robot.launch.xml:LV202", "robot.launch.xml:LV101"])
    assert findings(capsys, "use_sim:=false") == (0, ["robot.launch.xml:LV202"])
    assert main(["report", "--exit-zero"]) == 0
    assert (robot / "launchverify-report.html").is_file()
    capsys.readouterr()


@pytest.mark.parametrize("argv", [["graph", "use_sim:=true"], ["run", "use_sim:=true"],
                                  ["check", "--affected"]])
def test_commands_of_one_file_still_need_it(argv: list[str], robot: Path,
                                            capsys: pytest.CaptureFixture[str]) -> None:
    assert main(argv) == 2
    assert "launchverify: error: " in capsys.readouterr().err


@pytest.mark.parametrize(("argv", "config", "status"), [
    ([], "", 1),  # an error fails the report as it fails check
    (["--exit-zero"], "", 0),
    (["--ignore", "LV101"], "", 0),  # a warning is left: not a failure by default
    (["--ignore", "LV101", "--fail-on", "warning"], "", 1),
    (["--ignore", "LV101"], "fail-on = 'warning'\n", 1),  # the configuration's fail-on
    (["--ignore", "LV101", "--fail-on", "error"], "fail-on = 'warning'\n", 0),
])
def test_report_exits_as_check_does(argv: list[str], config: str, status: int, robot: Path,
                                    capsys: pytest.CaptureFixture[str]) -> None:
    (robot / "launchverify.toml").write_text(config)
    output = robot / "out.html"
    assert main(["report", ".", "-o", str(output), *argv]) == status
    assert output.is_file()  # written whatever the status
    assert findings(capsys, ".", *argv)[0] == status


def test_output_format_is_ruffs_spelling_of_format(capsys: pytest.CaptureFixture[str]
                                                   ) -> None:
    main(["check", str(DUPLICATE), "--format", "json", "--no-cache"])
    with_format = json.loads(capsys.readouterr().out)
    main(["check", str(DUPLICATE), "--output-format=json", "--no-cache"])
    with_output_format = json.loads(capsys.readouterr().out)
    for document in (with_format, with_output_format):
        del document["summary"]["seconds"]
    assert with_format == with_output_format
    check = next(c for c in commands_of(build_parser()) if c.name == "check")
    assert check.choices["--output-format"] == check.choices["--format"]  # completes too


@pytest.mark.parametrize(("argv", "status", "shown"), [
    (["explain", "--", "LV101"], 0, "# LV101 duplicate-node-name"),  # no paths: argparse's --
    (["check", "-q", str(DUPLICATE), "--", "--select=LV999"], 2,
     "no such file or folder"),  # after --, a path however it is spelt
    (["graph", "--"], 2, "graph takes exactly one launch file"),
])
def test_the_end_of_options(argv: list[str], status: int, shown: str,
                            capsys: pytest.CaptureFixture[str]) -> None:
    assert main(argv) == status
    captured = capsys.readouterr()
    assert shown in captured.out + captured.err
