"""A side-effect-free model of ``PythonExpression`` / ``$(eval ...)``.

launch calls ``eval`` on the substituted text with the ``math`` names in scope. We never do:
the expression is parsed with ``ast`` and interpreted over a small, safe subset (literals,
arithmetic, comparisons, boolean logic, conditional expressions, ``math``, common builtins
and string methods). Errors Python would raise are reported as such (launch would fail);
constructs outside the subset are "not modelled", never guessed.
"""

from __future__ import annotations

import ast
import math
import operator
from collections.abc import Callable
from typing import Any

MAX_TEXT = 100_000
MAX_NODES = 500


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
    "any": any, "all": all, "True": True, "False": False, "None": None,
}
_STR_METHODS = frozenset({
    "lower", "upper", "strip", "lstrip", "rstrip", "split", "startswith", "endswith",
    "replace", "join", "capitalize", "title", "count", "find", "isdigit", "isalpha",
    "zfill",
})
_MATH = {name: getattr(math, name) for name in dir(math) if not name.startswith("_")}


def evaluate_expression(text: str, modules: list[str] | None = None) -> str:
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
    try:
        tree = ast.parse(text.strip(), mode="eval")
    except SyntaxError as error:
        raise ExpressionError(f"SyntaxError: {error.msg} in {text!r}") from None
    if sum(1 for _ in ast.walk(tree)) > MAX_NODES:
        raise Unsupported("expression too large")
    try:
        return str(_Interpreter(names).run(tree.body))
    except (Unsupported, ExpressionError):
        raise
    except RecursionError:
        raise Unsupported("expression nested too deeply") from None
    except Exception as error:
        raise ExpressionError(f"{type(error).__name__}: {error}") from None


class _MathModule:
    """Stands in for the ``math`` module: attribute access only."""

    def __getattr__(self, name: str) -> Any:
        if name in _MATH:
            return _MATH[name]
        raise AttributeError(f"module 'math' has no attribute {name!r}")


class _Interpreter:
    def __init__(self, names: dict[str, Any]) -> None:
        self.names = names

    def run(self, node: ast.expr) -> Any:
        result = self.visit(node)
        if isinstance(result, str) and len(result) > MAX_TEXT:
            raise Unsupported("result too large")
        return result

    def visit(self, node: ast.expr) -> Any:
        method = getattr(self, "visit_" + type(node).__name__, None)
        if method is None:
            raise Unsupported(f"{type(node).__name__} in $(eval) is not modelled")
        return method(node)

    def visit_Constant(self, node: ast.Constant) -> Any:
        return node.value

    def visit_Name(self, node: ast.Name) -> Any:
        if node.id in self.names:
            return self.names[node.id]
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
        if isinstance(node.op, ast.Pow) and isinstance(right, (int, float)) and abs(right) > 64:
            raise Unsupported("large powers are not modelled")
        if isinstance(node.op, ast.Mult) and isinstance(left, (str, list)) and isinstance(
            right, int
        ) and right * len(left) > MAX_TEXT:
            raise Unsupported("result too large")
        return op(left, right)

    def visit_Compare(self, node: ast.Compare) -> Any:
        left = self.visit(node.left)
        for op_node, comparator in zip(node.ops, node.comparators, strict=False):
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
        return {self.visit(k): self.visit(v) for k, v in zip(node.keys, node.values, strict=False)}  # type: ignore[arg-type]

    def visit_Subscript(self, node: ast.Subscript) -> Any:
        value = self.visit(node.value)
        if isinstance(node.slice, ast.Slice):
            parts = [None if p is None else self.visit(p)
                     for p in (node.slice.lower, node.slice.upper, node.slice.step)]
            return value[slice(*parts)]
        return value[self.visit(node.slice)]

    def visit_Attribute(self, node: ast.Attribute) -> Any:
        value = self.visit(node.value)
        if isinstance(value, _MathModule):
            return getattr(value, node.attr)
        if isinstance(value, str) and node.attr in _STR_METHODS:
            return getattr(value, node.attr)
        raise Unsupported(f"attribute .{node.attr} in $(eval) is not modelled")

    def visit_Call(self, node: ast.Call) -> Any:
        if node.keywords and not all(k.arg for k in node.keywords):
            raise Unsupported("** arguments are not modelled")
        function = self.visit(node.func)
        allowed = function in _BUILTINS.values() or function in _MATH.values() or (
            getattr(function, "__self__", None).__class__ is str
        )
        if not callable(function) or not allowed:
            raise Unsupported("this call in $(eval) is not modelled")
        args = [self.visit(a) for a in node.args]
        kwargs = {k.arg: self.visit(k.value) for k in node.keywords if k.arg}
        return function(*args, **kwargs)
