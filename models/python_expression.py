"""A side-effect-free model of ``PythonExpression`` / ``$(eval ...)``.

launch calls ``eval`` on the substituted text with the ``math`` names in scope. We never do:
the expression is parsed with ``ast`` and interpreted over a small, safe subset (literals,
arithmetic, comparisons, boolean logic, conditional expressions, ``math``, common builtins
and string methods). Errors Python would raise are reported as such (launch would fail);
constructs outside the subset are "not modelled", never guessed. Every operation that could
build a large value or burn CPU is bounded *before* it runs.
"""

from __future__ import annotations

import ast
import builtins
import functools
import math
import operator
import re
from collections.abc import Callable
from typing import Any

MAX_SOURCE = 10_000
MAX_SIZE = 100_000  # characters / items a value may hold
MAX_NODES = 500
MAX_INT_BITS = 10_000
MAX_COMBINATORIAL = 1_000


class ExpressionError(Exception):
    """Python itself would raise: the launch fails at run time with this message."""


class Unsupported(Exception):
    """A construct outside the modelled subset; the value stays unknown."""


_BIN: dict[type, Callable[[Any, Any], Any]] = {
    ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
    ast.Div: operator.truediv, ast.FloorDiv: operator.floordiv, ast.Mod: operator.mod,
    ast.Pow: operator.pow,
}
_CMP: dict[type, Callable[[Any, Any], Any]] = {
    ast.Eq: operator.eq, ast.NotEq: operator.ne, ast.Lt: operator.lt, ast.LtE: operator.le,
    ast.Gt: operator.gt, ast.GtE: operator.ge, ast.Is: operator.is_, ast.IsNot: operator.is_not,
    ast.In: lambda a, b: a in b, ast.NotIn: lambda a, b: a not in b,
}
_BUILTINS: dict[str, Any] = {
    "str": str, "int": int, "float": float, "bool": bool, "len": len, "abs": abs,
    "min": min, "max": max, "round": round, "sorted": sorted, "list": list, "tuple": tuple,
    "any": any, "all": all, "set": set, "True": True, "False": False, "None": None,
}
_STR_METHODS = frozenset({
    "lower", "upper", "strip", "lstrip", "rstrip", "split", "startswith", "endswith",
    "replace", "join", "capitalize", "title", "count", "find", "isdigit", "isalpha",
    "zfill", "ljust", "rjust", "center",
})
_PERCENT_FIELD = re.compile(r"%[-+ #0]*(\*|\d+)?(?:\.(\*|\d+))?")
_SET_METHODS = frozenset({
    "intersection", "union", "difference", "symmetric_difference", "issubset", "issuperset",
    "isdisjoint",
})
_MATH = {name: getattr(math, name) for name in dir(math) if not name.startswith("_")}
_COMBINATORIAL = {math.factorial, math.comb, math.perm}


def evaluate_expression(text: str, modules: list[str] | None = None) -> str:
    """Evaluate ``text`` as launch's ``PythonExpression`` would (see ``_evaluate``).

    The result depends on the text and modules only: the reasoner asks the same
    expressions again and again under different arguments, so answers are kept.

    Examples:
        >>> evaluate_expression("'a' + 'b' == 'ab'")
        'True'
    """
    result, error = _remembered(text, tuple(modules) if modules is not None else None)
    if error is not None:
        raise error.with_traceback(None)  # one kept instance, raised afresh
    assert result is not None
    return result


@functools.lru_cache(maxsize=4096)
def _remembered(text: str, modules: tuple[str, ...] | None
                ) -> tuple[str | None, Exception | None]:
    try:
        return _evaluate(text, list(modules) if modules is not None else None), None
    except (ExpressionError, Unsupported) as error:
        return None, error


