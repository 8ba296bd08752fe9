"""The unknown's data model (``models/launch_api/data_model.py``), rule by rule.

Every operation Python offers has a rule; each rule's probe runs on an unknown value as
a launch file's code runs (its builtins, its compiled ``raise``/``except``/``match``, the
robot's machine), in the plain world and in the varied one, and must give what its rule
says. Then every probe, written into a launch file, is checked end to end: none of them
may give an error-level finding, except a ``raise``, which happens whatever the value is.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from launchverify.engine import CheckOptions, run_check
from launchverify.frontends.python import PythonFrontend, _Session
from launchverify.frontends.python.rewrite import compile_launch_file
from launchverify.models.launch_api.data_model import TABLE, Answer, Rule, operations, rules
from launchverify.models.launch_api.placeholders import WORLD, has_placeholder, varied_world
from launchverify.models.launch_api.unknown import Opaque, UnknownRaised
from launchverify.problems import ProblemSink
from launchverify.workspace.packages import PackageIndex

PRELUDE = """import json, math, os, pathlib, shlex, yaml
def drive(coroutine):
    try:
        coroutine.send(None)
    except StopIteration as end:
        return end.value
    raise RuntimeError('the coroutine waits')
"""
PROBED = [rule for rule in TABLE if rule.probe]


def test_every_operation_python_offers_has_a_rule() -> None:
    missing = operations() - set(rules())
    assert not missing, f"operations without a rule in data_model.TABLE: {sorted(missing)}"
    assert len(operations()) > 200  # the introspection found the data model, not a few


@dataclass
class Outcome:
    """What one probe did in one world."""

    result: Any = None
    error: BaseException | None = None
    answers: int = 0
    fixed: int = 0

    def shown(self) -> str:
        return repr(self.error) if self.error is not None else repr(self.result)


def _source(rule: Rule) -> str:
    probe = rule.probe
    statement = "\n" in probe or probe.startswith(("raise ", "assert ", "del ", "class "))
    return PRELUDE + (probe if statement or probe.startswith("r = ") else f"r = {probe}")


def _run(rule: Rule, folder: Path, *, varied: bool) -> Outcome:
    path = folder / "probe.launch.py"
    session = _Session(PythonFrontend(PackageIndex(), folder), path, ProblemSink())
    code = compile_launch_file(_source(rule), str(path))
    namespace: dict[str, Any] = {"__builtins__": session._builtins(), "__name__": "probe",
                                 "u": Opaque("vendor.value")}
    answers, fixed = WORLD.answers, WORLD.fixed
    outcome = Outcome()
    with session.environment():
        try:
            if varied:
                with varied_world():
                    exec(code, namespace)
            else:
                exec(code, namespace)
            outcome.result = namespace.get("r")
        except Exception as error:  # a probe may fail: its rule says whether it may
            outcome.error = error
    outcome.answers, outcome.fixed = WORLD.answers - answers, WORLD.fixed - fixed
    return outcome


def _unknown(value: Any) -> bool:
    return isinstance(value, Opaque) or (isinstance(value, str) and has_placeholder(value))


def _marked(value: Any) -> bool:
    if isinstance(value, bytes):
        value = value.decode(errors="replace")
    return has_placeholder(value if isinstance(value, str) else repr(value))


@pytest.mark.parametrize("rule", PROBED, ids=[rule.operation for rule in PROBED])
def test_each_rule_holds_for_an_unknown(rule: Rule, tmp_path: Path) -> None:
    plain = _run(rule, tmp_path, varied=False)
    varied = _run(rule, tmp_path, varied=True)
    why = (f"{rule.operation}: {rule.answer.name}, but plain {plain.shown()}, "
           f"varied {varied.shown()}")
    if rule.answer is Answer.UNKNOWN:
        assert plain.error is None and _unknown(plain.result), why
    elif rule.answer is Answer.ASSUMED:
        assert plain.answers > plain.fixed, why  # an answer the varied world varies...
        assert plain.shown() != varied.shown(), why  # ...and it does
    elif rule.answer is Answer.FIXED:
        assert plain.fixed > 0 and plain.error is None, why
    elif rule.answer is Answer.MARKED:
        assert (plain.error is None and _marked(plain.result)) or (
            plain.error is not None and has_placeholder(str(plain.error))), why
    elif rule.answer is Answer.SAME:
        assert plain.error is None and varied.error is None, why
    elif rule.answer is Answer.RAISES:
        raised = plain.error
        assert raised is not None and not isinstance(raised, TypeError), why
        assert isinstance(raised, UnknownRaised) or isinstance(
            raised.__cause__, UnknownRaised), why


def _launch_file(rule: Rule) -> str:
    body = _source(rule).removeprefix(PRELUDE)
    inner = "\n".join("    " + line for line in body.splitlines())
    return (f"{PRELUDE}import vendor\nfrom launch import LaunchDescription\n\n\n"
            "def generate_launch_description():\n    u = vendor.value\n"
            f"{inner}\n    return LaunchDescription([])\n")


def test_no_probe_gives_an_error_but_a_raise(tmp_path: Path) -> None:
    # End to end, through the worker: what the table's rules answer reaches no error
    # (a module nobody has is imported), except a raise, which is the launch file's.
    named: dict[str, Rule] = {}
    for number, rule in enumerate(PROBED):
        name = f"probe_{number:03d}.launch.py"
        (tmp_path / name).write_text(_launch_file(rule))
        named[name] = rule
    report = run_check(CheckOptions(paths=[tmp_path], workspace=tmp_path, time_limit=20.0))
    errors = {(f.span.file.name, f.code, f.message) for f in report.findings
              if f.severity.name.lower() == "error"}
    wrong = sorted((named[file].operation, code, message) for file, code, message in errors
                   if named[file].answer is not Answer.RAISES)
    assert not wrong
    raising = {named[file].operation for file, _, _ in errors}
    assert raising == {rule.operation for rule in PROBED if rule.answer is Answer.RAISES}
