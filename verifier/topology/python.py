"""Endpoints a Python file creates (rclpy, rclpy.action, message_filters, tf2_ros).

tree-sitter-python rather than the standard ``ast``, for the same reason as C++: a file
with a syntax error (or written for another Python) still yields what it recovered, and
both extractors share one tree walk. Types come from the file's imports (``from
sensor_msgs.msg import LaserScan`` makes ``LaserScan`` ``sensor_msgs/msg/LaserScan``);
names are literals, variables or attributes assigned from literals, or parameters
(``declare_parameter('topic', 'scan')`` then ``get_parameter('topic').value``).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING

from launchverify.topology.model import (
    Endpoint,
    EndpointKind,
    FileInterfaces,
    NodeName,
    Parameter,
)
from launchverify.topology.names import Resolved, merge, unknown
from launchverify.topology.parsing import damaged, parse, short, span, text, walk
from launchverify.topology.python_parameters import declaration, name_pattern, undeclared_option
from launchverify.topology.qos import Qos, overriding_of, qos_of
from launchverify.topology.wrappers import (
    TF_CLASSES,
    image_endpoints,
    normalise_type,
    tf_endpoints,
)

if TYPE_CHECKING:
    from tree_sitter import Node

MAX_DEPTH = 6
# method -> (kind, index of the type, index of the name, keyword of the type, of the name)
_METHODS = {
    "create_publisher": (EndpointKind.PUBLISHER, 0, 1, "msg_type", "topic"),
    "create_lifecycle_publisher": (EndpointKind.PUBLISHER, 0, 1, "msg_type", "topic"),
    "create_subscription": (EndpointKind.SUBSCRIPTION, 0, 1, "msg_type", "topic"),
    "create_service": (EndpointKind.SERVICE, 0, 1, "srv_type", "srv_name"),
    "create_client": (EndpointKind.CLIENT, 0, 1, "srv_type", "srv_name"),
}
_CLASSES = {
    "ActionServer": (EndpointKind.ACTION_SERVER, 1, 2, "action_type", "action_name"),
    "ActionClient": (EndpointKind.ACTION_CLIENT, 1, 2, "action_type", "action_name"),
}
_QOS = {"create_publisher": (2, "qos_profile"), "create_subscription": (3, "qos_profile"),
        "create_lifecycle_publisher": (2, "qos_profile")}
_NODE_CLASSES = ("Node", "LifecycleNode")
_DECLARING = re.compile(rb"\bdeclare_parameters?\s*\(")
_READERS = ("value", "string_value", "get_parameter_value", "as_string")


@dataclass
class _File:
    path: Path
    imports: dict[str, str] = field(default_factory=dict)  # local name -> dotted origin
    values: dict[str, list[Node]] = field(default_factory=dict)
    defaults: dict[str, Resolved] = field(default_factory=dict)
    loops: dict[str, str] = field(default_factory=dict)  # loop variable -> what it iterates
    parameters: list[Parameter] = field(default_factory=list)
    declaring_calls: int = 0  # declare_parameter(s) calls read
    changes: dict[str, list[str]] = field(default_factory=dict)  # var -> ``var.x = ...``


def extract(path: Path, data: bytes) -> FileInterfaces:
    """Return the endpoints and node names one Python source file creates."""
    tree = parse("python", data)
    nodes = walk(tree.root_node)
    context = _File(path)
    _collect(context, nodes)
    endpoints: list[Endpoint] = []
    names: list[NodeName] = []
    for node in nodes:
        if node.type == "call":
            endpoints.extend(_call(context, node))
            names.extend(_node_name(context, node))
    return FileInterfaces(path, tuple(endpoints), tuple(names),
                          partial=damaged(tree.root_node), parameters=tuple(context.parameters),
                          undeclared=undeclared_option(data),
                          bases=_bases(context, nodes),
                          includes=tuple(sorted(set(context.imports.values()))),
                          declarations_missed=len(_DECLARING.findall(data))
                          > context.declaring_calls)


def _collect(context: _File, nodes: list[Node]) -> None:
    for node in nodes:
        if node.type == "import_from_statement":
            module = text(node.child_by_field_name("module_name"))
            for name in node.children_by_field_name("name"):
                if name.type == "aliased_import":
                    original = text(name.child_by_field_name("name"))
                    context.imports[text(name.child_by_field_name("alias"))] = (
                        f"{module}.{original}")
                else:
                    context.imports[text(name)] = f"{module}.{text(name)}"
        elif node.type == "import_statement":
            for name in node.children_by_field_name("name"):
                if name.type == "aliased_import":
                    context.imports[text(name.child_by_field_name("alias"))] = text(
                        name.child_by_field_name("name"))
        elif node.type == "for_statement":
            target = _variable(node.child_by_field_name("left"))
            if target:
                context.loops[target] = short(text(node.child_by_field_name("right")), 40)
        elif node.type == "assignment":
            left = node.child_by_field_name("left")
            if left is not None and left.type == "attribute":
                changed = _variable(left.child_by_field_name("object"))
                if changed:
                    context.changes.setdefault(changed, []).append(text(node))
            target = _variable(left)
            value = node.child_by_field_name("right")
            if target and value is not None:
                context.values.setdefault(target, []).append(value)
        elif node.type == "call":
            function = node.child_by_field_name("function")
            arguments = _positional(node)
            if _name(function) in ("declare_parameter", "declare_parameters"):
                context.declaring_calls += 1
            if _name(function) == "declare_parameter" and arguments:
                parameter = _string(arguments[0])
                default = _argument(node, 1, "value")
                context.parameters.append(declaration(
                    context.path, node, name_pattern(arguments[0], _string), default,
                    _argument(node, 2, "descriptor")))
                if parameter is not None and default is not None:
                    context.defaults.setdefault(parameter, _resolve(context, default, 0))
            elif _name(function) == "declare_parameters":
                _declare_parameters(context, node)


def _bases(context: _File, nodes: list[Node]) -> tuple[tuple[str, str], ...]:
    """Return each class with its base classes, named by where they are imported from."""
    found: list[tuple[str, str]] = []
    for node in nodes:
        superclasses = node.child_by_field_name("superclasses")
        if node.type != "class_definition" or superclasses is None:
            continue
        name = text(node.child_by_field_name("name"))
        for base in superclasses.named_children:
            if base.type in ("identifier", "attribute"):
                written = text(base)
                found.append((name, context.imports.get(written, written)))
    return tuple(found)


def _declare_parameters(context: _File, node: Node) -> None:
    """``declare_parameters('', [('topic', 'scan'), ...])``: each pair is a default."""
    namespace = _argument(node, 0, "namespace")
    listed = _argument(node, 1, "parameters")
    prefix = _string(namespace) if namespace is not None else ""
    if listed is None or listed.type != "list" or prefix is None:
        pattern = f"{prefix}.*" if prefix else "*"  # names not known here
        context.parameters.append(Parameter(pattern, None, span(context.path, node)))
        return
    for item in listed.named_children:
        if item.type != "tuple" or not item.named_children:
            context.parameters.append(Parameter(f"{prefix}.*" if prefix else "*", None,
                                                span(context.path, item)))
            continue
        elements = item.named_children
        name = name_pattern(elements[0], _string)
        full = f"{prefix}.{name}" if prefix else name
        context.parameters.append(declaration(
            context.path, item, full, elements[1] if len(elements) > 1 else None,
            elements[2] if len(elements) > 2 else None))
        parameter = _string(elements[0])
        if parameter is not None and len(elements) >= 2:
            full = f"{prefix}.{parameter}" if prefix else parameter
            context.defaults.setdefault(full, _resolve(context, elements[1], 0))


def _variable(node: Node | None) -> str | None:
    """Return the key of an assigned name: ``topic`` or ``self.topic``."""
    if node is None:
        return None
    if node.type == "identifier":
        return text(node)
    if node.type == "attribute" and text(node.child_by_field_name("object")) == "self":
        return "self." + text(node.child_by_field_name("attribute"))
    return None


def _name(function: Node | None) -> str:
    """Return the called name: ``create_publisher`` of ``self.node.create_publisher``."""
    if function is None:
        return ""
    if function.type == "attribute":
        return text(function.child_by_field_name("attribute"))
    return text(function)


def _positional(call: Node) -> list[Node]:
    arguments = call.child_by_field_name("arguments")
    if arguments is None:
        return []
    return [a for a in arguments.named_children
            if a.type not in ("keyword_argument", "comment", "list_splat", "dictionary_splat")]


def _argument(call: Node, index: int, keyword: str) -> Node | None:
    """Return an argument given by position or by keyword."""
    arguments = call.child_by_field_name("arguments")
    if arguments is None:
        return None
    for argument in arguments.named_children:
        if argument.type == "keyword_argument" and text(
                argument.child_by_field_name("name")) == keyword:
            return argument.child_by_field_name("value")
    positional = _positional(call)
    return positional[index] if index < len(positional) else None


def _string(node: Node) -> str | None:
    """Return a plain string literal's value (no f-string, no escapes), else ``None``."""
    if node.type == "concatenated_string":
        parts = [_string(c) for c in node.named_children]
        return None if any(p is None for p in parts) else "".join(p or "" for p in parts)
    if node.type != "string":
        return None
    start = next((c for c in node.named_children if c.type == "string_start"), None)
    if start is not None and any(p in text(start).lower() for p in "fb"):
        return None  # f-strings are built at run time; bytes are not names
    pieces = [c for c in node.named_children if c.type not in ("string_start", "string_end")]
    if any(c.type != "string_content" for c in pieces):
        return None
    return "".join(text(c) for c in pieces)


