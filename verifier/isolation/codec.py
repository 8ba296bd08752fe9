"""The IR as plain data, for the trip from a worker process back to launchverify.

A worker evaluates a Python launch file and sends back what it built. The parent must not
trust it: the bytes may come from the launch file's own code. So the wire format is JSON
(nothing in it can run), and decoding rebuilds only the IR's own record classes, checking
every field against the record's type annotations. Anything else is a ``CodecError``,
which the parent reports on the file; it never reaches the evaluator.

Shape: scalars are themselves (integers within 64 bits, as ROS's: a larger one is refused
rather than sent, since converting huge integers to text is refused by Python and
quadratic); every container is a list whose first item is a tag: ``["#t", ...]`` a
tuple, ``["#l", ...]`` a list, ``["#d", k, v, ...]`` a dict with string keys, ``["#p",
text]`` a path, ``["#e", enum, value]``, ``["#f", id]`` a callback that runs in the
worker, ``["#r", n]`` the n-th record again
(actions are compared by identity: an event handler's target is the same object as the
action in the list; a file's encoder and decoder live on across its OpaqueFunctions'
answers, so a node made before one ran is that node in its answer too), and
``[ClassName, field...]`` a record with its fields in order.
"""

from __future__ import annotations

import dataclasses
import enum
import types
import typing
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

from launchverify.ir import actions, conditions, subst
from launchverify.problems import Problem, ProblemKind
from launchverify.span import Span

MAX_DEPTH = 400  # nested records; deeper descriptions are refused, not recursed into
MAX_RECORDS = 250_000  # records in one answer: what one file may put into the verdict
_SMALL_INT = 1 << 63


class CodecError(Exception):
    """Data that is not a well-formed launch description."""


class TooLarge(CodecError):
    """A launch description past what one file may put into the verdict."""


def _records() -> dict[str, type]:
    """Return every record class that may cross the boundary, by name."""
    found: dict[str, type] = {}
    for module in (subst, conditions, actions):
        for name, value in vars(module).items():
            if isinstance(value, type) and dataclasses.is_dataclass(value) \
                    and value.__module__ == module.__name__:
                if name in found:
                    raise RuntimeError(f"two IR records are named {name}")
                found[name] = value
    found["Span"] = Span
    found["Problem"] = Problem
    return found


RECORDS = _records()
_NAMES = {cls: tuple(f.name for f in dataclasses.fields(cls)) for cls in RECORDS.values()}
ENUMS: dict[str, type[enum.Enum]] = {"ProblemKind": ProblemKind}
_SCALARS = frozenset({bool, str, int, float})  # what JSON decodes to (exactly these types)


# --------------------------------------------------------------------------- encoding


class Encoder:
    """Turns IR into plain data; callables become numbered callbacks (``register``)."""

    def __init__(self, register: Callable[[Callable[..., Any]], int]) -> None:
        self.register = register
        self._seen: dict[int, int] = {}
        self._spans: dict[Span, int] = {}  # equal places are sent once (a loop's calls)
        self._keep: list[object] = []  # ids stay unique while the encoding runs

    @property
    def sent(self) -> int:
        """Return how many records this encoder has sent (the next one's number)."""
        return len(self._keep)

    def encode(self, value: object, depth: int = 0) -> object:
        kind = type(value)
        if kind is str or value is None or kind is bool or kind is float:
            return value
        names = _NAMES.get(kind)
        if names is not None:  # a record: the common case, dispatched first
            known = self._seen.get(id(value))
            if known is None and kind is Span:
                known = self._spans.get(value)  # type: ignore[call-overload]
            if known is not None:
                return ["#r", known]
            if depth > MAX_DEPTH:
                raise CodecError(f"the launch description nests deeper than {MAX_DEPTH} "
                                 "levels")
            self._seen[id(value)] = len(self._keep)
            if kind is Span:
                self._spans[value] = len(self._keep)  # type: ignore[index]
            self._keep.append(value)
            encode = self.encode
            depth += 1
            return [kind.__name__, *[encode(getattr(value, name), depth) for name in names]]
        if isinstance(value, (bool, str, float)):
            return value
        if isinstance(value, int):
            if not -_SMALL_INT <= value < _SMALL_INT:
                raise CodecError(f"an integer of {value.bit_length()} bits (ROS integers "
                                 "have 64)")
            return value
        if depth > MAX_DEPTH:
            raise CodecError(f"the launch description nests deeper than {MAX_DEPTH} levels")
        if isinstance(value, enum.Enum):
            return ["#e", type(value).__name__, value.value]
        if isinstance(value, Path):
            return ["#p", str(value)]
        if isinstance(value, tuple):
            return ["#t", *(self.encode(item, depth + 1) for item in value)]
        if isinstance(value, list):
            return ["#l", *(self.encode(item, depth + 1) for item in value)]
        if isinstance(value, dict):
            out: list[object] = ["#d"]
            for key, item in value.items():
                if not isinstance(key, str):
                    raise CodecError(f"a mapping key is {type(key).__name__}, not text")
                out += [key, self.encode(item, depth + 1)]
            return out
        if callable(value):
            return ["#f", self.register(value)]
        raise CodecError(f"a {kind.__name__} value cannot be part of a launch description")


# --------------------------------------------------------------------------- decoding


Check = Callable[[object], bool]


