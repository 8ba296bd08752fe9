"""Results as plain data, for the results cache on disk: nothing read back can run.

A stored result is made of launchverify's own records (findings, spans, verdicts, what
each root read). Pickle would rebuild whatever class a file names and run code while doing
so, and a pull request can commit the file a CI job's cache is read from. So a result is
stored as JSON, and reading it back rebuilds only dataclasses and enumerations defined in
launchverify's own modules, each field checked against its annotation. Anything else is
``Malformed``: for the cache, a miss.

Shape: ``[classes, paths, value]``. ``classes`` lists each record class once (module,
name, field names: a class whose fields changed since is malformed, not misread),
``paths`` each path once. In ``value``, text, numbers, booleans and ``None`` are
themselves; every other value is a list: ``[n, field...]`` a record of class ``n``,
``["e", n, value]`` an enumeration member, ``["p", n]`` the n-th path, ``["r", n]`` the
n-th record again (records are shared as they were: a span met twice is written once),
``["t", ...]``, ``["l", ...]``, ``["s", ...]``, ``["f", ...]`` a tuple, list, set or
frozenset, ``["d", key, value, ...]`` a mapping. Records are numbered in the order they
start.
"""

from __future__ import annotations

import dataclasses
import enum
import importlib
import json
import sys
import types
import typing
from collections.abc import Callable, Hashable, Iterable, Mapping, Sequence
from pathlib import Path, PurePath
from typing import Any

MAX_DEPTH = 200  # nested values; launchverify's own results nest a few dozen deep
_OWN = "launchverify"


class Malformed(Exception):
    """Stored data that is not a result launchverify would store."""


# --------------------------------------------------------------------------- writing


def dumps(value: object) -> bytes:
    """Return ``value`` as plain data (``Malformed`` for a value no result holds)."""
    # (ASCII: a lone surrogate, from a file name's undecodable bytes, becomes an escape)
    return json.dumps(_Writer().document(value), separators=(",", ":"),
                      check_circular=False).encode("ascii")


class _Writer:
    def __init__(self) -> None:
        self.classes: dict[type, int] = {}
        self.table: list[list[object]] = []
        self.names: list[tuple[str, ...]] = []  # each class's fields, by number
        self.paths: dict[str, int] = {}
        self.records: dict[int, int] = {}  # id -> number, while the value is alive
        self.values: dict[object, int] = {}  # frozen records by value (equal spans)
        self.count = 0

    def document(self, value: object) -> list[object]:
        encoded = self.encode(value, 0)
        return [self.table, list(self.paths), encoded]

    def class_number(self, cls: type) -> int:
        number = self.classes.get(cls)
        if number is None:
            if not _own(cls):
                raise Malformed(f"a {cls.__qualname__} is not one of launchverify's records")
            names = _field_names(cls)
            number = self.classes[cls] = len(self.table)
            self.table.append([cls.__module__, cls.__qualname__, list(names)])
            self.names.append(names)
        return number

    def encode(self, value: Any, depth: int) -> object:
        kind = type(value)
        if kind is str or kind is int or kind is bool or kind is float or value is None:
            return value
        if depth > MAX_DEPTH:
            raise Malformed(f"a value nested deeper than {MAX_DEPTH} levels")
        depth += 1
        if kind is tuple:
            return ["t", *[self.encode(item, depth) for item in value]]
        if kind is list:
            return ["l", *[self.encode(item, depth) for item in value]]
        if kind is dict:
            out: list[object] = ["d"]
            for key, item in value.items():
                out.append(self.encode(key, depth))
                out.append(self.encode(item, depth))
            return out
        if kind is frozenset or kind is set:
            return ["f" if kind is frozenset else "s",
                    *[self.encode(item, depth) for item in value]]
        if isinstance(value, PurePath):
            text = str(value)
            number = self.paths.get(text)
            if number is None:
                number = self.paths[text] = len(self.paths)
            return ["p", number]
        if isinstance(value, enum.Enum):
            return ["e", self.class_number(kind), self.encode(value.value, depth)]
        if dataclasses.is_dataclass(value):
            return self.record(value, kind, depth)
        if isinstance(value, tuple) and hasattr(kind, "_fields"):  # a named tuple
            return [self.class_number(kind), *[self.encode(item, depth) for item in value]]
        raise Malformed(f"a {kind.__qualname__} is not plain data")

    def record(self, value: object, kind: type, depth: int) -> object:
        known = self.records.get(id(value))
        frozen: bool = kind.__dataclass_params__.frozen  # type: ignore[attr-defined]
        if known is None and frozen:
            try:
                known = self.values.get(value)
            except TypeError:  # a frozen record holding a list: not hashable
                frozen = False
        if known is not None:
            return ["r", known]
        number = self.class_number(kind)
        self.records[id(value)] = self.count
        if frozen:
            self.values[value] = self.count
        self.count += 1
        return [number, *[self.encode(getattr(value, name), depth)
                          for name in self.names[number]]]