def _resolve(context: _File, node: Node, depth: int) -> Resolved:
    """Return what a name expression holds, as far as this file tells."""
    literal = _string(node)
    if literal is not None:
        return Resolved(literal)
    written = short(text(node))
    if depth > MAX_DEPTH:
        return unknown(f"'{written}' is too deeply indirect to follow")
    if node.type == "parenthesized_expression" and len(node.named_children) == 1:
        return _resolve(context, node.named_children[0], depth + 1)
    if node.type == "string":
        return unknown(f"built at run time: {written}")
    if node.type == "attribute" and text(node.child_by_field_name("attribute")) in _READERS:
        inner = node.child_by_field_name("object")
        return _resolve(context, inner, depth + 1) if inner is not None else unknown(written)
    if node.type == "call":
        function = node.child_by_field_name("function")
        called = _name(function)
        arguments = _positional(node)
        if called in ("declare_parameter", "get_parameter", "get_parameter_or") and arguments:
            parameter = _string(arguments[0])
            if parameter is not None:
                if called != "get_parameter" and len(arguments) > 1:
                    return Resolved(_resolve(context, arguments[1], depth + 1).value, parameter)
                default = context.defaults.get(parameter)
                return Resolved(default.value if default else None, parameter)
        if called in _READERS and function is not None and function.type == "attribute":
            inner = function.child_by_field_name("object")
            if inner is not None:
                return _resolve(context, inner, depth + 1)
        if called == "str" and len(arguments) == 1:
            return _resolve(context, arguments[0], depth + 1)
        return unknown(f"returned by {short(text(function), 40)}() at run time")
    variable = _variable(node)
    if variable is not None and variable not in context.values and variable in context.loops:
        return unknown(f"each item of {context.loops[variable]}, at run time")
    if variable is not None:
        candidates = [_resolve(context, v, depth + 1) for v in context.values.get(variable, [])]
        return merge(variable, candidates)
    return unknown(f"built at run time: {written}")


