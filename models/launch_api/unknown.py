"""Values launchverify cannot see, as a launch file's code holds them.

A module nothing provides, a name of the launch API nobody modelled, an attribute of
either: each is an ``Opaque`` value. It stands for *any* value, so every operation on it
gives another one, and where Python insists on a plain answer (``bool``, ``len``, ``int``,
a comparison, a loop) the answer is an assumption, and it is counted (``WORLD``).

Two things keep an assumption from becoming an error claim:

- An ``Opaque`` is a ``str`` whose text is a placeholder (``⟨opaque:what⟩``), and the name
  of its class and its ``repr`` are placeholders too. So what Python's own code does with
  it (``'/'.join``, ``json.dumps``, ``os.path.join``, f-strings, a type error naming its
  type) keeps the mark, and a message that names it says it rests on an unknown.
- The evaluation can be run again with every assumption the other way
  (``placeholders.varied_world``, ``frontends/python/assumptions.py``): a failure that
  does not happen again rested on an assumption.

A launch object given to an unknown value (``hand_over``) is marked: the unknown code
holding it may add to it or run it.
"""

from __future__ import annotations

import dis
import sys
import types
from collections.abc import Generator, Iterator
from typing import Any

from launchverify.models.launch_api.placeholders import WORLD, assumed, placeholder
from launchverify.own_code import for_launchverify


def _by_own_code(depth: int) -> bool:
    """Return whether the frame ``depth`` levels up runs launchverify's own code.

    (Python's own modules, ``os.path`` among them, run for whoever called them: called by
    the launch file's code, they see an unknown value as that code does.)
    """
    return for_launchverify(depth + 1)


