"""The unknown's data model: what every operation Python offers does to an unknown value.

An unknown value (``unknown.Opaque``: a vendor's module that is not installed, an
attribute nobody modelled, what a command would print on the robot) stands for *any*
value. Whatever the launch file's code does with it must give another unknown, or an
answer launchverify records as an assumption, so that the evaluation is run again with
the other answer (``placeholders.varied_world``) and nothing resting on it becomes an
error. ``TABLE`` gives every operation its rule; ``operations()`` lists every operation
Python offers (found by introspection, so a new Python's are found too), and
``tests/test_data_model.py`` runs each rule's probe and fails on an operation without one.

What implements each rule: ``Opaque``'s methods (``unknown.py``), the launch file's
builtins (``unknown.LAUNCH_BUILTINS``), the compiled file's ``raise``/``except``/``match``
(``frontends/python/rewrite.py``), the machine's functions (``frontends/python/machine.py``)
and the libraries the session wraps (``frontends/python/__init__.py``).
"""

from __future__ import annotations

import builtins
import collections.abc
import contextlib
import enum
import types
from dataclasses import dataclass


class Answer(enum.Enum):
    """What an operation on an unknown value gives."""

    UNKNOWN = "another unknown value"
    ASSUMED = "a plain answer recorded as an assumption: the varied world gives the other"
    FIXED = ("a plain answer about the value's type, recorded as an assumption the varied "
             "world cannot vary: nothing that follows is a fact")
    MARKED = ("Python's own answer for the placeholder's text, which carries the mark of the "
              "unknown (a message or a text that names it says it rests on an unknown)")
    SAME = "an answer that is the same whatever the value is"
    RAISES = ("the operation raises whatever the value is (a raise is a raise); reached on "
              "facts, that is a fact, named after the unknown")
    PLUMBING = ("not asked of a value the launch file holds: a hook of the classes, "
                "descriptors and objects Python's own machinery calls; Python's own")


@dataclass(frozen=True)
class Rule:
    """One operation's rule, with a probe the test runs on an unknown ``u``.

    ``probe`` is Python code that leaves the operation's result in ``r``; where it is a
    plain expression, ``r = `` is prepended. ``drive(coroutine)`` runs a coroutine to its
    end (an event loop would open sockets, which the sandbox refuses).
    """

    operation: str
    answer: Answer
    probe: str = ""


def _rules(answer: Answer, probes: dict[str, str]) -> tuple[Rule, ...]:
    return tuple(Rule(operation, answer, probe) for operation, probe in probes.items())


_OPERATORS = {"add": "+", "sub": "-", "mul": "*", "truediv": "/", "floordiv": "//",
              "mod": "%", "pow": "**", "lshift": "<<", "rshift": ">>", "and": "&",
              "xor": "^", "or": "|", "matmul": "@"}
_COMPARISONS = {"lt": "<", "le": "<=", "gt": ">", "ge": ">="}

