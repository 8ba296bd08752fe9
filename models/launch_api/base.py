"""What every modelled launch API object shares: where it was created, how it becomes IR.

Python launch files build launch objects; our models of those classes record the line of
the user's file that created each object (never a line of ours) and know how to turn
themselves into the same IR the XML and YAML frontends produce. Conversion needs a
``Converter`` (supplied by the Python frontend) that handles Python values: strings,
substitutions, lists of them, conditions, parameters.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Iterable
from pathlib import Path
from types import FrameType
from typing import TYPE_CHECKING, Any, Protocol

from launchverify.ir import subst as s
from launchverify.ir.actions import Action as IRAction
from launchverify.ir.conditions import Condition as IRCondition
from launchverify.models.launch_api import runtime
from launchverify.models.launch_api.runtime import blamable
from launchverify.span import Span

if TYPE_CHECKING:
    from launchverify.ir import actions as a

def caller_span(skip: int = 1) -> Span:
    """Return the span of the call in user code that is creating an object.

    Frames of launchverify itself (models, frontend) are skipped, so a Node built inside a
    helper function of the user's points at the helper's line.
    """
    frame: FrameType | None = sys._getframe(skip)
    while frame is not None and not blamable(frame.f_code.co_filename):
        frame = frame.f_back
    if frame is None:
        fallback = runtime.current.fallback if runtime.current is not None else None
        return fallback or Span(Path("<unknown>"), 1)
    return _frame_span(frame)


def _frame_span(frame: FrameType) -> Span:
    path = Path(frame.f_code.co_filename)
    line = frame.f_lineno or 1
    positions = getattr(frame.f_code, "co_positions", None)
    if positions is not None:
        try:
            entry = list(positions())[frame.f_lasti // 2]
        except (IndexError, ValueError):
            entry = None
        if entry and entry[0] is not None and entry[2] is not None:
            start, end, column, end_column = entry
            return Span(path, start, column + 1, end, (end_column or column) + 1)
    return Span(path, line)


class Converter(Protocol):
    """What models need from the frontend to become IR."""

    def sub(self, value: Any) -> s.Sub:
        """Return a substitution expression for a ``SomeSubstitutionsType`` value."""

    def opt_sub(self, value: Any) -> s.Sub | None:
        """Return ``sub(value)``, or ``None`` for ``None``."""

    def condition(self, value: Any) -> IRCondition | None:
        """Return an IR condition for a modelled condition (or ``None``)."""

    def actions(self, entities: Any) -> tuple[IRAction, ...]:
        """Return IR actions for launch description entities (flattening nested lists)."""

    def action(self, entity: Any) -> IRAction | None:
        """Return the IR action for one entity (the same object every time)."""

    def parameters(self, value: Any, span: Span) -> tuple[a.ParamEntry, ...]:
        """Return IR parameter entries for a Node's ``parameters`` list (built at ``span``)."""

    def param_value(self, value: Any) -> a.ParamValue:
        """Return an IR parameter value for one Python value."""

    def remaps(self, value: Any, span: Span) -> tuple[a.Remap, ...]:
        """Return IR remap rules for a list of ``(from, to)`` pairs."""

    def pairs(self, value: Any) -> tuple[tuple[s.Sub, s.Sub], ...]:
        """Return ``(name, value)`` expressions for a dict or iterable of pairs."""

    def unmodeled(self, what: str, span: Span) -> None:
        """Record that something was not modelled (LV003)."""

    def fail(self, message: str, span: Span) -> None:
        """Record that the launch would raise at ``span`` (LV002)."""

    def claim(self, source: Any) -> bool:
        """Return ``False`` when a description source was already used by an include."""


class LaunchDescriptionEntity:
    """Base of everything that can appear in a launch description."""

    def __init__(self) -> None:
        self._span = caller_span()

    def to_ir(self, cv: Converter) -> IRAction | None:
        """Return the IR action for this entity (a subclass we do not know is opaque)."""
        from launchverify.ir.actions import OpaqueAction

        span = getattr(self, "_span", None) or caller_span()
        name = type(self).__name__
        cv.unmodeled(f"action {name} is not modelled; what it does is unknown", span)
        return OpaqueAction(span=span, description=name)

    def describe(self) -> str:
        """Return a short description (launch's API)."""
        return type(self).__name__

    def get_sub_entities(self) -> list[LaunchDescriptionEntity]:
        """Return nested entities (launch's API)."""
        return []