def _own(cls: type) -> bool:
    """Return whether a class is one of launchverify's records or enumerations."""
    module = cls.__module__
    if not (module == _OWN or module.startswith(_OWN + ".")) or "<" in cls.__qualname__:
        return False
    return issubclass(cls, enum.Enum) or dataclasses.is_dataclass(cls) or _named_tuple(cls)


def _named_tuple(cls: type) -> bool:
    return issubclass(cls, tuple) and isinstance(getattr(cls, "_fields", None), tuple)


def _field_names(cls: type) -> tuple[str, ...]:
    """Return a record class's fields, in order (none for an enumeration)."""
    if dataclasses.is_dataclass(cls):
        return tuple(f.name for f in dataclasses.fields(cls))
    if _named_tuple(cls):
        return cls._fields  # type: ignore[attr-defined, no-any-return]
    return ()


# --------------------------------------------------------------------------- reading


def loads(data: bytes) -> object:
    """Return the value ``data`` holds (``Malformed`` for anything else)."""
    try:
        document = json.loads(data)
    except (ValueError, RecursionError) as error:  # (UnicodeDecodeError is a ValueError)
        raise Malformed(f"not JSON: {type(error).__name__}") from None
    if not (isinstance(document, list) and len(document) == 3
            and isinstance(document[0], list) and isinstance(document[1], list)):
        raise Malformed("not a stored result")
    classes = [_class(entry) for entry in document[0]]
    paths = document[1]
    if not all(isinstance(path, str) for path in paths):
        raise Malformed("a path that is not text")
    try:
        return _Reader(classes, [Path(path) for path in paths]).decode(document[2], 0)
    except RecursionError:
        raise Malformed("nested too deeply") from None
    except (TypeError, ValueError, AttributeError, IndexError) as error:
        raise Malformed(f"malformed value: {type(error).__name__}") from None


_CLASSES: dict[tuple[str, str, tuple[str, ...]], type] = {}


def _class(entry: object) -> type:
    """Return the record class an entry of the class table names, if it may be rebuilt."""
    if not (isinstance(entry, list) and len(entry) == 3 and isinstance(entry[0], str)
            and isinstance(entry[1], str) and isinstance(entry[2], list)
            and all(isinstance(name, str) for name in entry[2])):
        raise Malformed("a malformed class table")
    module, name, names = entry[0], entry[1], tuple(entry[2])
    known = _CLASSES.get((module, name, names))
    if known is not None:
        return known
    if not (module == _OWN or module.startswith(_OWN + ".")) or not all(
            part.isidentifier() for part in (*module.split("."), *name.split("."))):
        raise Malformed(f"{module[:60]}.{name[:60]} is not launchverify's")
    try:
        found: object = sys.modules.get(module) or importlib.import_module(module)
        for part in name.split("."):
            found = getattr(found, part)
    except (ImportError, AttributeError):
        raise Malformed(f"no record {module}.{name} here") from None
    if not (isinstance(found, type) and found.__module__ == module and _own(found)):
        raise Malformed(f"{module}.{name} is not a record")
    if _field_names(found) != names:
        raise Malformed(f"{module}.{name}'s fields changed")
    _CLASSES[(module, name, names)] = found
    return found


class _Reader:
    def __init__(self, classes: list[type], paths: list[Path]) -> None:
        self.classes = classes
        self.paths = paths
        self.records: list[object] = []

    def decode(self, data: object, depth: int) -> object:
        kind = type(data)
        if kind is str or kind is int or kind is bool or kind is float or data is None:
            return data
        if kind is not list or not data:
            raise Malformed("a malformed value")
        if depth > MAX_DEPTH:
            raise Malformed(f"a value nested deeper than {MAX_DEPTH} levels")
        depth += 1
        tag = data[0]  # type: ignore[index]
        rest = data[1:]  # type: ignore[index]
        if type(tag) is int:
            return self.record(tag, rest, depth)
        if tag == "r":
            return self.records[_index(rest, len(self.records))]
        if tag == "p":
            return self.paths[_index(rest, len(self.paths))]
        make = _CONTAINERS.get(tag)
        if make is not None:
            # text and numbers need no decoding (most containers hold only those)
            if all(item.__class__ in _SCALARS for item in rest):
                items = rest
            else:
                decode = self.decode
                items = [decode(item, depth) for item in rest]
            if tag == "d":
                if len(items) % 2:
                    raise Malformed("a malformed mapping")
                return dict(zip(items[::2], items[1::2], strict=True))
            return make(items)
        if tag == "e" and len(rest) == 2:
            cls = self.classes[_index(rest[:1], len(self.classes))]
            if not issubclass(cls, enum.Enum):
                raise Malformed(f"{cls.__qualname__} is not an enumeration")
            return cls(self.decode(rest[1], depth))
        raise Malformed("a malformed value")

    def record(self, number: int, values: list[object], depth: int) -> object:
        if not 0 <= number < len(self.classes):
            raise Malformed("a record of no class")
        cls = self.classes[number]
        checks = _checks(cls)
        if len(values) != len(checks):
            raise Malformed(f"{cls.__qualname__} has {len(values)} fields, "
                            f"expected {len(checks)}")
        if _named_tuple(cls):  # immutable: nothing refers to it before it is whole
            items = [self.decode(raw, depth) for raw in values]
            for (name, check), value in zip(checks, items, strict=True):
                if not check(value):
                    raise Malformed(f"{cls.__qualname__}.{name} holds a "
                                    f"{type(value).__name__}")
            return cls(*items)
        record: object = object.__new__(cls)  # as pickle does: no __init__ runs
        self.records.append(record)  # numbered when it starts, as when it was written
        set_field = object.__setattr__
        decode = self.decode
        for (name, check), raw in zip(checks, values, strict=True):
            value = decode(raw, depth)
            if not check(value):
                raise Malformed(f"{cls.__qualname__}.{name} holds a {type(value).__name__}")
            set_field(record, name, value)
        return record