class Opaque(str):
    """A value from unmodelled code: any value, so everything done with it gives more of it.

    Only the launch file's code (and the libraries it calls) sees that. launchverify's
    own code sees the placeholder's text, as it sees any other string, so it turns the
    value into a symbolic unknown like every placeholder.
    """

    _description: str
    _span: Any = None

    def __new__(cls, description: str) -> Opaque:
        value = super().__new__(cls, placeholder("opaque", description))
        value._description = description
        return value

    def __call__(self, *args: Any, **kwargs: Any) -> Opaque:
        from launchverify.models.launch_api.base import caller_span

        hand_over(args, kwargs)
        result = Opaque(f"{self._description}()")
        result._span = caller_span()  # where the launch file called it (if it is an action)
        return result

    @property  # type: ignore[misc]
    def __class__(self) -> type:
        # ``isinstance(unknown, dict)`` asks for its type: an assumption neither world
        # can vary (launchverify's own checks are not assumptions)
        if not _by_own_code(1):
            assumed(None, None, self._description, fixed=True)
        return Opaque

    def __getattr__(self, name: str) -> Opaque:
        # launchverify's own code probing a value (getattr(x, '_span', None)) learns that
        # it has nothing; the launch file's code gets more of the unknown
        if name.startswith("__") or _by_own_code(1):
            raise AttributeError(name)
        if name == "keys" and not _loads_attribute(sys._getframe(1)):
            # ``d.update(unknown)``, ``dict(unknown)``, ``{**unknown}``: Python's own code
            # merges an unknown mapping, so the result holds keys no run can name (a
            # lookup that misses there is no fact, whichever way the keys are assumed)
            assumed(None, None, f"which keys {self._description} has", fixed=True)
        return Opaque(f"{self._description}.{name}")

    def __iter__(self) -> Iterator[Any]:
        if _by_own_code(1):
            return iter(())  # a collection of unknown items (a model checks for Opaque)
        # ``a, b, c = unknown`` asks for exactly three values: give three unknowns; a loop
        # over an unknown runs no round, or one when assumptions are varied.
        wanted = _unpacked_count(sys._getframe(1)) or assumed(0, 1, self._description)
        return iter([Opaque(f"{self._description}[{i}]") for i in range(wanted)])

    def __next__(self) -> Opaque:
        return Opaque(f"{self._description}[]")  # an unknown iterator's next item

    def __fspath__(self) -> str:
        return str(self)

    def __bytes__(self) -> bytes:
        return str(self).encode()

    def __divmod__(self, other: Any) -> tuple[Opaque, Opaque]:
        return self, self

    def __rdivmod__(self, other: Any) -> tuple[Opaque, Opaque]:
        return self, self

    def __trunc__(self) -> Opaque:
        return self

    def __floor__(self) -> Opaque:
        return self

    def __ceil__(self) -> Opaque:
        return self

    def __delattr__(self, name: str) -> None:
        if name in vars(self):
            super().__delattr__(name)

    def __await__(self) -> Iterator[Any]:
        return _awaited(self)

    async def __aenter__(self) -> Opaque:
        return self

    async def __aexit__(self, *exc: Any) -> None:
        return None

    def __aiter__(self) -> _UnknownRounds:
        return _UnknownRounds(self)

    def __format__(self, spec: str) -> str:
        return str(self)

    def __str__(self) -> str:
        return placeholder("opaque", self._description)

    def __repr__(self) -> str:
        return str(self)

    def __mro_entries__(self, bases: tuple[Any, ...]) -> tuple[type, ...]:
        # ``class D(vendor.Base)``: D's instances are unknown values themselves (strings
        # to Python, as an Opaque is), unless a known base lays them out otherwise
        # (``class D(vendor.Base, dict)``); two unknown bases are one
        if any(isinstance(base, Opaque) for base in bases[:bases.index(self)]):
            return ()
        known = tuple(base for base in bases if isinstance(base, type))
        try:
            type("probe", (UnknownInstance, *known), {})
        except TypeError:
            return (OpaqueBase,)
        return (UnknownInstance,)

    def __enter__(self) -> Opaque:
        return self

    def __exit__(self, *exc: Any) -> None:
        return None

    def __setitem__(self, key: Any, value: Any) -> None:
        if not _by_own_code(1):
            hand_over(value)  # the unknown stays unknown, and holds the value now
        return None

    def __setattr__(self, name: str, value: Any) -> None:
        if not name.startswith("_") and not _by_own_code(1):
            hand_over(value)  # ``loader.use_camera = LaunchConfiguration(...)``
        super().__setattr__(name, value)

    def __delitem__(self, key: Any) -> None:
        return None

    def __getitem__(self, key: Any) -> Any:
        if _by_own_code(1):
            return str.__getitem__(self, key)
        return Opaque(f"{self._description}[]")

    def __int__(self) -> int:
        return assumed(0, 1, self._description)

    def __float__(self) -> float:
        return assumed(0.0, 1.0, self._description)

    def __index__(self) -> int:
        return assumed(0, 1, self._description)

    def __eq__(self, other: object) -> bool:
        if _by_own_code(1):
            return str.__eq__(self, other)
        return other is self or assumed(False, True, self._description)

    def __ne__(self, other: object) -> bool:
        if _by_own_code(1):
            return str.__ne__(self, other)
        return other is not self and not assumed(False, True, self._description)

    def __hash__(self) -> int:
        return str.__hash__(self)

    def __reduce__(self) -> Any:
        return (Opaque, (self._description,))

    def __copy__(self) -> Opaque:
        return self

    def __deepcopy__(self, memo: Any) -> Opaque:
        return self


def _awaited(unknown: Opaque) -> Generator[Any, None, Opaque]:
    """Awaiting an unknown gives more of it, at once (a generator that never yields)."""
    if False:
        yield None
    return Opaque(f"await {unknown._description}")


class _UnknownRounds:
    """``async for`` over an unknown: no round, or one when assumptions are varied."""

    def __init__(self, unknown: Opaque) -> None:
        self._unknown = unknown
        self._left: int | None = None

    def __aiter__(self) -> _UnknownRounds:
        return self

    async def __anext__(self) -> Opaque:
        if self._left is None:
            self._left = assumed(0, 1, self._unknown._description)
        if self._left <= 0:
            raise StopAsyncIteration
        self._left -= 1
        return Opaque(f"{self._unknown._description}[]")


def _answering(name: str, answer: str) -> Any:
    """Return an operator for ``name``: more unknown, or an assumption (``answer``).

    launchverify's own code gets ``str``'s (or the answer a string gives).
    """
    own = getattr(str, name, None)

    def method(self: Opaque, *args: Any, **kwargs: Any) -> Any:
        if _by_own_code(1):
            if own is not None:
                return own(self, *args, **kwargs)
            return len(self) > 0 if name == "__bool__" else NotImplemented
        if answer == "bool":
            return assumed(False, True, self._description)
        if answer == "int":
            return assumed(0, 1, self._description)
        return self

    method.__name__ = name
    return method