class Action(LaunchDescriptionEntity):
    """``launch.Action``: an entity with an optional condition."""

    def __init__(self, *, condition: Any = None) -> None:
        super().__init__()
        self.__condition = condition

    @property
    def condition(self) -> Any:
        """Return the condition (launch's API)."""
        return self.__condition

    def common(self, cv: Converter) -> dict[str, Any]:
        """Return the keyword arguments every IR action takes."""
        common: dict[str, Any] = {"span": self._span,
                                  "condition": cv.condition(self.__condition)}
        where = getattr(self.__condition, "_span", None)
        if where is not None:  # findings about the condition point at it
            common["attr_spans"] = {"if": where}
        return common

    def execute(self, context: Any) -> None:
        """Do nothing: statically nothing executes."""
        return None

    def visit(self, context: Any) -> None:
        """Do nothing: statically nothing executes."""
        return None


class Substitution:
    """Base of the modelled substitutions: each holds its IR expression."""

    def __init__(self) -> None:
        self._span = caller_span()

    def to_sub(self, cv: Converter) -> s.Sub:
        """Return the IR expression (a subclass we do not know is opaque)."""
        name = type(self).__name__
        cv.unmodeled(f"substitution {name} is not modelled; its value is unknown",
                     getattr(self, "_span", None) or caller_span())
        return s.Opaque(name)

    def describe(self) -> str:
        """Return a description (launch's API)."""
        return type(self).__name__

    def perform(self, context: Any) -> str:
        """Perform the substitution in an OpaqueFunction's concrete context."""
        performer = getattr(context, "perform_substitution", None)
        if performer is None:
            raise TypeError("perform() needs a LaunchContext")
        result: str = performer(self)
        return result


class Condition:
    """Base of the modelled conditions."""

    def __init__(self) -> None:
        self._span = caller_span()

    def to_condition(self, cv: Converter) -> IRCondition:
        """Return the IR condition (a subclass we do not know is opaque)."""
        from launchverify.ir.conditions import OpaqueCondition

        return OpaqueCondition(f"condition {type(self).__name__}")

    def evaluate(self, context: Any) -> bool:
        """Evaluate in an OpaqueFunction's concrete context."""
        evaluator = getattr(context, "evaluate_condition", None)
        if evaluator is None:
            raise TypeError("evaluate() needs a LaunchContext")
        result: bool = evaluator(self)
        return result


def check_substitutions(value: Any) -> Any:
    """Raise like ``normalize_to_list_of_substitutions`` on what launch does not accept.

    Launch takes a string, a substitution, or an iterable of those; anything else (a bool,
    a number, None) is a ``TypeError`` in the launch file. Paths and values from
    unmodelled code are accepted.
    """
    if isinstance(value, (str, Substitution, os.PathLike)) or _unknown(value):
        return value
    if isinstance(value, (bool, int, float)) or value is None:
        raise TypeError(f"'{type(value).__name__}' object is not iterable")
    try:
        items = list(value)
    except TypeError:
        raise TypeError(f"'{type(value).__name__}' object is not iterable") from None
    for item in items:
        if not isinstance(item, (str, Substitution, os.PathLike)) and not _unknown(item):
            raise TypeError(f"Failed to normalize given item of type '{type(item)}', when "
                            "only 'str' or 'launch.Substitution' were expected.")
    return value


def _unknown(value: Any) -> bool:
    return type(value).__name__ in ("Opaque", "OpaqueBase") or hasattr(value, "_description")


def flatten(entities: Iterable[Any] | None) -> list[Any]:
    """Flatten nested lists and tuples of entities, as launch accepts them."""
    out: list[Any] = []
    for item in entities or []:
        if isinstance(item, (list, tuple)):
            out.extend(flatten(item))
        else:
            out.append(item)
    return out
