"""Every modelled callable, each parameter fed unknowns: no error rests on an unknown.

The calls come from the models' own signatures (``tests/model_sweep.py``), so a model
is swept the day ``MODULES`` exports it. Each call with an unknown has a twin with a valid
value in its place: an error the call with the unknown gets that its twin does not get
rests on the unknown alone, and fails the sweep.
"""

from __future__ import annotations

import itertools
from collections import defaultdict
from pathlib import Path

import pytest
from model_sweep import Case, Modelled, calls, case_of, launch_file, modelled_callables, package

from launchverify.engine import CheckOptions, run_check
from launchverify.rule import Severity

RAISES = "the launch file raises"
_Calls = dict[str, tuple[Modelled, dict[int, str]]]  # file name -> callable, its calls


def _errors(launch: Path, files: _Calls) -> dict[tuple[str, int | None], set[str]]:
    """Return each call's error codes (by callable and case).

    A call that raises ends its file's evaluation (and the file gets no rule's findings):
    it is noted and the file's other calls are checked again in two files, until no call
    raises.
    """
    found: dict[tuple[str, int | None], set[str]] = defaultdict(set)
    counter = itertools.count()
    pending = dict(files)
    while pending:
        named = {}
        for (modelled, chosen) in pending.values():
            path = launch / f"{next(counter):05d}.launch.py"
            path.write_text(launch_file(modelled, chosen))
            named[path] = (modelled, chosen)
        report = run_check(CheckOptions(paths=sorted(named), workspace=launch.parent))
        raised: dict[Path, int] = {}
        errors: dict[Path, list[tuple[int | None, str]]] = defaultdict(list)
        for finding in report.findings:
            path = finding.span.file
            if finding.severity is Severity.ERROR and path in named:
                case = case_of(path.read_text(), finding.span.line)
                errors[path].append((case, finding.code))
                if case is not None and RAISES in finding.message:
                    raised[path] = case
        pending = {}
        for path, (modelled, chosen) in named.items():
            if path in raised:  # only the raise counts: nothing else was checked
                found[modelled.label, raised[path]].add("LV002")
                rest = [n for n in chosen if n != raised[path]]
                half = len(rest) // 2
                for part in (rest[:half], rest[half:]):
                    if part:
                        pending[f"{path.name}{len(pending)}"] = (
                            modelled, {n: chosen[n] for n in part})
            else:
                for case, code in errors[path]:
                    found[modelled.label, case].add(code)
            path.unlink()
    return found


@pytest.fixture(scope="module")
def sweep(tmp_path_factory: pytest.TempPathFactory) -> dict[str, list[str]]:
    """Return, by callable, the calls whose unknown gets an error its twin does not."""
    launch = package(tmp_path_factory.mktemp("sweep") / "sweep_pkg")
    cases: dict[str, list[Case]] = {}
    modelled = {}
    for each in modelled_callables():
        cases[each.label] = list(calls(each))
        modelled[each.label] = each
    unknown = _errors(launch, {label: (modelled[label], {
        n: case.unknown for n, case in enumerate(swept)}) for label, swept in cases.items()})
    suspects: dict[str, set[int]] = defaultdict(set)
    for label, number in unknown:
        if number is not None:
            suspects[label].add(number)
    twins = _errors(launch, {label: (modelled[label], {
        n: cases[label][n].twin for n in numbers}) for label, numbers in suspects.items()})
    out: dict[str, list[str]] = defaultdict(list)
    for (label, number), codes in twins.items():
        if number is None:  # a twin that is no valid launch file would hide the difference
            out[label].append(f"twins outside any call: {sorted(codes)}")
    for (label, number), codes in sorted(unknown.items(), key=str):
        if number is None:
            out[label].append(f"outside any call: {sorted(codes)}")
            continue
        case = cases[label][number]
        if unknown.get((label, 0)) and number:
            continue  # its known values are invalid: said once
        rest = codes - twins.get((label, number), set())
        if case.what == "known values" and codes:
            out[label].append(f"known values invalid: {sorted(codes)}  [{case.unknown}]")
        elif rest:
            out[label].append(f"{case.what}: {sorted(rest)}  [{case.unknown}]")
    return dict(out)


def test_every_exported_callable_is_swept() -> None:
    swept = modelled_callables()
    assert len(swept) >= 150
    unswept = [m.label for m in swept if not list(calls(m))]
    assert unswept == ["ament_index_python.PackageNotFoundError"]  # no signature: an exception


# An instance of a class deriving from an absent module's class (``UnknownInstance``,
# models/launch_api/unknown.py) must be as unknown as any value of the module.
DERIVED = "instance of a derived class"


# Calls whose values a loop over an unknown built (no round in the plain world, one in the
# varied one): what the loop built is no fact (``assumptions.unvary``). A model's failure
# on such a value points at the call (the action's line).
LEFT = ("=comprehension: ['LV102']", "outside any call: ['LV002']")


def _problems(sweep: dict[str, list[str]], derived: bool, left: bool = False) -> list[str]:
    return [f"{label}: {problem}" for label, problems in sorted(sweep.items())
            for problem in problems if (DERIVED in problem) is derived
            and any(mark in problem for mark in LEFT) is left]


def test_the_sweep_sees_a_real_error(tmp_path: Path) -> None:
    # The control: a call launch rejects whatever the values are, found at its call, and
    # a valid one beside it silent (a pipeline that evaluates nothing would find neither).
    [declare] = [m for m in modelled_callables()
                 if m.label == "launch.actions.DeclareLaunchArgument"]
    launch = package(tmp_path / "control_pkg")
    found = _errors(launch, {"control": (declare, {1: "target('a', choices=[])",
                                                   2: "target('b', choices=['x'])"})})
    assert found == {(declare.label, 1): {"LV002"}}


def test_no_error_rests_on_an_unknown(sweep: dict[str, list[str]]) -> None:
    lines = _problems(sweep, derived=False)
    assert not lines, "\n".join(lines)


def test_no_error_rests_on_a_loop_over_an_unknown(sweep: dict[str, list[str]]) -> None:
    lines = _problems(sweep, derived=False, left=True)
    assert not lines, "\n".join(lines)


def test_no_error_rests_on_an_instance_of_an_unknown_class(sweep: dict[str, list[str]]) -> None:
    lines = _problems(sweep, derived=True)
    assert not lines, "\n".join(lines)