def _attribute(name: str) -> property:
    """Return an attribute named like a str method.

    For the launch file's code it is more of the unknown (``config.count``,
    ``config.title`` are as likely values as methods; called, it gives more still, and a
    plain answer is an assumption); for launchverify's own code, ``str``'s method.
    """
    own = getattr(str, name)

    def get(self: Opaque) -> Any:
        if _by_own_code(1):
            return own.__get__(self)
        return Opaque(f"{self._description}.{name}")

    return property(get)


# What an unknown value is asked must not read the placeholder's text: it answers with
# more of the unknown, or, where Python wants a plain answer, an assumption.
_OPERATORS = {
    **{name: "bool" for name in ("__bool__", "__contains__", "__lt__", "__le__", "__gt__",
                                 "__ge__")},
    "__len__": "int",
    **{name: "self" for name in (
        "__add__", "__radd__", "__sub__", "__rsub__", "__mul__", "__rmul__", "__truediv__",
        "__rtruediv__", "__floordiv__", "__rfloordiv__", "__mod__", "__rmod__", "__neg__",
        "__pow__", "__rpow__", "__and__", "__rand__", "__xor__", "__rxor__", "__or__",
        "__ror__", "__round__", "__abs__", "__pos__", "__invert__", "__lshift__",
        "__rlshift__", "__rshift__", "__rrshift__", "__matmul__", "__rmatmul__")},
}
for _name, _answer in _OPERATORS.items():
    setattr(Opaque, _name, _answering(_name, _answer))
for _name in dir(str):
    if not _name.startswith("_") and _name != "maketrans":
        setattr(Opaque, _name, _attribute(_name))

# Named so that a message naming an unknown value's type ("expected str instance,
# ⟨opaque:value⟩ found") says that it rests on an unknown.
Opaque.__name__ = Opaque.__qualname__ = placeholder("opaque", "value")


class _Converting(type):
    """The type of ``int`` and ``float`` as a launch file's code sees them."""

    def __call__(cls, *args: Any, **kwargs: Any) -> Any:
        if args and isinstance(args[0], Opaque):
            return args[0]  # a number only the robot knows: still unknown
        return cls.__bases__[0](*args, **kwargs)

    def __instancecheck__(cls, value: Any) -> bool:
        return isinstance(value, cls.__bases__[0])

    def __subclasscheck__(cls, subclass: type) -> bool:
        return issubclass(subclass, cls.__bases__[0])


class _Int(int, metaclass=_Converting):
    """``int``: an unknown value converted stays unknown (not the 0 Python would want)."""


class _Float(float, metaclass=_Converting):
    """``float``: an unknown value converted stays unknown."""


class _Complex(complex, metaclass=_Converting):
    """``complex``: Python parses a string's text, which for an unknown is no number."""


class _Bytearray(bytearray, metaclass=_Converting):
    """``bytearray``: Python wants an encoding for a string; an unknown's bytes are unknown."""


def _ord(value: Any) -> Any:
    """``ord``: an unknown character's code is unknown (its text is no one character)."""
    return value if isinstance(value, Opaque) else ord(value)


def _callable(value: Any) -> bool:
    """``callable``: whether an unknown can be called is an assumption (yes, then no)."""
    if isinstance(value, Opaque):
        return assumed(True, False, f"whether {value._description} is callable")
    return callable(value)


def _hasattr(value: Any, name: str) -> bool:
    """``hasattr``: whether an unknown has an attribute is an assumption (yes, then no)."""
    if isinstance(value, Opaque):
        return assumed(True, False, f"whether {value._description} has {name}")
    return hasattr(value, name)


class _TypeQuestion(type):
    """The type of ``type`` as a launch file's code sees it: an unknown's type is asked."""

    def __call__(cls, *args: Any, **kwargs: Any) -> Any:
        if cls is not _Type:  # a metaclass of the launch file's, deriving from type
            return super().__call__(*args, **kwargs)
        if len(args) == 1 and isinstance(args[0], Opaque):
            assumed(None, None, args[0]._description, fixed=True)
        return type(*args, **kwargs)

    def __instancecheck__(cls, value: Any) -> bool:
        return isinstance(value, type)

    def __subclasscheck__(cls, subclass: type) -> bool:
        return issubclass(subclass, type)


class _Type(type, metaclass=_TypeQuestion):
    """``type``: asking an unknown value its type is an assumption nothing varies."""


def _unknown_class(value: Any) -> bool:
    """Return whether a value stands for a class launchverify cannot see."""
    return isinstance(value, Opaque) or (
        isinstance(value, type) and issubclass(value, UnknownInstance))


