"""What every modelled launch API object shares: where it was created, how it becomes IR.

Python launch files build launch objects; our models of those classes record the line of
the user's file that created each object (never a line of ours) and know how to turn
themselves into the same IR the XML and YAML frontends produce. Conversion needs a
``Converter`` (supplied by the Python frontend) that handles Python values: strings,
substitutions, lists of them, conditions, parameters.
"""

from __future__ import annotations

import contextlib
import functools
import os
import sys
import sysconfig
from collections.abc import Iterable
from pathlib import Path
from types import CodeType, FrameType
from typing import TYPE_CHECKING, Any, Protocol, cast

from launchverify.ir import subst as s
from launchverify.ir.actions import Action as IRAction
from launchverify.ir.conditions import Condition as IRCondition
from launchverify.models.launch_api import runtime
from launchverify.models.launch_api.runtime import blamable
from launchverify.own_code import is_own_file
from launchverify.span import Span, character_column
from launchverify.workspace.reading import read_file, unsaved

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


_Position = tuple[int | None, int | None, int | None, int | None]  # lines, columns


@functools.lru_cache(maxsize=256)
def _positions(code: CodeType) -> tuple[_Position, ...] | None:
    """Return a code object's instruction positions (a loop asks for the same ones often)."""
    positions = getattr(code, "co_positions", None)
    if positions is None:
        return None
    try:
        return tuple(positions())
    except ValueError:
        return None


def in_characters(span: Span) -> Span:
    """Return a span Python placed in UTF-8 bytes with character columns.

    Every span counts characters; Python's code positions, ``ast`` and tracebacks count
    a line's bytes. Lines in ASCII are the same both ways.
    """
    column = _characters(span.file, span.line, span.column - 1)
    end = None if span.end_column is None else _characters(
        span.file, span.end_line or span.line, span.end_column - 1)
    if column == span.column and end == span.end_column:
        return span
    return Span(span.file, span.line, column, span.end_line, end)


def _characters(path: Path, line: int, offset: int) -> int:
    """Return the character column of Python's UTF-8 byte ``offset`` on a line."""
    lines = _source(path)
    return character_column(lines[line - 1], offset) if 0 < line <= len(lines) \
        else offset + 1


def _source(path: Path) -> tuple[bytes, ...]:
    """Return a file's lines as bytes (the editor's buffer when one stands for it)."""
    data = unsaved(path)
    if data is not None:
        return tuple(data.split(b"\n"))
    try:
        stat = path.stat()
    except OSError:
        return ()
    return _read_lines(path, stat.st_mtime_ns, stat.st_size)


@functools.lru_cache(maxsize=64)
def _read_lines(path: Path, mtime_ns: int, size: int) -> tuple[bytes, ...]:
    """Return one version of a file's lines (asked again for each place in it)."""
    try:
        return tuple(read_file(path).split(b"\n"))
    except OSError:
        return ()


def _frame_span(frame: FrameType) -> Span:
    code = frame.f_code
    return _span_at(code, code.co_filename, frame.f_lasti, frame.f_lineno)


@functools.lru_cache(maxsize=4096)
def _span_at(code: CodeType, filename: str, lasti: int, lineno: int | None) -> Span:
    """Return the span of one instruction (a loop gets the same object: sent once).

    ``filename`` is part of the key: code objects compare equal without it, and two
    launch files alike but for a string are evaluated by one worker one after the other.
    """
    path = Path(filename)
    line = lineno or 1
    positions = _positions(code)
    if positions is not None:
        index = lasti // 2
        if 0 <= index < len(positions):
            start, end, column, end_column = positions[index]
            if start is not None and column is not None:  # bytes: in characters
                return in_characters(
                    Span(path, start, column + 1, end, (end_column or column) + 1))
    return Span(path, line)


class Converter(Protocol):
    """What models need from the frontend to become IR."""

    def sub(self, value: Any) -> s.Sub:
        """Return a substitution expression for a ``SomeSubstitutionsType`` value."""

    def opt_sub(self, value: Any) -> s.Sub | None:
        """Return ``sub(value)``, or ``None`` for ``None``."""

    def performed(self, value: Substitution) -> s.Sub | None:
        """Return what a launch file's own Substitution subclass performs to, if knowable."""

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

    def keyword_keys(self, call: Span, keyword: str) -> dict[str, Span]:
        """Return where each literal key of the call's ``keyword=`` dict or pairs is written."""

    def keyword_values(self, call: Span) -> dict[str, Span]:
        """Return where the value of each keyword argument of the call is written."""

    def written(self, call: Span, value: Any, *, position: int | None = None,
                keyword: str | None = None, item: int | None = None,
                items: int | None = None) -> s.Sub:
        """Return ``sub(value)``, located when the call writes it as a plain string literal.

        The argument is the call's ``position``-th or its ``keyword=`` one (``item``: an
        item of the list of ``items`` written there). A located literal (``Text.where``)
        can be fixed.
        """

    def written_key(self, call: Span, keyword: str, key: Any) -> s.Sub:
        """Return ``sub(key)`` for a key of the call's ``keyword=`` dict, located if literal."""

    def unmodeled(self, what: str, span: Span) -> None:
        """Record that something was not modelled (LV003)."""

    def fail(self, message: str, span: Span) -> None:
        """Record that the launch would raise at ``span`` (LV002)."""

    def claim(self, source: Any) -> bool:
        """Return ``False`` when a description source was already used by an include."""


