"""Results as plain data, for the results cache on disk: nothing read back can run.

A stored result is made of launchverify's own records (findings, spans, verdicts, what
each root read). Pickle would rebuild whatever class a file names and run code while doing
so, and a pull request can commit the file a CI job's cache is read from. So a result is
stored as JSON, and reading it back rebuilds only dataclasses, named tuples and
enumerations defined in launchverify's own modules, each field checked against its
annotation. Anything else is ``Malformed``: for the cache, a miss.

Shape: ``[classes, paths, value]``. ``classes`` lists each record class once (module,
name, field names: a class whose fields changed since is malformed, not misread),
``paths`` each path once. In ``value``, text, numbers, booleans and ``None`` are
themselves; every other value is a list: ``[n, field...]`` a record of class ``n``,
``["e", n, value]`` an enumeration member, ``["p", n]`` the n-th path, ``["r", n]`` the
n-th record again (records are shared as they were: a span met twice is written once),
``["t", ...]``, ``["l", ...]``, ``["s", ...]``, ``["f", ...]`` a tuple, list, set or
frozenset, ``["d", key, value, ...]`` a mapping, ``["c", keys, column...]`` a mapping
whose values are tuples of plain scalars, one column per place (a file's stamps: read
back at the speed of the JSON decoder). Records are numbered in the order they start.
"""

from __future__ import annotations

import dataclasses
import enum
import importlib
import json
import operator
import sys
import types
import typing
from collections.abc import Callable, Hashable, Iterable, Mapping, Sequence
from pathlib import Path, PurePath
from typing import Any

MAX_DEPTH = 200  # nested values; launchverify's own results nest a few dozen deep
_OWN = "launchverify"
_SCALARS = frozenset({str, int, float, bool, type(None)})


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
        self.getters: list[Callable[[object], tuple[object, ...]]] = []  # fields, by class
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
            self.getters.append(_getter(names))
        return number

    def encode(self, value: Any, depth: int) -> object:
        kind = type(value)
        if kind in _SCALARS:
            return value
        if depth > MAX_DEPTH:
            raise Malformed(f"a value nested deeper than {MAX_DEPTH} levels")
        depth += 1
        tag = _TAGS.get(kind)
        if tag is not None:
            if tag == "d":
                return self.mapping(value, depth)
            if set(map(type, value)) <= _SCALARS:
                return [tag, *value]
            return [tag, *self.items(value, depth)]
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
            return [self.class_number(kind), *self.items(value, depth)]
        raise Malformed(f"a {kind.__qualname__} is not plain data")

    def items(self, values: Iterable[object], depth: int) -> list[object]:
        encode = self.encode
        return [item if type(item) in _SCALARS else encode(item, depth) for item in values]

    def mapping(self, value: dict[Any, Any], depth: int) -> list[object]:
        keys = list(value)
        if set(map(type, keys)) <= _SCALARS:
            rows = list(value.values())
            if rows and set(map(type, rows)) == {tuple}:
                widths = set(map(len, rows))
                columns = list(zip(*rows, strict=True)) if len(widths) == 1 else None
                if columns and all(set(map(type, column)) <= _SCALARS for column in columns):
                    return ["c", keys, *map(list, columns)]
            if set(map(type, rows)) <= _SCALARS:
                return ["d", *[x for pair in value.items() for x in pair]]
        out: list[object] = ["d"]
        encode = self.encode
        for key, item in value.items():
            out.append(key if type(key) in _SCALARS else encode(key, depth))
            out.append(item if type(item) in _SCALARS else encode(item, depth))
        return out

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
        return [number, *self.items(self.getters[number](value), depth)]


_TAGS: dict[type, str] = {tuple: "t", list: "l", dict: "d", frozenset: "f", set: "s"}


def _getter(names: tuple[str, ...]) -> Callable[[object], tuple[object, ...]]:
    """Return a function giving a record's fields as a tuple, in order."""
    if not names:
        return lambda value: ()
    if len(names) == 1:
        one = operator.attrgetter(names[0])
        return lambda value: (one(value),)
    return operator.attrgetter(*names)


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
    if not set(map(type, paths)) <= {str}:
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

    def decode(self, data: Any, depth: int) -> object:
        kind = type(data)
        if kind in _SCALARS:
            return data
        if kind is not list or not data:
            raise Malformed("a malformed value")
        if depth > MAX_DEPTH:
            raise Malformed(f"a value nested deeper than {MAX_DEPTH} levels")
        depth += 1
        tag = data[0]
        if type(tag) is int:
            return self.record(tag, data, depth)
        if tag == "r":
            return self.records[_index(data, len(self.records))]
        if tag == "p":
            return self.paths[_index(data, len(self.paths))]
        make = _CONTAINERS.get(tag)
        if make is not None:
            items = data[1:]
            if not set(map(type, items)) <= _SCALARS:
                decode = self.decode
                items = [item if type(item) in _SCALARS else decode(item, depth)
                         for item in items]
            if tag == "d":
                if len(items) % 2:
                    raise Malformed("a malformed mapping")
                return dict(zip(items[::2], items[1::2], strict=True))
            return make(items)
        if tag == "c":
            return _columns(data)
        if tag == "e" and len(data) == 3:
            cls = self.classes[_index(data[:2], len(self.classes))]
            if not issubclass(cls, enum.Enum):
                raise Malformed(f"{cls.__qualname__} is not an enumeration")
            return cls(self.decode(data[2], depth))
        raise Malformed("a malformed value")

    def record(self, number: int, data: list[Any], depth: int) -> object:
        if not 0 <= number < len(self.classes):
            raise Malformed("a record of no class")
        cls = self.classes[number]
        checks = _checks(cls)
        if len(data) != len(checks) + 1:
            raise Malformed(f"{cls.__qualname__} has {len(data) - 1} fields, "
                            f"expected {len(checks)}")
        decode = self.decode
        if _named_tuple(cls):  # immutable: nothing refers to it before it is whole
            items = [decode(raw, depth) for raw in data[1:]]
            _checked(cls, checks, items)
            return cls(*items)
        record: object = object.__new__(cls)  # as pickle does: no __init__ runs
        self.records.append(record)  # numbered when it starts, as when it was written
        values = [raw if type(raw) in _SCALARS else decode(raw, depth) for raw in data[1:]]
        _checked(cls, checks, values)
        set_field = object.__setattr__
        for (name, _), value in zip(checks, values, strict=True):
            set_field(record, name, value)
        return record