TABLE: tuple[Rule, ...] = (
    # ------------------------------------------------------------ arithmetic: more unknown
    *_rules(Answer.UNKNOWN, {f"__{name}__": f"u {symbol} 2" for name, symbol in
                             _OPERATORS.items()}),
    *_rules(Answer.UNKNOWN, {f"__r{name}__": f"2 {symbol} u" for name, symbol in
                             _OPERATORS.items()}),
    *_rules(Answer.UNKNOWN, {f"__i{name}__": f"v = u\nv {symbol}= 2\nr = v" for name, symbol
                             in _OPERATORS.items()}),
    *_rules(Answer.UNKNOWN, {
        "__neg__": "-u", "__pos__": "+u", "__invert__": "~u", "__abs__": "abs(u)",
        "__round__": "round(u)", "__trunc__": "math.trunc(u)", "__floor__": "math.floor(u)",
        "__ceil__": "math.ceil(u)", "__divmod__": "divmod(u, 2)[0]",
        "__rdivmod__": "divmod(2, u)[1]", "abs": "abs(u)", "round": "round(u, 1)",
        "divmod": "divmod(u, 3)[0]", "pow": "pow(u, 2)",
        "__getitem__": "u['key']", "slicing": "u[1:3]", "__getattr__": "u.anything",
        "__getattribute__": "u.count", "getattr": "getattr(u, 'anything')",
        "__call__": "u(1, key=2)", "__next__": "next(u)", "next": "next(u)",
        "__enter__": "with u as w:\n    r = w", "with": "with u as w:\n    r = w",
        "__await__": "async def f():\n    return await u\nr = drive(f())",
        "await": "async def f():\n    return await u\nr = drive(f())",
        "__aenter__": ("async def f():\n    async with u as w:\n        return w\n"
                       "r = drive(f())"),
        "__aexit__": ("async def f():\n    async with u as w:\n        return w\n"
                      "r = drive(f())"),
        "async with": ("async def f():\n    async with u as w:\n        return w\n"
                       "r = drive(f())"),
        "int": "int(u)", "float": "float(u)", "complex": "complex(u)", "__complex__":
        "complex(u)", "bytearray": "bytearray(u)", "ord": "ord(u)",
        "str methods": "u.split('_')[1].strip().upper()",
        "unpacking": "a, b, c = u\nr = c", "starred unpacking": "a, *rest, b = u\nr = b",
        "json.loads": "json.loads(u)",
        "json.loads of the environment": "json.loads(os.environ.get('CFG', '{}'))",
        "yaml.safe_load": "yaml.safe_load(u)['robot']",
        "os.environ": "os.environ.get(u)", "os.getenv": "os.getenv(u)",
        "re": "import re\nr = int(re.findall(r'R(\\d+)', u)[0][0])",
    }),
    # --------------------------------------------- plain answers: assumptions, then varied
    *_rules(Answer.ASSUMED, {f"__{name}__": f"u {symbol} 2" for name, symbol in
                             _COMPARISONS.items()}),
    *_rules(Answer.ASSUMED, {
        "__eq__": "u == 'a'", "__ne__": "u != 'a'", "__bool__": "bool(u)", "bool": "bool(u)",
        "not": "not u", "if": "r = 1 if u else 2",
        "while": "r = 0\nwhile u and r < 3:\n    r += 1",
        "and/or": "u and 1", "assert": "assert u\nr = 1",
        "__contains__": "'a' in u", "in": "'a' in u", "__len__": "len(u)", "len": "len(u)",
        "__index__": "[1, 2][u]", "__int__": "import builtins\nr = builtins.int(u)",
        "__float__": "math.sqrt(u)", "str.join": "'/'.join(u)", "__iter__": "list(u)",
        "iter": "list(iter(u))",
        "for": "r = [x for x in u]", "comprehension": "{x: 1 for x in u}",
        "__reversed__": "list(reversed(u))", "reversed": "list(reversed(u))",
        "sorted": "sorted(u)", "sum": "sum(u)", "max": "max(u)", "min": "min(u)",
        "any": "any(u)", "all": "all(x != 'a' for x in u)", "enumerate": "list(enumerate(u))",
        "zip": "list(zip(u, 'ab'))", "map": "list(map(str, u))", "filter":
        "list(filter(None, u))", "list": "list(u)", "tuple": "tuple(u)", "set": "set(u)",
        "frozenset": "frozenset(u)", "dict": "dict(u)", "range": "list(range(u))",
        "chr": "chr(u)", "hex": "hex(u)", "oct": "oct(u)", "bin": "bin(u)",
        "slice": "[1, 2, 3][slice(u)]", "__aiter__": (
            "async def f():\n    return [x async for x in u]\n"
            "r = drive(f())"),
        "__anext__": (
            "async def f():\n    return [x async for x in u]\n"
            "r = drive(f())"),
        "async for": (
            "async def f():\n    return [x async for x in u]\n"
            "r = drive(f())"),
        "aiter": ("async def f():\n    return [x async for x in aiter(u)]\n"
                  "r = drive(f())"),
        "anext": ("async def f():\n    return await anext(aiter(u), 'end')\n"
                  "r = drive(f())"),
        "isinstance": "isinstance(3, u)", "issubclass": "issubclass(int, u)",
        "__instancecheck__": "isinstance(3, (u, str))",
        "__subclasscheck__": "issubclass(int, (u, str))",
        "callable": "callable(u)", "hasattr": "hasattr(u, 'anything')",
        "except": "try:\n    raise KeyError('k')\nexcept u:\n    r = 1",
        "os.path.exists": "os.path.exists(u)", "os.path.isfile": "os.path.isfile(u)",
        "os.path.isdir": "os.path.isdir(u)", "os.path.lexists": "os.path.lexists(u)",
        "file on the robot": "os.path.exists('/etc/vendor/robot.yaml')",
        "math": "math.log(u)",
    }),
    # ------------------------------------------------------------- questions of its type
    *_rules(Answer.FIXED, {
        "type": "type(u) is dict", "__class__": "u.__class__ is dict",
        "isinstance of a known class": "isinstance(u, dict)",
        "mapping merge": "d = {'a': 1}\nd.update(u)\nr = d.get('b')",
        "match": "match u:\n    case [a, b]:\n        r = 1\n    case _:\n        r = 2",
    }),
    # ----------------------------------------------- Python's answer, carrying the mark
    *_rules(Answer.MARKED, {
        "__str__": "str(u)", "str": "str(u)", "__repr__": "repr(u)", "repr": "repr(u)",
        "ascii": "ascii(u)", "__format__": "format(u, '>9')", "format": "format(u)",
        "f-string": "f'{u}/x'", "%-formatting": "'%s/x' % u", "__fspath__": "os.fspath(u)",
        "os.fspath": "os.fspath(u)",
        "os.path": "os.path.join(u, 'x')", "pathlib": "str(pathlib.Path(u) / 'x')",
        "json.dumps": "json.dumps({'a': u})", "__bytes__": "bytes(u)", "bytes": "bytes(u)",
        "yaml.dump": "yaml.dump({'a': u})",
        "yaml.safe_dump": "yaml.safe_dump({'a': u})", "shlex": "' '.join(shlex.split(u))",
        "string concatenation": "'a' + u", "__hash__": "{u: 1}",
        "print": "print(u, end='')\nr = u", "eval": "eval(repr(u))",
        "__setitem__": "u['a'] = 1\nr = u", "__delitem__": "del u['a']\nr = u",
        "__setattr__": "u.a = 1\nr = u", "setattr": "setattr(u, 'a', 1)\nr = u",
        "__delattr__": "del u.a\nr = u", "delattr": "delattr(u, 'a')\nr = u",
        "__copy__": "import copy\nr = copy.copy(u)", "__deepcopy__":
        "import copy\nr = copy.deepcopy(u)", "__reduce__": "import copy\nr = copy.deepcopy(u)",
        "__reduce_ex__": "import copy\nr = copy.deepcopy(u)", "__exit__":
        "with u:\n    pass\nr = u", "del": "v = u\ndel v\nr = u",
        "memoryview": "bytes(memoryview(bytes(u)))",
    }),
    # ------------------------------------------------- the same answer for any value
    *_rules(Answer.SAME, {
        "id": "id(u) > 0", "hash": "{u: 1}[u]", "dir": "dir(u) is not None",
        "vars": "vars(u) is not None",
        "__dir__": "dir(u) is not None", "__sizeof__": "u.__sizeof__() > 0",
        "globals": "globals() is not None", "locals": "locals() is not None",
        "object": "object()", "super": "super", "type()": "type('T', (), {})",
        "property": "property(lambda self: u)", "classmethod": "classmethod(len)",
        "staticmethod": "staticmethod(len)", "compile": "compile('u', 'x', 'eval')",
        "exec": "exec('v = u')\nr = u", "class base": "class C(u):\n    pass\nr = C(1).x",
        "class base of an exception": (
            "class E(u):\n    pass\ntry:\n    raise E('x')\nexcept E:\n    r = u"),
        "isinstance of a class built on it": "class C(u):\n    pass\nr = isinstance(C(), C)",
    }),
    # --------------------------------------------------------------- a raise is a raise
    *_rules(Answer.RAISES, {
        "raise": "raise u", "raise a call": "raise u('bad')",
        "raise from": "raise RuntimeError('x') from u",
    }),
    # ------------------------------------------ refused or replaced: nothing happens here
    *_rules(Answer.SAME, {
        "open": "open(u).read()", "input": "'input'", "breakpoint": "'breakpoint'",
        "exit": "'exit'", "quit": "'quit'", "help": "'help'", "copyright": "'copyright'",
        "credits": "'credits'", "license": "'license'",
    }),
    # ----------------------------------------------------- Python's machinery, not a value
    *(Rule(name, Answer.PLUMBING) for name in (
        "__init__", "__new__", "__init_subclass__", "__subclasshook__", "__class_getitem__",
        "__set_name__", "__prepare__", "__get__", "__set__", "__delete__", "__del__",
        "__getnewargs__", "__getnewargs_ex__", "__getstate__", "__setstate__",
        "__subclasses__", "__mro_entries__", "__length_hint__", "__missing__",
        "__getformat__", "__alloc__", "__buffer__", "__release_buffer__", "mro",
        "__isabstractmethod__", "__new_member__", "__setformat__",
    )),
    *_rules(Answer.UNKNOWN, {name: f"u.{name}(1)" for name in (
        "send", "throw", "close", "asend", "athrow", "aclose")}),
)


