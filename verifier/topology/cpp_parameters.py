"""The parameters a C++ file declares: name, static type, default, dynamic typing.

rclcpp gives a parameter its static type at declaration: the template argument
(``declare_parameter<double>("x")``), a ``rclcpp::ParameterType``, or the default's type
(``0.5`` is a double, ``1`` an integer). Names built at run time keep their literal parts
(``plugin_name_ + ".max_vel"`` is ``*.max_vel``). What the file does not show stays
unknown: a default held by a member declared in a header has no type here.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import TYPE_CHECKING

from launchverify.models.node_parameters import NAME_CONSTANTS
from launchverify.topology.parsing import text

if TYPE_CHECKING:
    from tree_sitter import Node

# rclcpp's ParameterType names (``rclcpp::PARAMETER_DOUBLE``) -> rcl's type names
PARAMETER_TYPES = {
    "PARAMETER_BOOL": "bool", "PARAMETER_INTEGER": "integer", "PARAMETER_DOUBLE": "double",
    "PARAMETER_STRING": "string", "PARAMETER_BYTE_ARRAY": "byte_array",
    "PARAMETER_BOOL_ARRAY": "bool_array", "PARAMETER_INTEGER_ARRAY": "integer_array",
    "PARAMETER_DOUBLE_ARRAY": "double_array", "PARAMETER_STRING_ARRAY": "string_array",
}
_SCALARS = {
    "bool": "bool", "double": "double", "float": "double", "long double": "double",
    "std::string": "string", "string": "string", "const char *": "string",
    "const char*": "string", "char *": "string",
}
_INTEGER = re.compile(r"(?:unsigned |signed )?(?:std::)?(?:u?int(?:8|16|32|64)?_t|int|long"
                      r"|long long|short|size_t|unsigned)")
_VECTOR = re.compile(r"(?:const\s+)?std::vector\s*<\s*(.+?)\s*>")
_FLOAT_LITERAL = re.compile(r"[-+]?(?:\d+\.\d*|\.\d+|\d+[eE][-+]?\d+|\d+\.\d*[eE][-+]?\d+)"
                            r"[fFlL]?|[-+]?\d+[fF]")
_TEXT_LITERALS = ("string_literal", "raw_string_literal", "concatenated_string")


def cpp_type(written: str) -> str | None:
    """Return the parameter type a C++ type gives (``std::vector<double>``: double_array)."""
    compact = " ".join(written.replace("const ", "").replace("&", "").split())
    if compact in _SCALARS:
        return _SCALARS[compact]
    if _INTEGER.fullmatch(compact):
        return "integer"
    vector = _VECTOR.fullmatch(compact)
    if vector is not None:
        inner = vector.group(1)
        if inner in ("uint8_t", "std::uint8_t", "unsigned char"):
            return "byte_array"
        element = cpp_type(inner)
        return f"{element}_array" if element in ("bool", "integer", "double", "string") else None
    return None


def enum_type(node: Node) -> str | None:
    """Return the type a ``rclcpp::ParameterType`` value names, ``None`` for anything else."""
    last = text(node).rsplit("::", 1)[-1].strip()
    return PARAMETER_TYPES.get(last)


def value_type(node: Node, variable_type: Callable[[Node], str | None],
               depth: int = 0) -> str | None:
    """Return the parameter type of a default value expression, when the file shows it.

    ``variable_type`` gives the declared C++ type of a variable or member.
    """
    if depth > 4:
        return None
    kind = node.type
    if kind == "number_literal":
        return "double" if _FLOAT_LITERAL.fullmatch(text(node)) else "integer"
    if kind in ("true", "false"):
        return "bool"
    if kind in _TEXT_LITERALS:
        return "string"
    if kind == "unary_expression" and node.named_children:
        inner = value_type(node.named_children[-1], variable_type, depth + 1)
        return inner if inner in ("integer", "double") else None
    if kind == "parenthesized_expression" and len(node.named_children) == 1:
        return value_type(node.named_children[0], variable_type, depth + 1)
    if kind in ("identifier", "field_expression", "qualified_identifier"):
        written = variable_type(node)
        if written is not None:
            return cpp_type(written)
        return None
    if kind == "call_expression":  # std::string("x"), rclcpp::ParameterValue(0.5)
        function = text(node.child_by_field_name("function"))
        arguments = node.child_by_field_name("arguments")
        values = [] if arguments is None else list(arguments.named_children)
        callee = function.rsplit("::", 1)[-1]
        if callee == "ParameterValue" and len(values) == 1:
            return value_type(values[0], variable_type, depth + 1)
        if callee in ("string", "string_view"):
            return "string"
        return cpp_type(function)
    if kind == "compound_literal_expression":  # std::vector<double>{1.0, 2.0}
        return cpp_type(text(node.child_by_field_name("type")))
    if kind == "initializer_list":
        elements = {value_type(e, variable_type, depth + 1) for e in node.named_children}
        if len(elements) == 1:
            element = elements.pop()
            if element in ("bool", "integer", "double", "string"):
                return f"{element}_array"
        return None
    return None


def literal_value(node: Node) -> object:
    """Return a default's value when it is a plain literal (``None`` otherwise)."""
    kind = node.type
    written = text(node)
    if kind == "number_literal":
        cleaned = written.rstrip("fFlLuU")
        try:
            return float(cleaned) if _FLOAT_LITERAL.fullmatch(written) else int(cleaned, 0)
        except ValueError:
            return None
    if kind in ("true", "false"):
        return kind == "true"
    if kind == "call_expression" and text(node.child_by_field_name("function")).endswith(
            "ParameterValue"):
        arguments = node.child_by_field_name("arguments")
        if arguments is not None and len(arguments.named_children) == 1:
            return literal_value(arguments.named_children[0])
    if kind == "unary_expression" and written.startswith("-") and node.named_children:
        inner = literal_value(node.named_children[-1])
        return -inner if isinstance(inner, (int, float)) and not isinstance(inner, bool) \
            else None
    return None