class Decoder:
    """Rebuilds IR from plain data, accepting only well-typed records.

    ``callback`` turns a callback number into the callable the parent will use.
    """

    def __init__(self, callback: Callable[[int], Callable[..., Any]],
                 span: Callable[[Span], Span] | None = None) -> None:
        self.callback = callback
        self.span = span  # may move a place the parent does not accept
        self._records: list[object | None] = []
        self._paths: dict[str, Path] = {}  # each file named once (its spans name it often)

    @property
    def received(self) -> int:
        """Return how many records this decoder has rebuilt (the next one's number)."""
        return len(self._records)

    def decode(self, data: object, depth: int = 0) -> object:
        if data is None or data.__class__ in _SCALARS:
            return data
        if data.__class__ is not list or not data or data[0].__class__ is not str:
            raise CodecError("malformed value")
        if depth > MAX_DEPTH:
            raise CodecError(f"the launch description nests deeper than {MAX_DEPTH} levels")
        tag, rest = data[0], data[1:]
        if tag == "#t":
            return tuple(self.decode(item, depth + 1) for item in rest)
        if tag == "#l":
            return [self.decode(item, depth + 1) for item in rest]
        if tag == "#d":
            if len(rest) % 2 or not all(isinstance(k, str) for k in rest[::2]):
                raise CodecError("malformed mapping")
            pairs = zip(rest[::2], rest[1::2], strict=True)
            return {k: self.decode(v, depth + 1) for k, v in pairs}
        if tag == "#p":
            text = _one(rest, str)
            path = self._paths.get(text)
            if path is None:
                path = self._paths[text] = Path(text)
            return path
        if tag == "#e":
            return _enum(rest)
        if tag == "#f":
            number = _one(rest, int)
            return self.callback(number)
        if tag == "#r":
            number = _one(rest, int)
            if not 0 <= number < len(self._records) or self._records[number] is None:
                raise CodecError("a reference to an unknown record")
            return self._records[number]
        return self._record(tag, rest, depth)

    def _record(self, name: str, values: list[object], depth: int) -> object:
        cls = RECORDS.get(name)
        if cls is None:
            raise CodecError(f"{name[:40]!r} is not a launch description record")
        fields = _fields(cls)
        if len(values) != len(fields):
            raise CodecError(f"{name} has {len(values)} fields, expected {len(fields)}")
        slot = len(self._records)
        if slot >= MAX_RECORDS:
            raise TooLarge(f"its launch description has more than {MAX_RECORDS:,} parts "
                           "(actions, nodes, parameters, substitutions), launchverify's "
                           "bound for one file")
        self._records.append(None)  # reserved: a reference to it now would be a cycle
        arguments = {}
        decode = self.decode
        depth += 1
        for (field, check), raw in zip(fields, values, strict=True):
            value = raw if raw.__class__ is str else decode(raw, depth)
            if not check(value):
                raise CodecError(f"{name}.{field} has an unexpected {type(value).__name__}")
            arguments[field] = value
        try:
            record = cls(**arguments)
        except (TypeError, ValueError) as error:
            raise CodecError(f"{name}: {error}") from None
        if self.span is not None and isinstance(record, Span):
            record = self.span(record)
        self._records[slot] = record
        return record


def _one(rest: list[object], kind: type) -> Any:
    if len(rest) != 1 or not isinstance(rest[0], kind) or isinstance(rest[0], bool):
        raise CodecError("malformed value")
    return rest[0]


def _enum(rest: list[object]) -> enum.Enum:
    if len(rest) != 2 or not isinstance(rest[0], str) or rest[0] not in ENUMS:
        raise CodecError("malformed enumeration value")
    try:
        return ENUMS[str(rest[0])](rest[1])
    except ValueError:
        raise CodecError("malformed enumeration value") from None


# --------------------------------------------------------------------------- type checks


_FIELDS: dict[type, list[tuple[str, Check]]] = {}


def _fields(cls: type) -> list[tuple[str, Check]]:
    """Return each field's name and a check of its annotation (computed once per class)."""
    known = _FIELDS.get(cls)
    if known is None:
        hints = typing.get_type_hints(cls)
        known = [(f.name, _check(hints[f.name]))
                 for f in dataclasses.fields(cls)]
        _FIELDS[cls] = known
    return known


def _check(hint: Any) -> Check:
    """Return a predicate for values of type ``hint`` (the IR's annotations only)."""
    if hint is Any or hint is object:
        return lambda value: True
    if hint is type(None):
        return lambda value: value is None
    if hint is float:
        return lambda value: isinstance(value, (int, float)) and not isinstance(value, bool)
    origin = typing.get_origin(hint)
    arguments = typing.get_args(hint)
    if origin in (typing.Union, types.UnionType):
        options = [_check(option) for option in arguments]
        return lambda value: any(option(value) for option in options)
    if origin is tuple:
        if len(arguments) == 2 and arguments[1] is Ellipsis:
            item = _check(arguments[0])
            return lambda value: isinstance(value, tuple) and all(item(v) for v in value)
        items = [_check(argument) for argument in arguments]
        return lambda value: (isinstance(value, tuple) and len(value) == len(items)
                              and all(check(v) for check, v in zip(items, value, strict=False)))
    if origin is dict:
        item = _check(arguments[1])
        return lambda value: isinstance(value, dict) and all(
            isinstance(k, str) and item(v) for k, v in value.items())
    if origin is not None and getattr(origin, "__name__", "") == "Callable":
        return callable
    if isinstance(hint, type):
        return lambda value: isinstance(value, hint)
    raise TypeError(f"no check for the annotation {hint!r}")


def iter_records(value: object) -> Iterator[object]:
    """Yield every record inside a decoded value (for checks over a whole description)."""
    stack = [value]
    seen: set[int] = set()
    while stack:
        item = stack.pop()
        if isinstance(item, (tuple, list)):
            stack.extend(item)
        elif isinstance(item, dict):
            stack.extend(item.values())
        elif type(item).__name__ in RECORDS and id(item) not in seen:
            seen.add(id(item))
            yield item
            stack.extend(getattr(item, f.name)
                         for f in dataclasses.fields(item))  # type: ignore[arg-type]