# Python's statements and forms that act on a value without a special method of their
# own; operations of libraries a launch file's code hands values to.
STATEMENTS = (
    "if", "while", "not", "and/or", "assert", "for", "comprehension", "unpacking",
    "starred unpacking", "with", "async with", "async for", "await", "raise", "raise a call",
    "raise from", "except", "match", "class base", "class base of an exception", "del",
    "f-string", "%-formatting", "slicing", "string concatenation", "str methods",
)
LIBRARIES = (
    "str.join", "json.dumps", "json.loads", "json.loads of the environment", "yaml.dump",
    "yaml.safe_dump", "yaml.safe_load",
    "os.path", "os.fspath", "pathlib", "shlex", "os.environ", "os.getenv", "math", "re",
    "mapping merge",
    "file on the robot", "isinstance of a known class", "isinstance of a class built on it",
    *(f"os.path.{name}" for name in ("exists", "isfile", "isdir", "lexists")),
)
# the built-in types whose special methods Python calls on values
_TYPES: tuple[type, ...] = (
    object, type, str, bytes, bytearray, int, float, complex, bool, list, tuple, dict, set,
    frozenset, range, slice, memoryview, BaseException, types.FunctionType,
    types.GeneratorType, types.CoroutineType, types.AsyncGeneratorType, types.ModuleType,
    property, classmethod, staticmethod, contextlib.AbstractContextManager,
    contextlib.AbstractAsyncContextManager, enum.Enum,
    *(kind for kind in vars(collections.abc).values() if isinstance(kind, type)),
)


def operations() -> frozenset[str]:
    """Return every operation Python offers on a value (what ``TABLE`` must give a rule).

    The special methods of the built-in types, the built-in functions, the statements and
    the library functions above. Found by introspection: a new Python's appear here.
    """
    special = {name for kind in _TYPES for name in dir(kind)
               if name.startswith("__") and name.endswith("__")
               and callable(getattr(kind, name, None))
               and not isinstance(getattr(kind, name), type)}  # a class's __base__
    functions = {name for name, value in vars(builtins).items()
                 if callable(value) and not name.startswith("_")
                 and not (isinstance(value, type) and issubclass(value, BaseException))}
    generators = {name for kind in (types.GeneratorType, types.AsyncGeneratorType)
                  for name in dir(kind)
                  if not name.startswith("_") and callable(getattr(kind, name))}
    return frozenset(special | functions | generators | set(STATEMENTS) | set(LIBRARIES))


def rules() -> dict[str, Rule]:
    """Return the table by operation (the first rule of each)."""
    found: dict[str, Rule] = {}
    for rule in TABLE:
        found.setdefault(rule.operation, rule)
    return found
