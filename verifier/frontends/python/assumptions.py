"""What rests on what launchverify assumed for unknown values is no fact.

Where a launch file's code asks an unknown value for a plain answer (``if cfg.enabled``,
``max(cfg.rates)``, ``for robot in cfg.robots``), launchverify assumes one (``WORLD``).
What follows may rest on that assumption: on the robot the module gives real values. So
an evaluation that assumed an answer it could branch on, or that failed after assuming
anything, runs again with every assumption the other way (the varied world):

- a failure that does not happen again is not an error (LV002) but something
  launchverify cannot tell (LV003), naming what it assumed;
- if the other run builds other actions (a loop that declared arguments ran once instead
  of never), what the file describes depends on the answers: it ends with an unknown
  action, so that no rule claims what it lacks.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from typing import Generic, TypeVar

from launchverify.ir import actions as a
from launchverify.models.launch_api.placeholders import WORLD, varied_world
from launchverify.problems import Problem, ProblemKind

_T = TypeVar("_T")


@dataclass
class Checked(Generic[_T]):
    """An evaluation's result and problems, once checked against the varied world."""

    result: _T
    problems: list[Problem]
    depends: bool = False  # the other answers build other actions


def checked(run: Callable[[], tuple[_T, Sequence[Problem]]],
            actions: Callable[[_T], tuple[a.Action, ...] | None]) -> Checked[_T]:
    """Run an evaluation, and again in the varied world where what it assumed may matter.

    ``run`` evaluates and returns its result and problems; ``actions`` what the result
    describes (``None`` when it describes nothing).
    """
    answers, fixed, branches = WORLD.answers, WORLD.fixed, WORLD.branches
    WORLD.answered.clear()  # what this run assumes (a worker may have run another file)
    result, found = run()
    failed = any(p.kind is ProblemKind.EVALUATION for p in found)
    branched = WORLD.branches != branches
    if WORLD.answers == answers or not (failed or branched):
        return Checked(result, list(found))
    assumed, unvaried = list(WORLD.answered), WORLD.fixed != fixed
    with varied_world():
        other, repeated = run()
    # an assumption no other run can vary (an unknown value's type): nothing is a fact
    problems = settle(found, () if unvaried else repeated, assumed) if failed else list(found)
    depends = branched and shape(actions(result)) != shape(actions(other))
    return Checked(result, problems, depends)


def shape(actions: tuple[a.Action, ...] | None) -> object:
    """Return the kinds of a description's actions, nested as they are (not their values)."""
    if actions is None:
        return None
    return tuple((type(action).__name__, shape(action.sub_actions())) for action in actions)


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