def _evaluate(text: str, modules: list[str] | None = None) -> str:
    """Evaluate ``text`` as launch's ``PythonExpression`` would and return ``str(result)``.

    Raises:
        ExpressionError: when Python would raise (launch fails).
        Unsupported: when the expression uses something outside the safe subset.

    Examples:
        >>> evaluate_expression("'a' + 'b' == 'ab'")
        'True'
        >>> evaluate_expression("pi > 3")
        'True'
    """
    names: dict[str, Any] = dict(_BUILTINS)
    for module in modules if modules is not None else ["math"]:
        if module == "math":
            names.update(_MATH)
            names["math"] = _MathModule()
        else:
            raise Unsupported(f"module {module!r} in $(eval) is not modelled")
    if len(text) > MAX_SOURCE:
        raise Unsupported("expression too long")
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except SyntaxError as error:
        raise ExpressionError(f"SyntaxError: {error.msg} in {text!r}") from None
    except (MemoryError, RecursionError, ValueError):
        raise Unsupported("expression nested too deeply") from None
    if sum(1 for _ in ast.walk(tree)) > MAX_NODES:
        raise Unsupported("expression too large")
    try:
        result = _Interpreter(names).visit(tree.body)
        _check_size(result)
        return str(result)
    except (Unsupported, ExpressionError):
        raise
    except (MemoryError, RecursionError):
        raise Unsupported("expression too expensive to evaluate") from None
    except Exception as error:
        raise ExpressionError(f"{type(error).__name__}: {error}") from None


def _size(value: Any, limit: int = MAX_SIZE) -> int:
    """Return how big a value is (characters, items, digits), stopping past ``limit``."""
    if isinstance(value, str):
        return len(value)
    if isinstance(value, bool) or value is None:
        return 1
    if isinstance(value, int):
        return value.bit_length() // 3 + 1
    if isinstance(value, (list, tuple, set, frozenset, dict)):
        total = len(value)
        items = value.items() if isinstance(value, dict) else value
        for item in items:
            total += _size(item, limit)
            if total > limit:
                break
        return total
    return 1


def _check_size(value: Any) -> None:
    if _size(value) > MAX_SIZE:
        raise Unsupported("result too large")


class _MathModule:
    """Stands in for the ``math`` module: its public names only."""

    def __getattr__(self, name: str) -> Any:
        if name in _MATH:
            return _MATH[name]
        raise AttributeError(f"module 'math' has no attribute {name!r}")