# ------------------------------------------------------------------ what a model lacks

def _installed_folders() -> tuple[str, ...]:
    """Return the folders of Python's standard library and of installed libraries."""
    import site

    folders = {sysconfig.get_paths().get(key) for key in (
        "stdlib", "platstdlib", "purelib", "platlib")}
    folders.update(os.path.join(prefix, "lib")  # noqa: PTH118 (as runtime.blamable)
                   for prefix in (sys.prefix, sys.base_prefix, sys.exec_prefix))
    with contextlib.suppress(AttributeError):  # an old virtualenv's site module lacks it
        folders.update(site.getsitepackages())
    return tuple(sorted(folder.rstrip(os.sep) + os.sep for folder in folders if folder))


_INSTALLED = _installed_folders()


def _user_code(filename: str) -> bool:
    """Return whether a frame in ``filename`` is the launch file's code (or its helpers).

    Not launchverify's own code (which probes attributes with ``getattr(x, name, default)``
    and must keep getting ``AttributeError``), not Python's or an installed library's.
    """
    return not (is_own_file(filename) or filename.startswith(("<", *_INSTALLED)))


def _model_name(obj: Any) -> str:
    """Return the name of the nearest launchverify model class of ``obj`` (its launch name)."""
    for klass in type(obj).__mro__:
        if klass.__module__.startswith("launchverify."):
            return klass.__name__
    return type(obj).__name__


def unmodelled_attribute(obj: Any, name: str, depth: int = 2) -> Any:
    """Return an unknown value for an attribute a model lacks, read by the launch file.

    The real class may well have it (an attribute of launch nobody modelled yet): the
    launch file gets an opaque value and one LV003, never an ``AttributeError`` that would
    be reported as the launch file's failure (LV002). Dunder names, reads outside an
    evaluation and reads by launchverify's or a library's code keep raising
    ``AttributeError``, which Python's protocols and ``getattr(x, name, default)`` rely on.
    """
    frame: FrameType | None = sys._getframe(depth)
    missing = AttributeError(f"'{type(obj).__name__}' object has no attribute '{name}'",
                             name=name, obj=obj)
    if (name.startswith("__") or runtime.current is None or frame is None
            or not _user_code(frame.f_code.co_filename)):
        raise missing
    from launchverify.models.launch_api.unknown import Opaque

    what = f"{_model_name(obj)}.{name}"
    while frame is not None and not blamable(frame.f_code.co_filename):
        frame = frame.f_back
    span = _frame_span(frame) if frame is not None else (
        runtime.current.fallback or Span(runtime.current.launch_file, 1))
    runtime.current.unmodeled(f"{what} is not modelled; values from it are unknown", span)
    return Opaque(what)


class Modelled:
    """Base of the models of launch's classes: what a model lacks is unknown, not an error.

    ``__getattr__`` runs only for attributes the model does not have (see
    ``unmodelled_attribute``); type checkers do not see it, so a typo in launchverify's own
    code stays an error for them.
    """

    if not TYPE_CHECKING:
        def __getattr__(self, name: str) -> Any:
            return unmodelled_attribute(self, name)


def launch_getter(attribute: str, doc: str) -> Any:
    """Return a read-only property like launch's getters (``normalized(attribute)``).

    Launch's classes expose what their constructor took as lists of substitutions; the
    models keep the value as given and normalise it when a launch file reads it.
    """

    def read(self: Any) -> Any:
        return normalized(getattr(self, attribute))

    read.__doc__ = doc
    return property(read)


def normalized(value: Any) -> Any:
    """``normalize_to_list_of_substitutions``, for what models return to launch files.

    Launch's getters return lists of substitutions where the constructor took strings,
    substitutions or lists of them; values launchverify does not know (opaque values) stay
    as they are, and ``None`` stays ``None``.
    """
    from launchverify.models.launch_api.launch_substitutions import TextSubstitution

    def one(item: Any) -> Any:
        if isinstance(item, (str, os.PathLike)):
            return TextSubstitution(text=os.fspath(item) if not isinstance(item, str) else item)
        return item

    if value is None:
        return None
    if isinstance(value, (str, os.PathLike, Substitution)) or _unknown(value):
        return [one(value)]
    try:
        items = list(value)
    except TypeError:
        return [value]
    return [one(item) for item in items]


def typed(value: Any) -> Any:
    """``normalize_typed_substitution``: scalars stay, substitutions become lists of them."""
    if isinstance(value, (bool, int, float, str)) or value is None:
        return value
    if isinstance(value, Substitution) or _unknown(value):
        return normalized(value)
    try:
        items = list(value)
    except TypeError:
        return value
    if items and all(isinstance(item, (str, Substitution)) for item in items) and any(
            isinstance(item, Substitution) for item in items):
        return normalized(items)
    return [item if isinstance(item, (bool, int, float, str)) else normalized(item)
            for item in items]