def _described(value: Any) -> str:
    return value._description if isinstance(value, Opaque) else getattr(
        value, "__name__", type(value).__name__)


def _class_test(real: Any, kind: str) -> Any:
    """``isinstance``/``issubclass``: against a class nobody can see, an assumption.

    Python refuses a string as the class. The known classes of a tuple answer first.
    """
    def test(value: Any, classes: Any) -> bool:
        if isinstance(value, Opaque):  # an unknown's type: an assumption nothing varies
            assumed(None, None, value._description, fixed=True)
            if kind == "a subclass of":
                return assumed(False, True, f"whether {value._description} is a class")
        try:
            return bool(real(value, classes))
        except TypeError:
            pending = list(classes) if type(classes) is tuple else [classes]
            unknown = [c for c in pending if _unknown_class(c)]
            if not unknown:
                raise
            known = tuple(c for c in pending if not _unknown_class(c))
            if known and real(value, known):
                return True
            return assumed(False, True, f"whether a value is {kind} {_described(unknown[0])}")

    test.__name__ = real.__name__
    return test


class UnknownRaised(Exception):
    """What the launch file raises when what it raises is a value launchverify cannot see.

    The raise happens on the robot whatever the value is (an exception of the vendor's,
    or Python's ``TypeError`` if it is none), so reached on facts it is a fact. It is
    named after the unknown, which ``except`` clauses recognise.
    """

    origin: str = ""


def _raised(value: Any) -> Any:
    """What ``raise value`` raises (the launch file's ``raise`` statements call it)."""
    if isinstance(value, BaseException) or (
            isinstance(value, type) and issubclass(value, BaseException)) or value is None:
        return value
    if isinstance(value, UnknownInstance):
        origin, text = type(value).__name__, "an exception class built on code launchverify " \
            "cannot see"
    elif _unknown_class(value):
        origin, text = _described(value).removesuffix("()"), "an exception of code " \
            "launchverify cannot see"
    else:
        return value  # Python's own TypeError follows: a fact
    kind = type(origin, (UnknownRaised,), {"origin": origin})
    return kind(text)


class _CatchesNothing(Exception):
    """An ``except`` clause's class that the propagating exception is not."""


def _caught(value: Any) -> Any:
    """What ``except value`` compares with (the launch file's clauses call it).

    Evaluated only while an exception propagates (as Python evaluates the clause): a
    class nobody can see catches the same unknown's raise, and anything else by an
    assumption (no, then yes).
    """
    if type(value) is tuple:
        return tuple(_caught(item) for item in value)
    if not _unknown_class(value):
        return value
    current = sys.exc_info()[1]
    origin = _described(value).removesuffix("()")
    if current is None:
        return _CatchesNothing
    if isinstance(current, UnknownRaised) and current.origin == origin:
        return type(current)
    if assumed(False, True, f"whether except {origin} catches {type(current).__name__}"):
        return type(current)
    return _CatchesNothing


def _subject(value: Any) -> Any:
    """A ``match`` statement's subject: patterns ask an unknown for its type (an assumption)."""
    if isinstance(value, Opaque):
        assumed(None, None, value._description, fixed=True)
    return value


_Int.__name__ = _Int.__qualname__ = "int"
_Float.__name__ = _Float.__qualname__ = "float"
_Complex.__name__ = _Complex.__qualname__ = "complex"
_Bytearray.__name__ = _Bytearray.__qualname__ = "bytearray"
_Type.__name__ = _Type.__qualname__ = "type"
# for the launch file's builtins: conversions and tests that Python would refuse on an
# unknown, and what the compiled launch file calls for ``raise``, ``except``, ``match``
# (frontends/python/rewrite.py)
LAUNCH_BUILTINS = {
    "int": _Int, "float": _Float, "complex": _Complex, "bytearray": _Bytearray, "ord": _ord,
    "callable": _callable, "hasattr": _hasattr, "type": _Type,
    "isinstance": _class_test(isinstance, "an instance of"),
    "issubclass": _class_test(issubclass, "a subclass of"),
    "__launchverify_raised__": _raised, "__launchverify_caught__": _caught,
    "__launchverify_subject__": _subject,
}


def launch_builtins() -> dict[str, Any]:
    """Return the builtins a launch file's code (and the workspace's Python) runs with."""
    import builtins

    return {**vars(builtins), **LAUNCH_BUILTINS}


