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

import dataclasses
import itertools
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from typing import Generic, TypeVar

from launchverify.ir import actions as a
from launchverify.ir import subst as s
from launchverify.ir.conditions import Condition, IfCondition
from launchverify.models.launch_api.placeholders import WORLD, varied_world
from launchverify.problems import Problem, ProblemKind
from launchverify.span import Span

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
    before_varied = WORLD.fixed
    with varied_world():
        other, repeated = run()
    # the other run may reach what neither can vary (its own path to an unknown's type)
    unvaried = unvaried or WORLD.fixed != before_varied
    # an assumption no other run can vary (an unknown value's type): nothing is a fact
    problems = settle(found, () if unvaried else repeated, assumed) if failed else list(found)
    depends = branched and shape(actions(result)) != shape(actions(other))
    if branched and actions(result) is not None and actions(other) is not None:
        what = ", ".join(f"<{name}>" for name in reversed(assumed[-3:]))
        unvary(result, other, f"what launchverify assumed for unknown values: {what}")
    return Checked(result, problems, depends)


def unvary(plain: object, varied: object, what: str) -> None:
    """Merge, in place, what the other world built into the plain world's result.

    A value may differ between the worlds: a name joined from a loop over a vendor's list
    (no round, then one), a flag's text. Such a value rests on an assumption, so it is
    no fact: it becomes an unknown (``s.Opaque``), and a condition that differs an unknown
    condition. Where the worlds built different actions, an action is paired with the
    other world's of its kind written at the same place; an action only the other world
    built (the nodes of a launch that checks for a file only the robot has, then finds it
    absent) is kept too, under an unknown condition, so that what each answer starts is
    in the graph. Actions keep their identity (an event handler names its target by it).
    """
    seen: set[int] = set()
    made = itertools.count(1)  # each its own unknown: two of them are not one value
    paired: dict[int, a.Action] = {}  # the other world's action -> this world's partner
    kept: list[a.Group] = []  # what only the other world started, under its condition

    def walk(mine: object, theirs: object) -> None:
        if (mine is theirs or id(mine) in seen or type(mine) is not type(theirs)
                or not dataclasses.is_dataclass(mine) or isinstance(mine, (s.Sub, Span))):
            return
        seen.add(id(mine))
        if isinstance(mine, a.Action):
            paired[id(theirs)] = mine
        for item in dataclasses.fields(mine):
            old = getattr(mine, item.name)
            new = value(old, getattr(theirs, item.name))
            if new is not old:
                object.__setattr__(mine, item.name, new)

    def value(mine: object, theirs: object) -> object:
        if isinstance(mine, s.Sub):
            if mine == theirs or not isinstance(theirs, s.Sub):
                return mine
            return s.Opaque(f"a value built from {what}, #{next(made)}")
        conditions = (isinstance(mine, Condition) or mine is None) and (
            isinstance(theirs, Condition) or theirs is None)
        if conditions and mine is not theirs and type(mine) is not type(theirs):
            # whether it runs rests on the assumption
            return IfCondition(s.Opaque(f"a condition built from {what}, #{next(made)}"))
        if type(mine) is tuple and type(theirs) is tuple:
            partners = _partners(mine, theirs)
            items = tuple(item if partner is None else value(item, partner)
                          for item, partner in zip(mine, partners, strict=True))
            if mine and not all(isinstance(item, a.Action) for item in mine):
                extra: tuple[object, ...] = ()
            else:
                extra = tuple(other_world(item) for item in theirs if isinstance(
                    item, a.Action) and not any(item is p for p in partners))
            if not extra and all(x is y for x, y in zip(items, mine, strict=True)):
                return mine
            return items + extra
        walk(mine, theirs)
        return mine

    def other_world(action: a.Action) -> a.Action:
        group = a.Group(span=action.span, condition=IfCondition(s.Opaque(
            f"the other answers about {what}, #{next(made)}")), actions=(action,),
            scoped=False, forwarding=True)
        kept.append(group)
        return group

    value(plain, varied)
    for group in kept:
        # an action this world built too, without starting it (a handler's target that
        # only the other answers start): started as this world's, so that what names it
        # by identity (``OnProcessExit(target_action=driver)``) finds it
        partner = paired.get(id(group.actions[0]))
        if partner is not None:
            object.__setattr__(group, "actions", (partner,))


def _partners(mine: tuple[object, ...], theirs: tuple[object, ...]) -> list[object | None]:
    """Return, for each item of one world's tuple, the other world's item it stands for.

    Items at the same place, when both worlds hold as many; otherwise an action is the
    other world's action of its kind written at the same place (a loop's extra round
    has none), and other items have no partner.
    """
    if len(mine) == len(theirs) and all(
            type(x) is type(y) and getattr(x, "span", None) == getattr(y, "span", None)
            for x, y in zip(mine, theirs, strict=True)):
        return list(theirs)
    if not all(isinstance(item, a.Action) for item in (*mine, *theirs)):
        return list(theirs) if len(mine) == len(theirs) else [None] * len(mine)
    left = list(theirs)
    found: list[object | None] = []
    for item in mine:
        partner = next((other for other in left if type(other) is type(item)
                        and getattr(other, "span", None) == getattr(item, "span", 0)), None)
        if partner is not None:
            left.remove(partner)
        found.append(partner)
    return found


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