def described(substitutions: Any) -> str:
    """Return ``' + '.join(sub.describe() ...)`` as launch's ``describe()`` methods do."""
    return " + ".join(
        sub.describe() if isinstance(sub, Substitution) else repr(sub)
        for sub in normalized(substitutions) or [])


class LaunchDescriptionEntity(Modelled):
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

    def describe_sub_entities(self) -> list[Any]:
        """Return the sub-entities always visited (launch's API)."""
        return []

    def describe_conditional_sub_entities(self) -> list[tuple[str, Any]]:
        """Return ``(condition description, entities)`` pairs (launch's API)."""
        return []

    def visit(self, context: Any) -> Any:
        """Visit the entity (launch's API): statically nothing runs."""
        return None

    def get_asyncio_future(self) -> None:
        """Return the future of an on-going activity: statically there is none."""
        return None


# Python keywords and the XML attributes IR actions know them by (``Action.at``).
ATTRIBUTE_OF_KEYWORD = {"package": "pkg", "executable": "exec", "name": "name",
                        "namespace": "namespace", "plugin": "plugin", "filename": "filename",
                        "src": "from", "dst": "to", "condition": "if"}


def attribute_spans(cv: Converter, call: Span) -> dict[str, Span]:
    """Return where the call's keyword values are written, by IR attribute name.

    Findings about one attribute (a misspelt package, an invalid name) point at its value,
    as they point at the attribute in XML.
    """
    written = cv.keyword_values(call)
    return {ATTRIBUTE_OF_KEYWORD[k]: span for k, span in written.items()
            if k in ATTRIBUTE_OF_KEYWORD}


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
        common["attr_spans"] = attribute_spans(cv, self._span)
        where = getattr(self.__condition, "_span", None)
        if where is not None:  # findings about the condition point at it
            common["attr_spans"]["if"] = where
        return common

    def describe(self) -> str:
        """Return a description (launch's ``Action.describe``: the object's repr)."""
        return repr(self)

    def describe_sub_entities(self) -> list[Any]:
        """Return the sub-entities when unconditional (launch's API)."""
        return list(self.get_sub_entities()) if self.__condition is None else []

    def describe_conditional_sub_entities(self) -> list[tuple[str, Any]]:
        """Return the sub-entities under their condition (launch's API)."""
        if self.__condition is None:
            return []
        return [(f"Conditionally included by {self.describe()}", self.get_sub_entities())]

    def execute(self, context: Any) -> Any:
        """Do nothing: statically nothing executes."""
        return None

    def visit(self, context: Any) -> Any:
        """Execute when the condition holds in ``context`` (launch's ``Action.visit``)."""
        if self.__condition is None or self.__condition.evaluate(context):
            return self.execute(context)
        return None


class Substitution(Modelled):
    """Base of the modelled substitutions: each holds its IR expression."""

    def __init__(self) -> None:
        self._span = caller_span()

    def to_sub(self, cv: Converter) -> s.Sub:
        """Return the IR expression (a subclass we do not know is opaque)."""
        performed = cv.performed(self)
        if performed is not None:
            return performed
        name = type(self).__name__
        cv.unmodeled(f"substitution {name} is not modelled; its value is unknown",
                     getattr(self, "_span", None) or caller_span())
        return s.Opaque(name)

    def describe(self) -> str:
        """Return a description (launch's ``Substitution.describe``: the object's repr)."""
        return repr(self)

    def perform(self, context: Any) -> str:
        """Perform the substitution in an OpaqueFunction's concrete context."""
        if _unknown(context):  # a context of code launchverify cannot see: its text too
            from launchverify.models.launch_api.unknown import Opaque

            return Opaque(f"{type(self).__name__} performed in an unknown context")
        performer = getattr(context, "perform_substitution", None)
        if performer is None:
            raise TypeError("perform() needs a LaunchContext")
        result: str = performer(self)
        return result


class Condition(Modelled):
    """Base of the modelled conditions."""

    def __init__(self) -> None:
        self._span = caller_span()

    def to_condition(self, cv: Converter) -> IRCondition:
        """Return the IR condition (a subclass we do not know is opaque)."""
        from launchverify.ir.conditions import OpaqueCondition

        return OpaqueCondition(f"condition {type(self).__name__}")

    def evaluate(self, context: Any) -> bool:
        """Evaluate in an OpaqueFunction's concrete context."""
        if _unknown(context):  # a context of code launchverify cannot see: an unknown truth
            from launchverify.models.launch_api.unknown import Opaque

            return cast(bool, Opaque(f"{type(self).__name__} in an unknown context"))
        evaluator = getattr(context, "evaluate_condition", None)
        if evaluator is None:
            raise TypeError("evaluate() needs a LaunchContext")
        result: bool = evaluator(self)
        return result

    def describe(self) -> str:
        """Return a description (launch's ``Condition.describe``: the object's repr)."""
        return repr(self)


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