def _type(context: _File, node: Node | None) -> str | None:
    """Return the interface type a class expression names, through the file's imports."""
    if node is None:
        return None
    written = text(node)
    head, _, rest = written.partition(".")
    origin = context.imports.get(head)
    if origin is not None:
        written = f"{origin}.{rest}" if rest else origin
    return normalise_type(written)


def _owner(node: Node) -> str | None:
    parent = node.parent
    while parent is not None:
        if parent.type == "class_definition":
            return text(parent.child_by_field_name("name")) or None
        parent = parent.parent
    return None


def _endpoint(context: _File, call: Node, kind: EndpointKind, type_: str | None,
              name: Node | None, qos: Node | None = None, via: str | None = None,
              overriding: Node | None = None) -> Endpoint:
    where = span(context.path, call)
    qos_text = short(text(qos), 40) if qos is not None else None
    owner = _owner(call)
    if name is None:
        return Endpoint(kind, None, type_, where, qos=qos_text, via=via, owner=owner,
                        unresolved_reason="no name argument found")
    resolved = _resolve(context, name, 0)
    reason = resolved.reason
    if resolved.parameter is not None and resolved.value is None:
        reason = f"parameter '{resolved.parameter}' has no default declared in this file"
    profile = None
    if qos is not None and kind in (EndpointKind.PUBLISHER, EndpointKind.SUBSCRIPTION):
        profile = qos_of(_qos_texts(context, qos))
    opened = overriding_of(_qos_texts(context, overriding)) if overriding is not None else None
    if opened is not None:  # qos_overrides.* may settle what the code leaves open
        profile = replace(profile or Qos(None, None), overriding=opened)
    return Endpoint(kind, resolved.value, type_, where, resolved.parameter,
                    resolved.value if resolved.parameter else None, qos_text, via,
                    reason if resolved.value is None else None, owner, profile=profile)