_SCALARS = frozenset({str, int, float, bool, type(None)})
_CONTAINERS: dict[str, Callable[[list[Any]], object]] = {
    "t": tuple, "l": list, "f": frozenset, "s": set, "d": dict}


def _index(rest: list[Any], size: int) -> int:
    if len(rest) != 1 or type(rest[0]) is not int or not 0 <= rest[0] < size:
        raise Malformed("a reference to nothing")
    number: int = rest[0]
    return number


# --------------------------------------------------------------------------- type checks


Check = Callable[[Any], bool]
_CHECKS: dict[type, list[tuple[str, Check]]] = {}


def _checks(cls: type) -> list[tuple[str, Check]]:
    """Return each field's name and a check of its annotation (worked out once per class).

    An annotation that cannot be resolved here (a name imported only for type checkers)
    accepts any value: the check is a second line behind the stored data's seal.
    """
    known = _CHECKS.get(cls)
    if known is None:
        if issubclass(cls, enum.Enum):
            raise Malformed(f"{cls.__qualname__} is an enumeration, not a record")
        try:
            hints = typing.get_type_hints(cls)
        except Exception:
            hints = _field_hints(cls)
        known = [(name, _check(hints.get(name, Any))) for name in _field_names(cls)]
        _CHECKS[cls] = known
    return known


def _field_hints(cls: type) -> dict[str, object]:
    """Return the annotations of ``cls`` that resolve one by one (others are left out)."""
    out: dict[str, object] = {}
    for klass in reversed(cls.__mro__):
        namespace = vars(sys.modules.get(klass.__module__, types.ModuleType("_")))
        for name, hint in vars(klass).get("__annotations__", {}).items():
            try:
                out[name] = eval(hint, dict(namespace)) if isinstance(hint, str) else hint
            except Exception:
                out.pop(name, None)
    return out


def _anything(value: object) -> bool:
    return True


def _check(hint: Any) -> Check:
    """Return a predicate for values of type ``hint`` (unknown kinds accept anything)."""
    if hint in (Any, object, Hashable) or isinstance(hint, (str, typing.TypeVar)):
        return _anything
    if hint is type(None) or hint is None:
        return lambda value: value is None
    if hint is float:
        return lambda value: type(value) in (int, float)
    if hint is int:
        return lambda value: type(value) is int
    origin = typing.get_origin(hint)
    arguments = typing.get_args(hint)
    if origin in (typing.Union, types.UnionType):
        options = [_check(option) for option in arguments]
        return lambda value: any(option(value) for option in options)
    if origin is typing.Literal:
        return lambda value: value in arguments
    if origin is tuple:
        if len(arguments) == 2 and arguments[1] is Ellipsis:
            return _all_of(tuple, _check(arguments[0]))
        items = [_check(argument) for argument in arguments]
        return lambda value: (type(value) is tuple and len(value) == len(items)
                              and all(check(v) for check, v in zip(items, value,
                                                                   strict=False)))
    if origin in (list, Sequence, Iterable) and arguments:
        return _all_of((list, tuple) if origin is not list else list, _check(arguments[0]))
    if origin in (set, frozenset) and arguments:
        return _all_of(origin, _check(arguments[0]))
    if origin in (dict, Mapping) and len(arguments) == 2:
        key, item = _check(arguments[0]), _check(arguments[1])
        return lambda value: type(value) is dict and all(
            key(k) and item(v) for k, v in value.items())
    if origin is not None:
        return _kind(origin)
    if isinstance(hint, type):
        return _kind(hint)
    return _anything


def _kind(kind: type) -> Check:
    if kind is Path or kind is PurePath:
        return lambda value: isinstance(value, PurePath)
    if not isinstance(kind, type) or kind.__module__ in ("typing", "collections.abc"):
        return _anything if not isinstance(kind, type) else (
            lambda value: isinstance(value, kind))
    return lambda value: isinstance(value, kind)


def _all_of(kinds: type | tuple[type, ...], item: Check) -> Check:
    def check(value: Any) -> bool:
        items: Iterable[Any] = value
        return isinstance(value, kinds) and all(item(v) for v in items)

    return check
