"""``$(eval ...)`` / ``PythonExpression`` over symbolic inputs, as z3 terms.

The expression text still holds unknown parts (``'$(var mode)' == 'sim'``). Each part is
replaced by a placeholder name, the text is parsed with ``ast``, and the subset real launch
files use is translated: string, bool and int literals; ``==``/``!=``/``<``.. on ints and
strings; ``in``/``not in`` a literal list or a string; ``and``/``or``/``not``; ``x if c
else y``; ``.lower()``/``.upper()`` compared with literals. A part outside quotes is
Python source (``not $(var use_sim)`` with ``True``/``False``/digits). Anything else, or a
value Python would reject, makes the whole expression an unknown value.
"""

from __future__ import annotations

import ast
import operator
import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import z3

from launchverify.ir import subst as s
from launchverify.smt import regexes as rx

if TYPE_CHECKING:
    from launchverify.smt.encode import Encoder

_HOLE = re.compile(r"_lv_hole(\d+)_")
_LITERAL_TRUE, _LITERAL_FALSE = ("True", "1"), ("False", "0")


class Unsupported(Exception):
    """The expression leaves the translated subset."""


@dataclass(frozen=True)
class Value:
    """A translated Python value: ``kind`` is str, bool, int, source or case.

    ``source`` is an input written outside quotes (Python evaluates its text); ``case``
    is ``x.lower()``/``x.upper()`` (``term`` is ``x``; ``upper`` says which). ``ok`` is
    false where Python would fail or the value leaves what we model.
    """

    kind: str
    term: z3.ExprRef
    ok: z3.BoolRef
    upper: bool = False


def encode_expression(sub: s.PythonExpr, encoder: Encoder) -> z3.SeqRef | None:
    """Return ``str(eval(expression))`` as a z3 string, or ``None`` outside the subset."""
    if sub.modules is not None and not (isinstance(sub.modules, s.Text)
                                        and sub.modules.text.strip() in ("", "math")):
        return None
    parts = sub.expression.parts if isinstance(sub.expression, s.Concat) else (sub.expression,)
    holes: list[s.Sub] = []
    source = ""
    for part in parts:
        if isinstance(part, s.Text):
            source += part.text
        else:
            source += f"_lv_hole{len(holes)}_"
            holes.append(part)
    try:
        tree = ast.parse(source.strip(), mode="eval")
        value = _Translator(encoder, holes).visit(tree.body)
        text = _to_str(value)
    except (SyntaxError, ValueError, RecursionError, Unsupported):
        return None
    return z3.If(z3.And(value.ok, text.ok), text.term, encoder.unknown(sub))


def _to_str(value: Value) -> Value:
    if value.kind == "str":
        return value
    if value.kind == "bool":
        return Value("str", z3.If(value.term, z3.StringVal("True"), z3.StringVal("False")),
                     value.ok)
    if value.kind == "int":
        return Value("str", z3.IntToStr(value.term), z3.And(value.ok, value.term >= 0))
    raise Unsupported(value.kind)


def _to_bool(value: Value) -> Value:
    if value.kind == "bool":
        return value
    if value.kind == "str":
        return Value("bool", z3.Length(value.term) > 0, value.ok)
    if value.kind == "int":
        return Value("bool", value.term != 0, value.ok)
    if value.kind == "source":
        term = value.term
        return Value("bool", rx.one_of(term, _LITERAL_TRUE),
                     z3.And(value.ok, rx.one_of(term, _LITERAL_TRUE + _LITERAL_FALSE)))
    raise Unsupported(value.kind)


def _to_int(value: Value) -> Value:
    if value.kind == "int":
        return value
    if value.kind == "bool":
        return Value("int", z3.If(value.term, 1, 0), value.ok)
    if value.kind == "source":  # digits, or True/False (bools are ints in Python)
        term = value.term
        number = z3.If(term == z3.StringVal("True"), 1,
                       z3.If(term == z3.StringVal("False"), 0, z3.StrToInt(term)))
        valid = z3.Or(z3.InRe(term, rx.digits()), rx.one_of(term, ("True", "False")))
        return Value("int", number, z3.And(value.ok, valid))
    raise Unsupported(value.kind)


