"""Conditions before arguments (issue 43): a field fails only where its action runs.

Launch evaluates an include's arguments and a node's fields only once the action's
condition held. A failure there is an error with the arguments that make the condition
true (the witness), nothing when no values do, and an error without witness when the
condition holds with the arguments as given. The corpus markers check where findings
are; these tests check the witnesses they name.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from launchverify.engine import CheckOptions, run_check
from launchverify.rule import Finding

CORPUS = Path(__file__).resolve().parent.parent / "corpus"
PYTHON_TREE = CORPUS / "python" / "conditional_include_arguments"
XML_TREE = CORPUS / "conditions" / "conditional_include_arguments"


def findings(tree: Path, arguments: dict[str, str] | None = None,
             root: Path | None = None) -> list[Finding]:
    """Return the findings of a check of ``tree`` (or of one root file in it)."""
    options = CheckOptions(paths=[root or tree], workspace=tree, arguments=arguments or {})
    return run_check(options).findings


def witnesses(found: list[Finding], code: str, file: str) -> dict[int, dict[str, str] | None]:
    """Return the witness of each finding of ``code`` in ``file``, by line."""
    return {f.span.line: (dict(f.witness) if f.witness else None)
            for f in found if f.code == code and f.span.file.name == file}


@pytest.fixture(autouse=True)
def _no_ament(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)


def test_python_failures_name_the_arguments_that_reach_them() -> None:
    found = findings(PYTHON_TREE)
    assert witnesses(found, "LV002", "bringup.launch.py") == {
        35: {"use_camera": "true"},  # an int as an include argument's value
        40: {"sensor": "rs"},  # '1 / false': a free-text argument takes the compared value
        48: {"use_camera": "true"},  # an int as a node's name
    }
    assert witnesses(found, "LV201", "bringup.launch.py") == {59: {"sensor": "lidar"}}
    # what fails whatever the condition stays an error, with no witness
    assert witnesses(found, "LV002", "always.launch.py") == {13: None}


def test_python_file_still_loads_when_an_argument_is_rejected() -> None:
    found = findings(PYTHON_TREE)
    assert not [f for f in found if "the launch file raises" in f.message]


def test_arguments_as_given_that_take_the_path_need_no_witness() -> None:
    root = PYTHON_TREE / "sensors" / "launch" / "bringup.launch.py"
    found = findings(PYTHON_TREE, {"use_camera": "true"}, root)
    lines = witnesses(found, "LV002", "bringup.launch.py")
    assert lines[35] is None and lines[48] is None


def test_xml_failures_name_the_arguments_that_reach_them() -> None:
    found = findings(XML_TREE)
    assert witnesses(found, "LV002", "bringup.launch.xml") == {
        15: {"use_camera": "true"},  # '60 / true'
        19: {"sensor": "oakd"},  # fails whatever the values, once included
        23: {"use_camera": "true"},  # a group's node
        26: None,  # a <let> that always runs
    }


def test_a_condition_no_value_makes_true_leaves_its_failures_unjudged(tmp_path: Path) -> None:
    (tmp_path / "never.launch.xml").write_text(
        '<launch>\n'
        '  <arg name="mode" default="a"><choice value="a"/><choice value="b"/></arg>\n'
        '  <group if="$(equals $(var mode) c)">\n'
        '    <let name="ratio" value="$(eval \'1 / 0\')"/>\n'
        '    <node pkg="demo_nodes_cpp" exec="talker" name="$(eval \'1 / $(var mode)\')"/>\n'
        '  </group>\n'
        '</launch>\n', encoding="utf-8")
    found = findings(tmp_path)
    assert not [f for f in found if f.code in ("LV002", "LV003")]
    assert [f.code for f in found] == ["LV205"]  # the condition itself is what is wrong


def test_an_eval_over_arguments_off_the_default_path_is_tried_where_it_runs(
        tmp_path: Path) -> None:
    (tmp_path / "rate.launch.xml").write_text(
        '<launch>\n'
        '  <arg name="divisor" default="0"/>\n'
        '  <arg name="scale" default="0"/>\n'
        '  <let name="safe" value="$(eval \'60 / $(var divisor)\')"\n'
        '       if="$(eval \'$(var divisor) != 0\')"/>\n'
        '  <let name="unsafe" value="$(eval \'60 / $(var scale)\')"\n'
        '       if="$(eval \'$(var divisor) != 0\')"/>\n'
        '</launch>\n', encoding="utf-8")
    found = [f for f in findings(tmp_path) if f.code == "LV002"]
    assert [(f.span.line, "ZeroDivisionError" in f.message) for f in found] == [(6, True)]
    assert found[0].witness and found[0].witness.get("divisor") not in (None, "0")


def test_no_failure_rests_on_a_value_guessed_to_break_the_expression(tmp_path: Path) -> None:
    # a free-text argument or an environment variable quoted into an $(eval): a value
    # such as ' breaks it, but that is no fact about the launch (autoware, husarion)
    (tmp_path / "quoted.launch.xml").write_text(
        '<launch>\n'
        '  <arg name="use_x" default="false"/>\n'
        '  <arg name="prefix" default=""/>\n'
        '  <let name="ns" value="$(eval &quot;\'$(var prefix)\' + \'/\'&quot;)"'
        ' if="$(var use_x)"/>\n'
        '  <let name="file" value="$(eval &quot;\'cfg_$(env ROBOT_MODEL panther).yaml\'&quot;)"'
        ' if="$(var use_x)"/>\n'
        '</launch>\n', encoding="utf-8")
    assert [f for f in findings(tmp_path) if f.code == "LV002"] == []


def test_a_failure_under_a_condition_on_the_machine_is_not_an_error(tmp_path: Path) -> None:
    # whether the robot sets USE_X is unknown: what fails only if it does is no error
    (tmp_path / "machine.launch.xml").write_text(
        '<launch>\n'
        '  <group if="$(env USE_X)">\n'
        '    <let name="ratio" value="$(eval \'1 / 0\')"/>\n'
        '  </group>\n'
        '</launch>\n', encoding="utf-8")
    found = findings(tmp_path)
    assert not [f for f in found if f.code == "LV002"]
    assert [f.span.line for f in found if f.code == "LV003"] == [3]
