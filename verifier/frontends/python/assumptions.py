"""A failure is a fact only if it happens whatever launchverify assumed for unknown values.

Where a launch file's code asks an unknown value for a plain answer (``if cfg.enabled``,
``max(cfg.rates)``, ``cfg.mode in (...)``), launchverify assumes one (``WORLD``). A
failure that follows may rest on that assumption: on the robot the module gives real
values and the file runs. So an evaluation that failed after assuming anything runs
again with every assumption the other way; a failure that does not happen again is not
an error (LV002) but something launchverify cannot tell (LV003), naming what it assumed.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from typing import TypeVar

from launchverify.models.launch_api.placeholders import WORLD, varied_world
from launchverify.problems import Problem, ProblemKind

_T = TypeVar("_T")


def checked(run: Callable[[], _T], problems: Callable[[_T], Sequence[Problem]],
            again: Callable[[], Sequence[Problem]]) -> tuple[_T, list[Problem]]:
    """Run an evaluation; its failures that rest on assumptions become LV003.

    ``run`` evaluates, ``problems`` says what its result recorded, ``again`` evaluates
    once more (in the varied world) and returns what that run recorded.
    """
    answers, fixed = WORLD.mark()
    result = run()
    found = list(problems(result))
    if not any(p.kind is ProblemKind.EVALUATION for p in found) or WORLD.answers == answers:
        return result, found
    assumed = list(WORLD.answered)
    if WORLD.fixed != fixed:  # an assumption no other run can vary: nothing is a fact
        return result, settle(found, (), assumed)
    with varied_world():
        repeated = again()
    return result, settle(found, repeated, assumed)


def settle(plain: Iterable[Problem], varied: Iterable[Problem],
           assumed: Sequence[str]) -> list[Problem]:
    """Keep the failures that happen in both worlds; the others cannot be told."""
    again = {(p.kind, p.span, p.message) for p in varied}
    what = ", ".join(f"<{name}>" for name in reversed(assumed[-3:])) or "an unknown value"
    out = []
    for problem in plain:
        if problem.kind is ProblemKind.EVALUATION and (
                problem.kind, problem.span, problem.message) not in again:
            problem = Problem(
                ProblemKind.UNMODELED,
                f"cannot tell whether ros2 launch fails here: {problem.message}, but that "
                f"rests on what launchverify assumed for values it cannot know ({what})",
                problem.span)
        out.append(problem)
    return out