_CONTAINERS: dict[str, Callable[[list[Any]], object]] = {
    "t": tuple, "l": list, "f": frozenset, "s": set, "d": dict}


def _columns(data: list[Any]) -> dict[object, tuple[object, ...]]:
    """Return a mapping stored by columns (``["c", keys, column...]``)."""
    if len(data) < 3 or not all(type(part) is list for part in data[1:]):
        raise Malformed("a malformed mapping")
    keys = data[1]
    if not all(set(map(type, part)) <= _SCALARS for part in data[1:]):
        raise Malformed("a malformed mapping")
    return dict(zip(keys, zip(*data[2:], strict=True), strict=True))


def _index(data: list[Any], size: int) -> int:
    if len(data) != 2 or type(data[1]) is not int or not 0 <= data[1] < size:
        raise Malformed("a reference to nothing")
    number: int = data[1]
    return number


def _checked(cls: type, checks: list[tuple[str, Check]], values: list[object]) -> None:
    for (name, check), value in zip(checks, values, strict=True):
        if check is not _anything and not check(value):
            raise Malformed(f"{cls.__qualname__}.{name} holds a {type(value).__name__}")


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


def _scalar_types(hint: Any) -> frozenset[type] | None:
    """Return the exact types of the plain values ``hint`` allows (``None``: not only those)."""
    if hint is None or hint is type(None):
        return frozenset({type(None)})
    if hint is float:
        return frozenset({int, float})
    if hint in (str, int, bool):
        return frozenset({hint})
    if typing.get_origin(hint) in (typing.Union, types.UnionType):
        parts = [_scalar_types(option) for option in typing.get_args(hint)]
        if all(part is not None for part in parts):
            return frozenset().union(*parts)  # type: ignore[arg-type]
    return None


def _check(hint: Any) -> Check:
    """Return a predicate for values of type ``hint`` (unknown kinds accept anything)."""
    if hint in (Any, object, Hashable) or isinstance(hint, (str, typing.TypeVar)):
        return _anything
    scalars = _scalar_types(hint)
    if scalars is not None:
        return lambda value: type(value) in scalars
    origin = typing.get_origin(hint)
    arguments = typing.get_args(hint)
    if origin in (typing.Union, types.UnionType):
        options = [_check(option) for option in arguments]
        return lambda value: any(option(value) for option in options)
    if origin is typing.Literal:
        return lambda value: value in arguments
    if origin is tuple:
        if len(arguments) == 2 and arguments[1] is Ellipsis:
            return _all_of(tuple, arguments[0])
        items = [_check(argument) for argument in arguments]
        return lambda value: (type(value) is tuple and len(value) == len(items)
                              and all(check(v) for check, v in zip(items, value,
                                                                   strict=False)))
    if origin in (list, Sequence, Iterable) and arguments:
        return _all_of((list, tuple) if origin is not list else list, arguments[0])
    if origin in (set, frozenset) and arguments:
        return _all_of(origin, arguments[0])
    if origin in (dict, Mapping) and len(arguments) == 2:
        keys, values = _all_of(object, arguments[0]), _values_of(arguments[1])
        return lambda value: type(value) is dict and keys(value) and values(value)
    if origin is not None:
        return _kind(origin)
    if isinstance(hint, type):
        return _kind(hint)
    return _anything


def _kind(kind: type) -> Check:
    if kind is Path or kind is PurePath:
        return lambda value: isinstance(value, PurePath)
    return lambda value: isinstance(value, kind)


def _all_of(kinds: type | tuple[type, ...], hint: Any) -> Check:
    """Return a check of a collection of ``kinds`` whose items are all of type ``hint``."""
    scalars = _scalar_types(hint)
    if scalars is not None:  # the common case, at the speed of the interpreter's loops
        def plain(value: Any) -> bool:
            items: Iterable[Any] = value
            return isinstance(value, kinds) and set(map(type, items)) <= scalars

        return plain
    item = _check(hint)
    if item is _anything:
        return lambda value: isinstance(value, kinds)

    def check(value: Any) -> bool:
        items: Iterable[Any] = value
        return isinstance(value, kinds) and all(item(v) for v in items)

    return check


def _values_of(hint: Any) -> Check:
    """Return a check of a mapping's values: each of type ``hint``."""
    if typing.get_origin(hint) is tuple:
        arguments = typing.get_args(hint)
        columns = [_scalar_types(argument) for argument in arguments]
        if Ellipsis not in arguments and all(c is not None for c in columns):
            width = len(columns)

            def rows(value: dict[Any, Any]) -> bool:  # a file's stamps: one check per column
                found = list(value.values())
                return (set(map(type, found)) <= {tuple}
                        and set(map(len, found)) <= {width}
                        and all(set(map(type, column)) <= allowed  # type: ignore[operator]
                                for column, allowed in zip(zip(*found), columns,  # noqa: B905
                                                           strict=False)))

            return rows
    every = _all_of(object, hint)
    return lambda value: every(value.values())