class _Interpreter:
    def __init__(self, names: dict[str, Any]) -> None:
        self.names = names

    def visit(self, node: ast.expr) -> Any:
        method = getattr(self, "visit_" + type(node).__name__, None)
        if method is None:
            raise Unsupported(f"{type(node).__name__} in $(eval) is not modelled")
        return method(node)

    def visit_Constant(self, node: ast.Constant) -> Any:
        _check_size(node.value)
        return node.value

    def visit_Name(self, node: ast.Name) -> Any:
        if node.id in self.names:
            return self.names[node.id]
        if hasattr(builtins, node.id):
            raise Unsupported(f"builtin {node.id!r} in $(eval) is not modelled")
        raise ExpressionError(f"NameError: name {node.id!r} is not defined")

    def visit_BoolOp(self, node: ast.BoolOp) -> Any:
        result: Any = None
        for value in node.values:
            result = self.visit(value)
            if isinstance(node.op, ast.And) and not result:
                return result
            if isinstance(node.op, ast.Or) and result:
                return result
        return result

    def visit_UnaryOp(self, node: ast.UnaryOp) -> Any:
        value = self.visit(node.operand)
        if isinstance(node.op, ast.Not):
            return not value
        if isinstance(node.op, ast.USub):
            return -value
        if isinstance(node.op, ast.UAdd):
            return +value
        raise Unsupported("bitwise operators are not modelled")

    def visit_BinOp(self, node: ast.BinOp) -> Any:
        op = _BIN.get(type(node.op))
        if op is None:
            raise Unsupported("bitwise operators are not modelled")
        left, right = self.visit(node.left), self.visit(node.right)
        if isinstance(node.op, ast.Pow):
            _check_power(left, right)
        if isinstance(node.op, ast.Mult):
            _check_repeat(left, right)
        if isinstance(node.op, ast.Mod) and isinstance(left, str):
            _check_percent_format(left)
        result = op(left, right)
        _check_size(result)
        return result

    def visit_Compare(self, node: ast.Compare) -> Any:
        left = self.visit(node.left)
        for op_node, comparator in zip(node.ops, node.comparators, strict=True):
            right = self.visit(comparator)
            if not _CMP[type(op_node)](left, right):
                return False
            left = right
        return True

    def visit_IfExp(self, node: ast.IfExp) -> Any:
        return self.visit(node.body) if self.visit(node.test) else self.visit(node.orelse)

    def visit_Tuple(self, node: ast.Tuple) -> Any:
        return tuple(self.visit(e) for e in node.elts)

    def visit_List(self, node: ast.List) -> Any:
        return [self.visit(e) for e in node.elts]

    def visit_Set(self, node: ast.Set) -> Any:
        return {self.visit(e) for e in node.elts}

    def visit_Dict(self, node: ast.Dict) -> Any:
        if any(k is None for k in node.keys):
            raise Unsupported("dict unpacking is not modelled")
        return {self.visit(k): self.visit(v)  # type: ignore[arg-type]
                for k, v in zip(node.keys, node.values, strict=True)}

    def visit_Subscript(self, node: ast.Subscript) -> Any:
        value = self.visit(node.value)
        if isinstance(node.slice, ast.Slice):
            parts = [None if p is None else self.visit(p)
                     for p in (node.slice.lower, node.slice.upper, node.slice.step)]
            return value[slice(*parts)]
        return value[self.visit(node.slice)]

    def visit_Attribute(self, node: ast.Attribute) -> Any:
        if node.attr.startswith("_"):
            raise Unsupported(f"attribute .{node.attr} in $(eval) is not modelled")
        value = self.visit(node.value)
        if isinstance(value, _MathModule):
            return getattr(value, node.attr)
        if isinstance(value, str) and node.attr in _STR_METHODS:
            return getattr(value, node.attr)
        if isinstance(value, (set, frozenset)) and node.attr in _SET_METHODS:
            return getattr(value, node.attr)
        raise Unsupported(f"attribute .{node.attr} in $(eval) is not modelled")

    def visit_Call(self, node: ast.Call) -> Any:
        if node.keywords and not all(k.arg for k in node.keywords):
            raise Unsupported("** arguments are not modelled")
        function = self.visit(node.func)
        owner = getattr(function, "__self__", None)
        allowed = callable(function) and (
            any(function is f for f in _BUILTINS.values())
            or any(function is f for f in _MATH.values())
            or isinstance(owner, (str, set, frozenset))
        )
        if not allowed:
            raise Unsupported("this call in $(eval) is not modelled")
        args = [self.visit(a) for a in node.args]
        kwargs = {k.arg: self.visit(k.value) for k in node.keywords if k.arg}
        if function in _COMBINATORIAL and any(
            isinstance(a, int) and abs(a) > MAX_COMBINATORIAL for a in args
        ):
            raise Unsupported(f"{function.__name__} of large numbers is not modelled")
        if isinstance(owner, str):
            _check_string_method(owner, function.__name__, args)
        result = function(*args, **kwargs)
        _check_size(result)
        return result


def _check_power(base: Any, exponent: Any) -> None:
    if (isinstance(base, int) and isinstance(exponent, int) and exponent > 0
            and max(base.bit_length(), 1) * exponent > MAX_INT_BITS):
        raise Unsupported("a power this large is not modelled")


def _check_repeat(left: Any, right: Any) -> None:
    for sequence, count in ((left, right), (right, left)):
        if (isinstance(count, int) and isinstance(sequence, (str, list, tuple))
                and count > 0 and _size(sequence) * count > MAX_SIZE):
            raise Unsupported("result too large")


def _check_percent_format(template: str) -> None:
    for match in _PERCENT_FIELD.finditer(template):
        for number in match.groups():
            if number == "*" or (number is not None and int(number) > 1000):
                raise Unsupported("a %-format field this wide is not modelled")


def _check_string_method(text: str, name: str, args: list[Any]) -> None:
    padded = name in ("zfill", "ljust", "rjust", "center")
    if padded and args and isinstance(args[0], int) and args[0] > MAX_SIZE:
        raise Unsupported("result too large")
    if name == "join" and args:
        items = list(args[0])
        total = sum(_size(i) for i in items[:MAX_SIZE]) + len(text) * len(items)
        if len(items) > MAX_SIZE or total > MAX_SIZE:
            raise Unsupported("result too large")
    if name == "replace" and len(args) >= 2 and isinstance(args[0], str) and isinstance(
        args[1], str
    ):
        hits = len(text) + 1 if not args[0] else text.count(args[0])
        if len(text) + hits * max(len(args[1]) - len(args[0]), 0) > MAX_SIZE:
            raise Unsupported("result too large")
