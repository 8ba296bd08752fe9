"""The parameters a Python (rclpy) file declares: name, static type, default, dynamic typing.

rclpy types a parameter from its default (``0.5`` a double, ``1`` an integer), from a
``Parameter.Type`` given instead, or not at all: a declaration with neither (or a
descriptor with ``dynamic_typing=True``) takes any type. A parameter declared with a type
only has no value until one is given: reading it raises, which the code may handle.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import TYPE_CHECKING

from launchverify.topology.cpp_parameters import PARAMETER_TYPES
from launchverify.topology.model import PYTHON_UNDECLARED, Parameter
from launchverify.topology.parsing import span, text

if TYPE_CHECKING:
    from pathlib import Path

    from tree_sitter import Node

# ``Parameter.Type.DOUBLE`` and ``ParameterType.PARAMETER_DOUBLE`` -> rcl's type names
_ENUM = {**{name.removeprefix("PARAMETER_"): kind for name, kind in PARAMETER_TYPES.items()},
         **PARAMETER_TYPES}
_UNDECLARED = re.compile(rb"(allow_undeclared_parameters|automatically_declare_parameters_"
                         rb"from_overrides)\s*=\s*(?!False\b)")


def undeclared_option(source: bytes) -> str | None:
    """Return the option that lets a node take parameters it never declares, if set."""
    found = _UNDECLARED.search(source)
    return None if found is None else PYTHON_UNDECLARED + found.group(1).decode()


def value_type(node: Node | None) -> str | None:
    """Return the parameter type of a literal default (``None``: not a literal)."""
    if node is None:
        return None
    kind = node.type
    if kind == "float":
        return "double"
    if kind == "integer":
        return "integer"
    if kind in ("true", "false"):
        return "bool"
    if kind in ("string", "concatenated_string"):
        return "string"
    if kind == "unary_operator" and node.named_children:
        return value_type(node.named_children[-1])
    if kind in ("list", "tuple"):
        elements = {value_type(e) for e in node.named_children}
        if len(elements) == 1:
            element = elements.pop()
            if element in ("bool", "integer", "double", "string"):
                return f"{element}_array"
    return None


def literal_value(node: Node | None) -> object:
    """Return a default's value when it is a number or a boolean literal."""
    if node is None:
        return None
    kind = node.type
    if kind in ("true", "false"):
        return kind == "true"
    try:
        if kind == "float":
            return float(text(node))
        if kind == "integer":
            return int(text(node), 0)
    except ValueError:
        return None
    if kind == "unary_operator" and text(node).startswith("-") and node.named_children:
        inner = literal_value(node.named_children[-1])
        return -inner if isinstance(inner, (int, float)) and not isinstance(inner, bool) \
            else None
    return None


def enum_type(node: Node | None) -> str | None:
    """Return the type ``Parameter.Type.X`` (or ``ParameterType.PARAMETER_X``) names."""
    if node is None or node.type != "attribute":
        return None
    return _ENUM.get(text(node).rsplit(".", 1)[-1])


def declaration(path: Path, call: Node, name: str, default: Node | None,
                descriptor: Node | None) -> Parameter:
    """Return one declared parameter from its name, default (or type) and descriptor."""
    where = span(path, call)
    described = text(descriptor) if descriptor is not None else ""
    # a descriptor built in the call is judged by its flags; one from elsewhere may
    # allow any type
    dynamic = bool(re.search(r"dynamic_typing\s*=\s*True", described)) or (
        descriptor is not None and descriptor.type != "call")
    read_only = bool(re.search(r"read_only\s*=\s*True", described))
    by_enum = enum_type(default)
    if by_enum is not None:  # declared unset: reading it raises, which code may handle
        return Parameter(name, by_enum, where, read_only=read_only)
    if default is None or default.type == "none":  # rclpy: dynamically typed
        return Parameter(name, None, where, dynamic=True, read_only=read_only)
    return Parameter(name, value_type(default), where, literal_value(default),
                     dynamic=dynamic, read_only=read_only)



def name_pattern(node: Node, string: Callable[[Node], str | None]) -> str:
    """Return a declared name with ``*`` for each part built at run time."""
    found = string(node)
    if found is not None:
        return found
    if node.type == "binary_operator" and text(node.child_by_field_name("operator")) == "+":
        left, right = node.child_by_field_name("left"), node.child_by_field_name("right")
        if left is not None and right is not None:
            return re.sub(r"\*+", "*", name_pattern(left, string) + name_pattern(right, string))
    if node.type == "string":  # an f-string: its literal parts, ``*`` for each field
        parts = []
        for child in node.named_children:
            if child.type == "string_content":
                parts.append(text(child))
            elif child.type == "interpolation":
                parts.append("*")
        return re.sub(r"\*+", "*", "".join(parts)) or "*"
    return "*"