def _qos_texts(context: _File, qos: Node) -> list[str]:
    """Return the QoS argument's text, or a variable's initialiser and changes."""
    variable = _variable(qos) if qos.type in ("identifier", "attribute") else None
    if variable is None:
        return [text(qos)]
    imported = context.imports.get(text(qos))
    if imported is not None:  # from rclpy.qos import qos_profile_sensor_data
        return [imported]
    values = context.values.get(variable, [])
    if len(values) != 1:
        return []
    return [text(values[0]), *context.changes.get(variable, [])]


def _call(context: _File, node: Node) -> list[Endpoint]:
    function = node.child_by_field_name("function")
    called = _name(function)
    origin = context.imports.get(text(function), text(function))
    if function is not None and function.type == "attribute" and called in _METHODS:
        kind, type_at, name_at, type_key, name_key = _METHODS[called]
        qos_at, qos_key = _QOS.get(called, (-1, ""))
        qos = _argument(node, qos_at, qos_key) if qos_at >= 0 else None
        overriding = _argument(node, 99, "qos_overriding_options") if qos_at >= 0 else None
        return [_endpoint(context, node, kind, _type(context, _argument(node, type_at, type_key)),
                          _argument(node, name_at, name_key), qos, overriding=overriding)]
    if called in _CLASSES:
        kind, type_at, name_at, type_key, name_key = _CLASSES[called]
        return [_endpoint(context, node, kind, _type(context, _argument(node, type_at, type_key)),
                          _argument(node, name_at, name_key))]
    if called in TF_CLASSES and ("tf2_ros" in origin or called in context.imports):
        return tf_endpoints(called, span(context.path, node), _owner(node))
    if called == "Subscriber" and "message_filters" in origin:
        return [_endpoint(context, node, EndpointKind.SUBSCRIPTION,
                          _type(context, _argument(node, 1, "msg_type")),
                          _argument(node, 2, "topic"), _argument(node, 3, "qos_profile"),
                          via="message_filters")]
    if called in ("advertise", "subscribe") and "transport" in text(function).lower():
        kind = EndpointKind.PUBLISHER if called == "advertise" else EndpointKind.SUBSCRIPTION
        return image_endpoints(_endpoint(context, node, kind, None, _argument(node, 0, "")),
                               camera=False)
    return []


def _node_name(context: _File, node: Node) -> list[NodeName]:
    """``super().__init__('talker')``, ``Node.__init__(self, 'x')``, ``rclpy.create_node('x')``."""
    function = node.child_by_field_name("function")
    called = _name(function)
    written = text(function)
    arguments = _positional(node)
    name: Node | None = None
    if called == "__init__" and written.startswith("super()"):
        name = _argument(node, 0, "node_name")
    elif called == "__init__" and written.rsplit(".", 1)[0].rsplit(".", 1)[-1] in _NODE_CLASSES:
        name = arguments[1] if len(arguments) > 1 else _argument(node, 99, "node_name")
    elif called in ("create_node", *_NODE_CLASSES) and (
            called == "create_node" or "rclpy" in context.imports.get(called, "")):
        name = _argument(node, 0, "node_name")
    if name is None:
        return []
    value = _resolve(context, name, 0).value
    return [NodeName(value, span(context.path, node), _owner(node))]