def name_pattern(node: Node, literal: Callable[[Node], str | None],
                 values: Callable[[Node], list[Node]], depth: int = 0) -> str:
    """Return a declared name with ``*`` for each part built at run time.

    ``plugin_name_ + ".max_vel_x"`` is ``*.max_vel_x`` (also through a variable holding
    it); a name read entirely at run time is ``*`` (it could be any name).
    """
    found = literal(node)
    if found is not None:
        return found
    if depth > 4:
        return "*"
    if node.type == "qualified_identifier" and "".join(text(node).split()) in NAME_CONSTANTS:
        return NAME_CONSTANTS["".join(text(node).split())]
    if node.type in ("identifier", "field_expression") and len(values(node)) == 1:
        return name_pattern(values(node)[0], literal, values, depth + 1)
    if node.type == "binary_expression" and text(node.child_by_field_name("operator")) == "+":
        left, right = node.child_by_field_name("left"), node.child_by_field_name("right")
        if left is not None and right is not None:
            return re.sub(r"\*+", "*", name_pattern(left, literal, values, depth + 1)
                          + name_pattern(right, literal, values, depth + 1))
    if node.type == "call_expression" and _formatted(node, literal) is not None:
        return _formatted(node, literal) or "*"
    if node.type == "call_expression":  # std::string("x") + ...
        arguments = node.child_by_field_name("arguments")
        if arguments is not None and len(arguments.named_children) == 1 and \
                text(node.child_by_field_name("function")).endswith("string"):
            return name_pattern(arguments.named_children[0], literal, values, depth + 1)
    return "*"


_FORMATS = ("format", "fmt::format", "std::format")


def _formatted(node: Node, literal: Callable[[Node], str | None]) -> str | None:
    """Return ``fmt::format("{}.type", name)`` as ``*.type`` (``None``: not a format call).

    The format string may be wrapped in ``FMT_COMPILE(...)``/``FMT_STRING(...)``; each
    replacement field is a part built at run time.
    """
    function = "".join(text(node.child_by_field_name("function")).split())
    arguments = node.child_by_field_name("arguments")
    if function not in _FORMATS or arguments is None or not arguments.named_children:
        return None
    first = arguments.named_children[0]
    if first.type == "call_expression" and text(first.child_by_field_name("function")) in (
            "FMT_COMPILE", "FMT_STRING"):
        inner = first.child_by_field_name("arguments")
        first = inner.named_children[0] if inner is not None and inner.named_children else first
    written = literal(first)
    if written is None:
        return ""
    return re.sub(r"\*+", "*", re.sub(r"\{[^{}]*\}", "*", written))


_NUMBER = r"([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)[fFlL]?"


def descriptor_bounds(source: str, descriptor: str) -> tuple[float, float] | None:
    """Return the ``[from, to]`` range a descriptor variable is given in the file, if one.

    ``d.floating_point_range.push_back(r)`` (or ``= {r}``) with ``r.from_value = 0.0;
    r.to_value = 1.0`` or ``r.set__from_value(0.0).set__to_value(1.0)``, or
    ``d.integer_range[0].from_value = 1`` directly. Two different values for one end
    leave the range unknown.
    """
    name = re.escape(descriptor)
    ends: dict[str, set[str]] = {"from": set(), "to": set()}
    direct = re.compile(rf"\b{name}\s*\.\s*(?:floating_point|integer)_range\s*(?:\[\s*0\s*\])?"
                        rf"\s*\.\s*(from|to)_value\s*=\s*{_NUMBER}")
    for end, value in direct.findall(source):
        ends[end].add(value)
    held = re.compile(rf"\b{name}\s*\.\s*(?:floating_point|integer)_range\s*(?:\.\s*push_back"
                      rf"\s*\(\s*|=\s*\{{\s*)(\w+)")
    for holder in set(held.findall(source)):
        inner = re.escape(holder)
        for end, value in re.findall(rf"\b{inner}\s*\.\s*(from|to)_value\s*=\s*{_NUMBER}",
                                     source):
            ends[end].add(value)
        for end, value in re.findall(rf"\b{inner}\b[\w\s.()+-]*?\.\s*set__(from|to)_value\s*"
                                     rf"\(\s*{_NUMBER}\s*\)", source):
            ends[end].add(value)
        for value in re.findall(rf"\b{inner}\s*\.\s*set__from_value\s*\([^)]*\)\s*\.\s*"
                                rf"set__to_value\s*\(\s*{_NUMBER}\s*\)", source):
            ends["to"].add(value)
    if len(ends["from"]) != 1 or len(ends["to"]) != 1:
        return None
    return float(ends["from"].pop()), float(ends["to"].pop())