class OpaqueModule(types.ModuleType):
    """A module we cannot see into: every attribute is an opaque value."""

    def __init__(self, name: str) -> None:
        super().__init__(name)
        self.__path__: list[str] = []

    def __getattr__(self, name: str) -> Any:
        if name.startswith("__"):
            raise AttributeError(name)
        return Opaque(f"{self.__name__}.{name}")


class OpaqueBase:
    """What a class deriving from an unknown one and a laid-out known one derives from.

    ``class D(vendor.Base, dict)``: its instances are dicts, and answer as dicts do; what
    the vendor's base adds is unknown (any attribute the class lacks).
    """

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        hand_over(args, kwargs)

    def __getattr__(self, name: str) -> Any:
        if name.startswith("__") or _by_own_code(1):
            raise AttributeError(name)
        return Opaque(f"{type(self).__name__}.{name}")


class UnknownInstance(Opaque):
    """What a class deriving from an unknown one derives from: its instances are unknown.

    The launch file's own methods and attributes are the class's; everything else is
    what an ``Opaque`` gives. Each instance is a value of its own.
    """

    _made = 0

    def __new__(cls, *args: Any, **kwargs: Any) -> UnknownInstance:
        UnknownInstance._made += 1
        value = super().__new__(cls, f"a {cls.__name__} object #{UnknownInstance._made}")
        return value  # type: ignore[return-value]

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        hand_over(args, kwargs)

    @property  # type: ignore[misc]
    def __class__(self) -> type:
        return type(self)

    __hash__ = Opaque.__hash__


def hand_over(*values: Any) -> None:
    """Mark the launch objects given to code launchverify cannot see (``handed``).

    That code may add actions to a launch description it holds (a vendor's argument
    parser declares the arguments), or run an action it was given (a helper that starts
    the spawners once a controller is up): what launchverify sees of them is not all.
    """
    from launchverify.models.launch_api import runtime
    from launchverify.models.launch_api.base import Modelled

    pending, seen = list(values), 0
    while pending and seen < 1000:
        value = pending.pop()
        seen += 1
        if isinstance(value, Modelled):
            object.__setattr__(value, "handed", True)
            name = vars(value).get("_variable_name")  # a LaunchConfiguration: it may read it
            if isinstance(name, str) and runtime.current is not None:
                runtime.current.handed_names.add(name)
        elif isinstance(value, (list, tuple, set)):
            pending.extend(value)
        elif isinstance(value, dict):
            pending.extend(value.values())


def handed(value: Any) -> bool:
    """Return whether a launch object was given to code launchverify cannot see."""
    return bool(vars(value).get("handed")) if hasattr(value, "__dict__") else False


_ATTRIBUTE_LOADS = frozenset(dis.opmap[name] for name in ("LOAD_ATTR", "LOAD_METHOD")
                             if name in dis.opmap)
_UNPACK_SEQUENCE = dis.opmap["UNPACK_SEQUENCE"]
_UNPACK_EX = dis.opmap["UNPACK_EX"]
_EXTENDED_ARG = dis.opmap["EXTENDED_ARG"]


def _loads_attribute(frame: types.FrameType | None) -> bool:
    """Return whether the instruction running in ``frame`` reads an attribute.

    (Python code asking for it, not a C function such as ``dict.update`` that it called.)
    """
    if frame is None:
        return False
    code, at = frame.f_code.co_code, frame.f_lasti
    return 0 <= at < len(code) and code[at] in _ATTRIBUTE_LOADS


def _unpacked_count(frame: types.FrameType | None) -> int:
    """Return how many values the instruction running in ``frame`` unpacks (0: none)."""
    if frame is None:
        return 0
    code = frame.f_code.co_code
    at = frame.f_lasti
    if not 0 <= at < len(code) - 1:
        return 0
    operation, argument = code[at], code[at + 1]
    back = at - 2
    while back >= 0 and code[back] == _EXTENDED_ARG:  # a count over 255 (or a, *b, c)
        argument |= code[back + 1] << (8 * ((at - back) // 2))
        back -= 2
    if operation == _UNPACK_SEQUENCE:
        return argument
    if operation == _UNPACK_EX:  # a, *rest, b: the fixed ones, and the rest empty
        return (argument & 0xFF) + (argument >> 8)
    return 0


__all__ = ["WORLD", "Opaque", "OpaqueBase", "OpaqueModule", "UnknownInstance"]