class _Translator:
    """Translates one parsed expression."""

    def __init__(self, encoder: Encoder, holes: list[s.Sub]) -> None:
        self.encoder = encoder
        self.holes = holes

    def visit(self, node: ast.expr) -> Value:
        method = getattr(self, "visit_" + type(node).__name__, None)
        if method is None:
            raise Unsupported(type(node).__name__)
        result: Value = method(node)
        return result

    def visit_Constant(self, node: ast.Constant) -> Value:
        true = z3.BoolVal(True)
        if isinstance(node.value, bool):
            return Value("bool", z3.BoolVal(node.value), true)
        if isinstance(node.value, int):
            return Value("int", z3.IntVal(node.value), true)
        if isinstance(node.value, str):
            return Value("str", self.text(node.value), true)
        raise Unsupported(type(node.value).__name__)

    def text(self, value: str) -> z3.SeqRef:
        """Return a string literal's term, with the inputs quoted inside it."""
        pieces: list[z3.SeqRef] = []
        position = 0
        for match in _HOLE.finditer(value):
            if match.start() > position:
                pieces.append(z3.StringVal(value[position:match.start()]))
            pieces.append(self.encoder.string(self.holes[int(match.group(1))]))
            position = match.end()
        if position < len(value) or not pieces:
            pieces.append(z3.StringVal(value[position:]))
        return z3.Concat(*pieces) if len(pieces) > 1 else pieces[0]

    def visit_Name(self, node: ast.Name) -> Value:
        match = _HOLE.fullmatch(node.id)
        if match is None:
            raise Unsupported(node.id)
        return Value("source", self.encoder.string(self.holes[int(match.group(1))]),
                     z3.BoolVal(True))

    def visit_UnaryOp(self, node: ast.UnaryOp) -> Value:
        operand = self.visit(node.operand)
        if isinstance(node.op, ast.Not):
            value = _to_bool(operand)
            return Value("bool", z3.Not(value.term), value.ok)
        if isinstance(node.op, ast.USub) and operand.kind == "int":
            return Value("int", -operand.term, operand.ok)
        raise Unsupported(type(node.op).__name__)

    def visit_BoolOp(self, node: ast.BoolOp) -> Value:
        values = [self.visit(v) for v in node.values]
        for value in values:
            if value.kind not in ("bool", "source"):
                raise Unsupported("and/or of non-booleans")  # Python returns an operand
        as_bools = [_to_bool(v) for v in values]
        # A source operand must be True/False itself: ``1 and x`` would return an int.
        exact = [z3.And(b.ok, rx.one_of(v.term, ("True", "False")))
                 if v.kind == "source" else b.ok for v, b in zip(values, as_bools, strict=True)]
        terms = [b.term for b in as_bools]
        combined = z3.And(*terms) if isinstance(node.op, ast.And) else z3.Or(*terms)
        return Value("bool", combined, z3.And(*exact))

    def visit_IfExp(self, node: ast.IfExp) -> Value:
        test = _to_bool(self.visit(node.test))
        body, orelse = self.visit(node.body), self.visit(node.orelse)
        if body.kind != orelse.kind or body.kind not in ("str", "bool", "int"):
            raise Unsupported("branches of different kinds")
        return Value(body.kind, z3.If(test.term, body.term, orelse.term),
                     z3.And(test.ok, z3.If(test.term, body.ok, orelse.ok)))

    def visit_Call(self, node: ast.Call) -> Value:
        func = node.func
        if (isinstance(func, ast.Attribute) and func.attr in ("lower", "upper")
                and not node.args and not node.keywords):
            target = self.visit(func.value)
            if target.kind != "str":
                raise Unsupported("case of a non-string")
            return Value("case", target.term, target.ok, upper=func.attr == "upper")
        if isinstance(func, ast.Name) and func.id == "str" and len(node.args) == 1:
            return _to_str(self.visit(node.args[0]))
        raise Unsupported("call")

    def visit_Compare(self, node: ast.Compare) -> Value:
        left = self.visit(node.left)
        results: list[Value] = []
        for index, (op, comparator) in enumerate(zip(node.ops, node.comparators, strict=True)):
            results.append(self.compare(left, op, comparator))
            if index + 1 < len(node.ops):  # a chain: ``a < b < c``
                left = self.visit(comparator)
        return Value("bool", z3.And(*[r.term for r in results]),
                     z3.And(*[r.ok for r in results]))

    def compare(self, left: Value, op: ast.cmpop, right_node: ast.expr) -> Value:
        if isinstance(op, (ast.In, ast.NotIn)):
            result = self.member(left, right_node)
            return Value("bool", z3.Not(result.term) if isinstance(op, ast.NotIn)
                         else result.term, result.ok)
        right = self.visit(right_node)
        if isinstance(op, (ast.Eq, ast.NotEq)):
            result = self.equal(left, right)
            return Value("bool", z3.Not(result.term) if isinstance(op, ast.NotEq)
                         else result.term, result.ok)
        orderings: dict[type, Callable[[Any, Any], Any]] = {
            ast.Lt: operator.lt, ast.LtE: operator.le, ast.Gt: operator.gt, ast.GtE: operator.ge}
        ordering = orderings.get(type(op))
        if ordering is None:
            raise Unsupported(type(op).__name__)
        a, b = _to_int(left), _to_int(right)
        return Value("bool", ordering(a.term, b.term), z3.And(a.ok, b.ok))

    def equal(self, left: Value, right: Value) -> Value:
        ok = z3.And(left.ok, right.ok)
        if left.kind == "case" or right.kind == "case":
            case, other = (left, right) if left.kind == "case" else (right, left)
            return Value("bool", self.caseless_equal(case, other), ok)
        kinds = {left.kind, right.kind}
        if kinds == {"str"}:
            return Value("bool", left.term == right.term, ok)
        if kinds <= {"int", "bool", "source"} and kinds != {"source"}:
            if "int" in kinds:
                a, b = _to_int(left), _to_int(right)
            else:
                a, b = _to_bool(left), _to_bool(right)
            return Value("bool", a.term == b.term, z3.And(a.ok, b.ok))
        if kinds == {"source"}:
            return Value("bool", left.term == right.term, z3.BoolVal(False))
        if "str" in kinds and kinds & {"int", "bool"}:
            return Value("bool", z3.BoolVal(False), ok)  # 'a' == 1 is False
        raise Unsupported("comparison of a string with Python source")

    def caseless_equal(self, case: Value, other: Value) -> z3.BoolRef:
        """``x.lower() == 'true'``: ``x`` is some casing of the literal."""
        if other.kind != "str" or not z3.is_string_value(other.term):
            raise Unsupported("case-insensitive comparison with a non-literal")
        literal = other.term.as_string()
        wanted = literal.upper() if case.upper else literal.lower()
        if literal != wanted:
            return z3.BoolVal(False)
        if not literal:
            return case.term == z3.StringVal("")
        return z3.InRe(case.term, rx.caseless(literal))

    def member(self, left: Value, container: ast.expr) -> Value:
        if isinstance(container, (ast.List, ast.Tuple, ast.Set)):
            options = [self.equal(left, self.visit(e)) for e in container.elts]
            if not options:
                return Value("bool", z3.BoolVal(False), left.ok)
            return Value("bool", z3.Or(*[o.term for o in options]),
                         z3.And(*[o.ok for o in options]))
        right = self.visit(container)
        if left.kind == "str" and right.kind == "str":
            return Value("bool", z3.Contains(right.term, left.term), z3.And(left.ok, right.ok))
        raise Unsupported("membership")
