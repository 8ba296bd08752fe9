"""Endpoints a C++ file creates (rclcpp, rclcpp_action, image_transport, message_filters, tf2).

Reads the tree-sitter-cpp tree of one file: every call of a ``create_*`` factory, every
construction of a wrapper class, and the default node name given to ``rclcpp::Node`` or
``LifecycleNode``. Names are resolved within the file: literals, ``std::string`` variables
and members initialised from literals, and parameters (``declare_parameter`` with its
default, ``get_parameter``). Variables are tracked by name, not by flow, so two different
values for one name leave it unknown rather than guessed.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING

from launchverify.span import Span
from launchverify.topology.cpp_parameters import (
    cpp_type,
    descriptor_bounds,
    enum_type,
    literal_value,
    name_pattern,
    value_type,
)
from launchverify.topology.model import (
    CPP_UNDECLARED,
    Endpoint,
    EndpointKind,
    FileInterfaces,
    MemberInit,
    NodeName,
    Parameter,
)
from launchverify.topology.names import Resolved, merge, unknown
from launchverify.topology.parsing import damaged, parse, short, span, text, walk
from launchverify.topology.qos import Qos, overriding_of, qos_of
from launchverify.topology.wrappers import (
    COSTMAP_CLASS,
    TF_CLASSES,
    Wrapper,
    image_endpoints,
    normalise_type,
    tf_endpoints,
    wrapper_endpoints,
    wrapper_of,
)

if TYPE_CHECKING:
    from tree_sitter import Node

MAX_DEPTH = 6
MAX_WRAPPER_ARGUMENTS = 4  # arguments of a wrapper's constructor resolved (names come first)
NODE_NAMESPACE = "the node's namespace, get_namespace()"
NODE_NAME = "~"  # ``get_name() + "/x"`` is ``~/x``: both expand to <namespace>/<name>/x
_OWN_NODE = re.compile(r"this|node_?|\w*node\(\)|shared_from_this\(\)", re.I)
_RCLCPP = {
    "create_publisher": EndpointKind.PUBLISHER,
    "create_subscription": EndpointKind.SUBSCRIPTION,
    "create_generic_publisher": EndpointKind.PUBLISHER,
    "create_generic_subscription": EndpointKind.SUBSCRIPTION,
    "create_service": EndpointKind.SERVICE,
    "create_client": EndpointKind.CLIENT,
}
_ACTION = {"create_server": EndpointKind.ACTION_SERVER,
           "create_client": EndpointKind.ACTION_CLIENT}
# image_transport calls: name -> (kind, camera)
_IMAGE = {
    "advertise": (EndpointKind.PUBLISHER, False),
    "advertiseCamera": (EndpointKind.PUBLISHER, True),
    "create_camera_publisher": (EndpointKind.PUBLISHER, True),
    "subscribeCamera": (EndpointKind.SUBSCRIPTION, True),
    "create_camera_subscription": (EndpointKind.SUBSCRIPTION, True),
}
_NODE_CLASSES = ("Node", "LifecycleNode")
_NODE_ARG = re.compile(r"[*&]?\s*(?:this|[\w:\->.]*node\w*(?:\(\))?|.*shared_from_this\(\)"
                       r"|.*get_node_\w+\(\))", re.I)
_BARE_TYPE = re.compile(r"[A-Za-z_]\w*")  # a type named without namespace: maybe a typedef
_IMAGE_OBJECT = re.compile(r"transport|^(?:this->)?it_?$", re.I)
_STRING_TYPES = ("std::string", "string", "const std::string", "std::string_view")


@dataclass
class _File:
    """What the whole file tells about its names: aliases, variables, parameters."""

    path: Path
    aliases: dict[str, str] = field(default_factory=dict)
    values: dict[str, list[Node]] = field(default_factory=dict)
    read_params: dict[str, list[str]] = field(default_factory=dict)  # get_parameter(p, var)
    types: dict[str, str] = field(default_factory=dict)
    members: dict[str, str] = field(default_factory=dict)
    defaults: dict[str, Resolved] = field(default_factory=dict)
    parameters: list[Parameter] = field(default_factory=list)
    declaring_calls: int = 0  # declare_parameter(s) calls read
    # var -> ``var.x(...)`` calls and ``var.qos_overriding_options = ...`` statements
    changes: dict[str, list[str]] = field(default_factory=dict)
    data: bytes = b""  # the file's bytes, for patterns the tree makes long-winded
    dynamic: set[str] = field(default_factory=set)  # descriptors with dynamic_typing = true
    read_only: set[str] = field(default_factory=set)  # descriptors with read_only = true


# NodeOptions that make a node take parameters it never declares (anything but ``false``)
_UNDECLARED = re.compile(rb"(allow_undeclared_parameters|automatically_declare_parameters_"
                         rb"from_overrides)\s*\(\s*(?!false\s*\))")
# every spelling of a declaring call, to tell whether the tree showed them all
DECLARING = re.compile(rb"\b(?:declare_parameters?|declare_parameter_if_not_declared|"
                       rb"add_parameter|declare_or_get_parameter)\s*[<(]")
_DESCRIPTOR_FLAG = re.compile(r"(\w+)\s*\.\s*(dynamic_typing|read_only)\s*=\s*true")


def extract(path: Path, data: bytes) -> FileInterfaces:
    """Return the endpoints and node names one C++ source file creates."""
    tree = parse("cpp", data)
    nodes = walk(tree.root_node)
    context = _File(path, data=data)
    _collect(context, nodes)
    endpoints: list[Endpoint] = []
    names: list[NodeName] = []
    inits: list[MemberInit] = []
    for node in nodes:
        if node.type == "call_expression":
            endpoints.extend(_call(context, node))
            endpoints.extend(_make_call(context, node, inits))
            names.extend(_node_name_call(context, node))
        elif node.type in ("declaration", "new_expression"):
            endpoints.extend(_construction(context, node, inits))
        elif node.type == "field_initializer":
            endpoints.extend(_construction(context, node))
            names.extend(_node_name_initializer(context, node))
            inits.extend(_member_init(context, node))
    undeclared = _UNDECLARED.search(data)
    return FileInterfaces(path, tuple(endpoints), tuple(names),
                          partial=damaged(tree.root_node),
                          aliases=tuple(sorted(context.aliases.items())),
                          members=tuple(sorted(context.members.items())),
                          inits=tuple(inits), classes=_classes(nodes),
                          instantiated=_instantiated(nodes), loaders=_loaders(nodes),
                          parameters=tuple(context.parameters),
                          undeclared=None if undeclared is None else (
                              CPP_UNDECLARED + undeclared.group(1).decode()),
                          bases=_bases(nodes),
                          includes=tuple(text(n.child_by_field_name("path")).strip('"<>')
                                         for n in nodes if n.type == "preproc_include"),
                          declarations_missed=len(DECLARING.findall(data))
                          > context.declaring_calls)


# --------------------------------------------------------------------------- the file


def _collect(context: _File, nodes: list[Node]) -> None:
    """Record aliases, variable values and types, and declared parameters."""
    for node in nodes:
        kind = node.type
        if kind == "alias_declaration":
            alias, aliased = node.child_by_field_name("name"), node.child_by_field_name("type")
            context.aliases[text(alias)] = "".join(text(aliased).split())
        elif kind == "type_definition":
            declarator = node.child_by_field_name("declarator")
            context.aliases[text(declarator)] = "".join(
                text(node.child_by_field_name("type")).split())
        elif kind == "using_declaration":
            written = "".join(text(node).removeprefix("using").rstrip(";").split())
            if "::" in written and not written.startswith("namespace"):
                context.aliases[written.rsplit("::", 1)[1]] = written
        elif kind == "init_declarator":
            value = node.child_by_field_name("value")
            target = _variable(node.child_by_field_name("declarator"))
            if target and value is not None:
                context.values.setdefault(target, []).extend(_initial(value))
        elif kind in ("declaration", "field_declaration"):
            written = text(node.child_by_field_name("type"))
            for declarator in node.children_by_field_name("declarator"):
                target = _variable(declarator)
                if target:
                    context.types[target] = written
                    if kind == "field_declaration":  # keyed by class: names repeat
                        context.members[f"{_owner(node) or ''}::{target}"] = written
            value = node.child_by_field_name("default_value")
            target = _variable(node.child_by_field_name("declarator"))
            if kind == "field_declaration" and value is not None and target:
                context.values.setdefault(target, []).extend(_initial(value))
        elif kind == "assignment_expression" and text(node.child_by_field_name("operator")) == "=":
            flag = _DESCRIPTOR_FLAG.fullmatch(" ".join(text(node).split()))
            if flag is not None:
                (context.dynamic if flag.group(2) == "dynamic_typing"
                 else context.read_only).add(flag.group(1))
            left = node.child_by_field_name("left")
            target = _variable(left)
            value = node.child_by_field_name("right")
            updated = _parameter_update(node)
            if left is not None and left.type == "field_expression" and text(
                    left.child_by_field_name("field")) == "qos_overriding_options":
                opened = _variable(left.child_by_field_name("argument"))  # options.qos_...
                if opened:
                    context.changes.setdefault(opened, []).append(text(node))
            if target and updated is not None:
                context.read_params.setdefault(target, []).append(updated)
            elif target and value is not None:
                context.values.setdefault(target, []).append(value)
        elif kind == "field_initializer":
            target = _variable(node.named_children[0]) if node.named_children else None
            arguments = node.named_children[-1] if node.named_children else None
            if target and arguments is not None and arguments.type in (
                    "argument_list", "initializer_list"):
                context.values.setdefault(target, []).extend(_initial(arguments))
        elif kind == "call_expression":
            _parameter_call(context, node)
            function = node.child_by_field_name("function")
            if function is not None and function.type == "field_expression":
                changed = _variable(function.child_by_field_name("argument"))
                if changed:
                    context.changes.setdefault(changed, []).append(text(node))


def _parameter_call(context: _File, node: Node) -> None:
    """Record ``declare_parameter`` defaults and ``get_parameter("p", var)`` targets."""
    _, name, template, _ = _callee(node.child_by_field_name("function"))
    arguments = _arguments(node)
    if name in ("declare_parameters", "declare_parameter", "declare_parameter_if_not_declared",
                "add_parameter", "declare_or_get_parameter"):
        context.declaring_calls += 1
    if name == "declare_parameters" and arguments:  # a map of names under a prefix
        prefix = _literal(arguments[0])
        context.parameters.append(Parameter(f"{prefix}.*" if prefix else "*", None,
                                            span(context.path, node)))
        return
    if name in ("declare_parameter_if_not_declared", "declare_or_get_parameter"):
        # nav2's helpers: the node comes first in their free-function forms
        name, arguments = "declare_parameter", _skip_nodes(context, arguments)
    elif name == "add_parameter":  # nav2's LifecycleNode's
        name = "declare_parameter"
    if name not in ("declare_parameter", "get_parameter", "get_parameter_or") or not arguments:
        return
    if name == "declare_parameter" and not _forwarded(arguments[0]):
        context.parameters.append(_declaration(context, node, arguments, template))
    parameter = _literal(arguments[0])
    if parameter is None:
        return
    if name == "declare_parameter" and len(arguments) > 1:
        default = _resolve(context, arguments[1], 0)
        if default.parameter is None and parameter not in context.defaults:
            context.defaults[parameter] = default
    elif name in ("get_parameter", "get_parameter_or") and len(arguments) > 1:
        target = _variable(arguments[1])
        if target:
            context.read_params.setdefault(target, []).append(parameter)
            if name == "get_parameter_or" and len(arguments) > 2:
                default = _resolve(context, arguments[2], 0)
                context.defaults.setdefault(parameter, default)


def _inside_try(node: Node) -> bool:
    """Return whether ``node`` is in a ``try`` block of its function (errors caught)."""
    parent = node.parent
    while parent is not None and parent.type not in ("function_definition",
                                                     "lambda_expression"):
        if parent.type == "try_statement":
            return True
        parent = parent.parent
    return False


def _in_scope(use: Node, values: list[Node]) -> list[Node]:
    """Return the values a variable may hold where it is used: its own function's first.

    One file's functions often reuse a local's name (``param_name`` for a controller's
    ``.type`` here, its ``.params_file`` there).
    """
    if len(values) < 2:
        return values
    function = _function_of(use)
    local = [v for v in values if _function_of(v) == function]
    return local or values


def _function_of(node: Node) -> tuple[int, int] | None:
    parent = node.parent
    while parent is not None and parent.type not in ("function_definition", "lambda_expression"):
        parent = parent.parent
    return None if parent is None else (parent.start_byte, parent.end_byte)


def _forwarded(name: Node) -> bool:
    """Return whether a declared name is a parameter of the enclosing function.

    Such a function is a helper (``declare_or_get_parameter(name, ...)`` forwarding to
    rclcpp): its callers' calls are the declarations, each read where it is written. So
    is a field the helper sets from one (nav2_util's ``add_parameter``: ``descriptor.name
    = name; declare_parameter(descriptor.name, ...)``).
    """
    parent = name.parent
    while parent is not None and parent.type not in ("function_definition", "lambda_expression"):
        parent = parent.parent
    declarator = parent.child_by_field_name("declarator") if parent is not None else None
    while declarator is not None and declarator.type != "function_declarator":
        declarator = declarator.child_by_field_name("declarator")
    parameters = declarator.child_by_field_name("parameters") if declarator else None
    if parameters is None or parent is None:
        return False
    given = {text(n) for p in parameters.named_children for n in walk(p) if n.type == "identifier"}
    if name.type == "identifier":
        return text(name) in given
    if name.type != "field_expression":
        return False
    written = text(name)
    return any(node.type == "assignment_expression"
               and text(node.child_by_field_name("left")) == written
               and (right := node.child_by_field_name("right")) is not None
               and right.type == "identifier" and text(right) in given
               for node in walk(parent))


def _declaration(context: _File, node: Node, arguments: list[Node],
                 template: Node | None) -> Parameter:
    """Return one ``declare_parameter`` call as a declaration.

    ``(name, default[, descriptor])`` or ``(name, type[, descriptor])``; a template
    argument gives the type. Without a default, the template form (rclcpp's, and the
    ``helper``s of nav2) is required: it throws at the declaration unless a value is
    given. One declared inside a ``try`` is optional: the code handles its absence.
    """
    name = name_pattern(arguments[0], _literal, lambda n: _in_scope(
        n, context.values.get(_variable(n) or "", [])))
    where = span(context.path, node)
    written = None if template is None or not template.named_children else text(
        template.named_children[0])
    declared = cpp_type(written) if written is not None else None
    second = arguments[1] if len(arguments) > 1 else None
    by_enum = enum_type(second) if second is not None else None
    descriptor = arguments[2] if len(arguments) > 2 else (
        second if second is not None and "escriptor" in text(second) else None)
    if descriptor is second:
        second = None
    flags = {w for w in re.findall(r"\w+", text(descriptor))} if descriptor is not None else set()
    # a descriptor this file builds in sight (a local variable, a literal) is judged by
    # its flags; one from elsewhere may allow any type
    seen = descriptor is None or "ParameterDescriptor" in text(descriptor) or (
        descriptor.type == "identifier" and text(descriptor) in context.types)
    dynamic = bool(flags & context.dynamic) or "dynamic_typing" in flags or not seen
    read_only = bool(flags & context.read_only)
    owner = _owner(node)
    if by_enum is not None or (second is None and written is not None):
        # the template form throws at the declaration when nothing gives a value (nav2's
        # helper too); a type alone declares it unset, which the code may well check
        required = by_enum is None and not _inside_try(node)
        return Parameter(name, by_enum or declared, where, dynamic=dynamic, required=required,
                         read_only=read_only, owner=owner)
    if second is None:  # (name) or (name, descriptor): a dynamically typed declaration
        return Parameter(name, None, where, dynamic=True, read_only=read_only, owner=owner)
    kind = declared or value_type(second, lambda n: context.types.get(_variable(n) or ""))
    bounds = None
    if descriptor is not None and descriptor.type == "identifier":
        bounds = descriptor_bounds(context.data.decode("utf-8", "replace"), text(descriptor))
    return Parameter(name, kind, where, literal_value(second), dynamic=dynamic,
                     read_only=read_only, owner=owner,
                     limits=(("bounds", bounds),) if bounds is not None else ())


_UPDATED = re.compile(r"""name\(?\)?\s*==\s*"([^"]+)"|"([^"]+)"\s*==\s*\w*name""")


def _parameter_update(assignment: Node) -> str | None:
    """Return the parameter a dynamic-parameter callback assigns: ``x = p.as_string()``.

    The idiom ``if (name == "topic") { topic_ = parameter.as_string(); }`` re-reads a
    declared parameter; it is the same parameter, not another value of the variable.
    """
    value = assignment.child_by_field_name("right")
    if value is None or value.type != "call_expression" or not re.search(
            r"\.(as_string|get_value<std::string>)\(\)$", "".join(text(value).split())):
        return None
    parent, depth = assignment.parent, 0
    while parent is not None and depth < 5:
        if parent.type == "if_statement":
            condition = text(parent.child_by_field_name("condition"))
            match = _UPDATED.search(condition)
            return (match.group(1) or match.group(2)) if match else None
        parent, depth = parent.parent, depth + 1
    return None


def _initial(value: Node) -> list[Node]:
    """Return the value an initialiser gives: ``{"x"}`` and ``("x")`` hold one."""
    if value.type in ("initializer_list", "argument_list"):
        return value.named_children[:1] if len(value.named_children) == 1 else []
    return [value]


def _variable(node: Node | None) -> str | None:
    """Return the key of an assigned variable: ``x``, ``x_``, ``this->x_`` are ``x`` / ``x_``."""
    if node is None:
        return None
    if node.type in ("identifier", "field_identifier"):
        return text(node)
    if node.type == "field_expression":
        if text(node.child_by_field_name("argument")) == "this":
            return text(node.child_by_field_name("field"))
        return None
    if node.type in ("reference_declarator", "pointer_declarator"):
        inner = node.named_children[-1] if node.named_children else None
        return _variable(inner)
    if node.type == "qualified_identifier":
        return text(node.child_by_field_name("name")) or None
    return None


# --------------------------------------------------------------------------- names


def _literal(node: Node) -> str | None:
    """Return the value of a string literal (adjacent literals joined), else ``None``."""
    if node.type == "string_literal":
        if any(c.type != "string_content" for c in node.named_children):
            return None  # escape sequences: rare in names, not decoded here
        return "".join(text(c) for c in node.named_children)
    if node.type == "raw_string_literal":
        content = node.child_by_field_name("delimiter")
        raw = text(node)
        delimiter = text(content) if content is not None else ""
        start = raw.find("(") + 1
        return raw[start: len(raw) - len(delimiter) - 2]
    if node.type == "concatenated_string":
        parts = [_literal(c) for c in node.named_children]
        return None if any(p is None for p in parts) else "".join(p or "" for p in parts)
    return None


def _resolve(context: _File, node: Node, depth: int) -> Resolved:
    """Return what a name expression holds, as far as this file tells."""
    literal = _literal(node)
    if literal is not None:
        return Resolved(literal)
    written = short(text(node))
    if depth > MAX_DEPTH:
        return unknown(f"'{written}' is too deeply indirect to follow")
    kind = node.type
    if kind in ("parenthesized_expression", "initializer_list") and len(node.named_children) == 1:
        return _resolve(context, node.named_children[0], depth + 1)
    if kind == "call_expression":
        return _resolve_call(context, node, depth)
    if kind in ("identifier", "field_expression", "qualified_identifier"):
        variable = _variable(node)
        if variable is None:
            return unknown(f"'{written}' is read at run time")
        candidates = [_resolve(context, value, depth + 1)
                      for value in context.values.get(variable, [])]
        candidates += [_parameter(context, p) for p in context.read_params.get(variable, [])]
        return merge(variable, candidates)
    if kind == "compound_literal_expression":  # std::string{x}
        value = node.child_by_field_name("value")
        if value is not None and len(value.named_children) == 1:
            return _resolve(context, value.named_children[0], depth + 1)
    if kind == "binary_expression" and text(node.child_by_field_name("operator")) == "+":
        left = _resolve(context, node.child_by_field_name("left"), depth + 1)  # type: ignore[arg-type]
        right = _resolve(context, node.child_by_field_name("right"), depth + 1)  # type: ignore[arg-type]
        if left.value is not None and right.value is not None and not (
                left.parameter or right.parameter):
            if left.value == NODE_NAME and not right.value.startswith("/"):
                return unknown(f"built from the node's name at run time: {written}")
            return Resolved(left.value + right.value)
        return unknown(f"built at run time: {written}")
    return unknown(f"built at run time: {written}")


def _own_node(obj: Node | None) -> bool:
    """Return whether a method is called on the node itself (``get_name()``, ``node->``)."""
    return obj is None or bool(_OWN_NODE.fullmatch(text(obj).lstrip("*")))


def _parameter(context: _File, parameter: str) -> Resolved:
    """Return a parameter's value: its declared default, when the file declares one."""
    default = context.defaults.get(parameter)
    return Resolved(default.value if default is not None else None, parameter)


def _resolve_call(context: _File, node: Node, depth: int) -> Resolved:
    function = node.child_by_field_name("function")
    _, name, _, obj = _callee(function)
    arguments = _arguments(node)
    if name in ("declare_parameter", "get_parameter", "declare_or_get_parameter") and arguments:
        parameter = _literal(arguments[0])
        if parameter is not None:
            if name != "get_parameter" and len(arguments) > 1:
                default = _resolve(context, arguments[1], depth + 1)
                return Resolved(default.value, parameter)
            return _parameter(context, parameter)
    if name == "get_namespace" and not arguments and _own_node(obj):
        return unknown(NODE_NAMESPACE)
    if name == "get_name" and not arguments and _own_node(obj):
        return Resolved(NODE_NAME)  # as a relative name, the node's own name is ``~``
    if name in ("as_string", "get_value", "c_str", "string_value", "get", "value_to_string") \
            and obj is not None:
        return _resolve(context, obj, depth + 1)
    if name in ("string", "string_view", "ParameterValue") and len(arguments) == 1:
        return _resolve(context, arguments[0], depth + 1)
    return unknown(f"returned by {short(text(function), 40)}() at run time")


# --------------------------------------------------------------------------- calls


def _callee(function: Node | None) -> tuple[str, str, Node | None, Node | None]:
    """Return (scope, name, template arguments, object) of a called expression."""
    if function is None:
        return "", "", None, None
    obj: Node | None = None
    scope = ""
    node: Node | None = function
    if function.type == "field_expression":
        obj = function.child_by_field_name("argument")
        node = function.child_by_field_name("field")
    while node is not None and node.type == "qualified_identifier":
        scope += text(node.child_by_field_name("scope")) + "::"
        node = node.child_by_field_name("name")
    if node is None:
        return scope, "", None, obj
    if node.type in ("template_function", "template_method"):
        return scope, text(node.child_by_field_name("name")), node.child_by_field_name(
            "arguments"), obj
    return scope, text(node), None, obj


def _arguments(call: Node) -> list[Node]:
    arguments = call.child_by_field_name("arguments")
    return [] if arguments is None else [
        a for a in arguments.named_children if a.type != "comment"]


def _template_type(context: _File, arguments: Node | None) -> str | None:
    """Return the normalised interface type of the first template argument."""
    if arguments is None or not arguments.named_children:
        return None
    return _type(context, text(arguments.named_children[0]))


def _type(context: _File, written: str) -> str | None:
    return _aliased(context.aliases, written)


def _aliased(aliases: dict[str, str], written: str) -> str | None:
    """Return the normalised type of ``written`` after following the aliases given."""
    compact = "".join(written.split()).removeprefix("const")
    for _ in range(4):  # follow aliases of aliases
        last = compact.rsplit("::", 1)[-1]
        if compact in aliases:
            compact = aliases[compact]
        elif last in aliases and aliases[last] != compact:
            compact = aliases[last]
        else:
            break
    return normalise_type(compact)


def _skip_nodes(context: _File, arguments: list[Node], keep_last: bool = True) -> list[Node]:
    """Drop the leading node arguments (``this``, ``node``, ``*this``) of a factory call.

    A factory's last argument is its name however it is spelt (``keep_last``); a helper
    class may take the node alone (``diagnostic_updater::Updater(this)``).
    """
    index = 0
    while index < len(arguments) - keep_last and _NODE_ARG.fullmatch(
            text(arguments[index])) and (
            context.types.get(_variable(arguments[index]) or "", "") not in _STRING_TYPES):
        index += 1
    return arguments[index:]


def _owner(node: Node) -> str | None:
    """Return the class whose code holds ``node`` (class body or ``Class::method``)."""
    parent = node.parent
    while parent is not None:
        if parent.type in ("class_specifier", "struct_specifier"):
            return text(parent.child_by_field_name("name")) or None
        if parent.type == "function_definition":
            declarator = parent.child_by_field_name("declarator")
            while declarator is not None and declarator.type != "function_declarator":
                declarator = declarator.child_by_field_name("declarator")
            inner = declarator.child_by_field_name("declarator") if declarator else None
            if inner is not None and inner.type == "qualified_identifier":
                return class_name(text(inner.child_by_field_name("scope"))) or None
        parent = parent.parent
    return None


def _endpoint(context: _File, node: Node, kind: EndpointKind, type_: str | None,
              name_arg: Node | None, qos: Node | None = None, via: str | None = None,
              written: str | None = None, options: Node | None = None) -> Endpoint:
    resolved = _resolve(context, name_arg, 0) if name_arg is not None else None
    built = _built(kind, resolved, type_, span(context.path, node), _owner(node),
                   short(text(qos), 40) if qos is not None else None, via, written)
    if qos is None or kind not in (EndpointKind.PUBLISHER, EndpointKind.SUBSCRIPTION):
        return built
    profile = qos_of(_qos_texts(context, qos))
    opened = overriding_of(_options_texts(context, options)) if options is not None else None
    if opened is not None:  # qos_overrides.* may settle what the code leaves open
        profile = replace(profile or Qos(None, None), overriding=opened)
    return replace(built, profile=profile)


def _options_texts(context: _File, options: Node) -> list[str]:
    """Return the options argument's text and, for a variable, what sets its overriding.

    A variable's single initialiser counts too (``auto opts = [] {...; return o;}()``).
    """
    variable = _variable(options) if options.type in ("identifier", "field_expression") else None
    if variable is None:
        return [text(options)]
    values = context.values.get(variable, [])
    initial = [text(values[0])] if len(values) == 1 else []
    return [text(options), *initial, *context.changes.get(variable, [])]


def _qos_texts(context: _File, qos: Node) -> list[str]:
    """Return the QoS argument's text, or a variable's initialiser and changes."""
    variable = _variable(qos) if qos.type in ("identifier", "field_expression") else None
    if variable is None:
        return [text(qos)]
    values = context.values.get(variable, [])
    if len(values) != 1:
        return []  # not known here, or assigned twice
    return [text(values[0]), *context.changes.get(variable, [])]


def _built(kind: EndpointKind, resolved: Resolved | None, type_: str | None, where: Span,
           owner: str | None, qos_text: str | None = None, via: str | None = None,
           written: str | None = None) -> Endpoint:
    """Return an endpoint from its resolved name (``None``: no name argument)."""
    written = "".join(written.split()) if written and type_ is None else None
    if resolved is None:
        return Endpoint(kind, None, type_, where, qos=qos_text, via=via, owner=owner,
                        unresolved_reason="no name argument found", type_written=written)
    reason = resolved.reason
    if resolved.parameter is not None and resolved.value is None:
        reason = f"parameter '{resolved.parameter}' has no default declared in this file"
    return Endpoint(kind, resolved.value, type_, where, resolved.parameter,
                    resolved.value if resolved.parameter else None, qos_text, via,
                    reason if resolved.value is None else None, owner, type_written=written)


def _first_template(arguments: Node | None) -> str | None:
    if arguments is None or not arguments.named_children:
        return None
    return text(arguments.named_children[0])


def _call(context: _File, node: Node) -> list[Endpoint]:
    scope, name, template, obj = _callee(node.child_by_field_name("function"))
    arguments = _arguments(node)
    image_scope = "image_transport" in scope
    if "rclcpp_action" in scope and name in _ACTION:
        rest = _skip_nodes(context, arguments)
        return [_endpoint(context, node, _ACTION[name], _template_type(context, template),
                          rest[0] if rest else None, written=_first_template(template))]
    if (name in _IMAGE and template is None and (image_scope or _image_object(context, obj))) or (
            image_scope and name in ("create_publisher", "create_subscription")):
        kind, camera = _IMAGE[name] if name in _IMAGE else (_RCLCPP[name], False)
        rest = _skip_nodes(context, arguments) if image_scope else arguments
        base = _endpoint(context, node, kind, None, rest[0] if rest else None)
        return image_endpoints(base, camera)
    if name == "subscribe" and obj is not None:
        return _subscribe(context, node, obj, arguments)
    if name in _RCLCPP:
        rest = _skip_nodes(context, arguments) if (scope or obj is None) else arguments
        type_ = _template_type(context, template)
        if name.startswith("create_generic_") and len(rest) > 1:
            written = _resolve(context, rest[1], 0).value
            type_ = normalise_type(written) if written else None
        qos = rest[1] if len(rest) > 1 and not name.startswith("create_generic_") else None
        if name in ("create_service", "create_client"):
            qos = None
        # (name, qos, options), (name, qos, callback, options)
        at = 2 if _RCLCPP[name] is EndpointKind.PUBLISHER else 3
        return [_endpoint(context, node, _RCLCPP[name], type_, rest[0] if rest else None, qos,
                          written=_first_template(template),
                          options=rest[at] if qos is not None and len(rest) > at else None)]
    return []


def _image_object(context: _File, obj: Node | None) -> bool:
    """Return whether a method's object is an ImageTransport (ROS 1 ``nh.advertise<T>`` is not)."""
    if obj is None:
        return False
    declared = context.types.get(_variable(obj) or "", "")
    return "image_transport" in declared or "ImageTransport" in declared or bool(
        _IMAGE_OBJECT.search(text(obj)))


def _subscribe(context: _File, node: Node, obj: Node, arguments: list[Node]) -> list[Endpoint]:
    """``sub.subscribe(node, "name")`` (message_filters) or ``it.subscribe("name", ...)``."""
    declared = context.types.get(_variable(obj) or "", "")
    rest = _skip_nodes(context, arguments)
    if "message_filters" in declared or "SubscriberFilter" in declared or (
            len(rest) < len(arguments) and "image_transport" not in declared):
        if "SubscriberFilter" in declared:
            base = _endpoint(context, node, EndpointKind.SUBSCRIPTION, None,
                             rest[0] if rest else None)
            return image_endpoints(base, camera=False)
        template = _template_arguments_in(declared)
        return [_endpoint(context, node, EndpointKind.SUBSCRIPTION,
                          _type(context, template) if template else None,
                          rest[0] if rest else None, via="message_filters", written=template)]
    if _image_object(context, obj):
        base = _endpoint(context, node, EndpointKind.SUBSCRIPTION, None,
                         rest[0] if rest else None)
        return image_endpoints(base, camera=False)
    return []


def _template_arguments_in(written: str) -> str | None:
    """Return the first template argument inside a written type, ``A<B>`` -> ``B``."""
    start, end = written.find("<"), written.rfind(">")
    if start < 0 or end < start:
        return None
    inner = written[start + 1: end]
    depth, out = 0, []
    for char in inner:
        if char == "<":
            depth += 1
        elif char == ">":
            depth -= 1
        elif char == "," and depth == 0:
            break
        out.append(char)
    return "".join(out).strip()


# --------------------------------------------------------------------------- constructions


def _construction(context: _File, node: Node,
                  deferred: list[MemberInit] | None = None) -> list[Endpoint]:
    """Wrapper objects built with their arguments: declarations, ``new``, initialisers."""
    if node.type == "declaration":
        declarator = node.child_by_field_name("declarator")
        if declarator is None or declarator.type != "init_declarator":
            return []
        arguments = declarator.child_by_field_name("value")
        if arguments is None or arguments.type not in ("argument_list", "initializer_list"):
            return []
        return _wrapper(context, node, text(node.child_by_field_name("type")),
                        list(arguments.named_children), deferred)
    if node.type == "new_expression":
        arguments = node.child_by_field_name("arguments")
        return _wrapper(context, node, text(node.child_by_field_name("type")),
                        [] if arguments is None else list(arguments.named_children), deferred)
    # field_initializer: a member whose declared type is a wrapper
    if len(node.named_children) < 2:
        return []
    member = _variable(node.named_children[0]) or ""
    arguments = node.named_children[-1]
    return _wrapper(context, node, context.types.get(member, ""),
                    list(arguments.named_children))


def _wrapper(context: _File, node: Node, written: str, arguments: list[Node],
             deferred: list[MemberInit] | None = None) -> list[Endpoint]:
    rest = _skip_nodes(context, arguments, keep_last=False) if arguments else []
    values = _values(context, rest)
    compact = "".join(written.split())
    if (deferred is not None and (len(rest) < len(arguments) or wrapper_of(compact))
            and _BARE_TYPE.fullmatch(compact) and compact not in context.aliases):
        deferred.append(MemberInit(None, compact, span(context.path, node), _owner(node),
                                   len(arguments) - len(rest), len(arguments), values))
        return []
    return _wrapper_endpoints(written, span(context.path, node), _owner(node),
                              len(arguments) - len(rest), len(arguments), values,
                              context.aliases)


def _values(context: _File, arguments: list[Node]) -> tuple[Resolved, ...]:
    """Resolve a wrapper's first arguments (a name is one of them; the rest cost little)."""
    return tuple(_resolve(context, a, 0) for a in arguments[:MAX_WRAPPER_ARGUMENTS])


def _wrapper_endpoints(written: str, where: Span, owner: str | None, node_arguments: int,
                       arguments: int, values: tuple[Resolved, ...],
                       aliases: dict[str, str]) -> list[Endpoint]:
    """Return what constructing a wrapper of type ``written`` with these arguments creates."""
    compact = "".join(written.split())
    for _ in range(4):  # a typedef of a wrapper: typedef message_filters::Subscriber<T> S;
        if compact not in aliases or aliases[compact] == compact:
            break
        compact = aliases[compact]
    if "make_shared" in compact or "make_unique" in compact:
        return []
    cls = re.sub(r"<.*", "", compact).rsplit("::", 1)[-1]
    if cls in TF_CLASSES and ("tf2_ros" in compact or cls in compact):
        return tf_endpoints(cls, where, owner)
    name = values[0] if values else None
    helper = wrapper_of(compact)
    if helper is not None and arguments and (node_arguments or helper[1].name_first):
        return _helper_endpoints(helper, compact, values, where, owner, aliases)
    if not arguments or (not node_arguments and "SubscriberFilter" not in compact):
        return []  # no node given: not subscribed yet
    if "message_filters" in compact and cls == "Subscriber":
        template = _template_arguments_in(compact)
        type_ = _aliased(aliases, template) if template else None
        return [_built(EndpointKind.SUBSCRIPTION, name, type_, where, owner,
                       via="message_filters", written=template)]
    if "image_transport" in compact and cls in ("CameraPublisher", "Publisher",
                                                "SubscriberFilter", "CameraSubscriber"):
        kind = EndpointKind.PUBLISHER if "Publisher" in cls else EndpointKind.SUBSCRIPTION
        return image_endpoints(_built(kind, name, None, where, owner),
                               camera=cls.startswith("Camera"))
    return []


def _helper_endpoints(helper: tuple[str, Wrapper], compact: str,
                      values: tuple[Resolved, ...], where: Span, owner: str | None,
                      aliases: dict[str, str]) -> list[Endpoint]:
    """Return what a helper class of ``wrappers.WRAPPERS`` creates with these arguments."""
    cls, wrapper = helper
    template = _template_arguments_in(compact)
    type_ = _aliased(aliases, template) if template else None
    name = None
    if wrapper.name_at is not None and len(values) > wrapper.name_at:
        name = values[wrapper.name_at]
    prefix = None
    if cls == COSTMAP_CLASS:
        if len(values) < 2:
            return []  # the costmap node's own constructor (NodeOptions): no child node
        prefix = _costmap_namespace(values)
    return wrapper_endpoints(cls, wrapper, name, type_, where, owner, prefix)


def _costmap_namespace(values: tuple[Resolved, ...]) -> Resolved:
    """Return where a ``Costmap2DROS`` child node lives, relative to its parent node.

    nav2 jazzy's ``(name, parent_namespace, local_namespace, use_sim_time)`` puts it in
    ``parent_namespace/local_namespace`` (the parent's own namespace in nav2's servers),
    kilted's ``(name, parent_namespace, use_sim_time, options)`` in
    ``parent_namespace/name``; ``(name, use_sim_time)`` in ``/name``.
    """
    name = values[0]
    if len(values) < 3:
        return Resolved(f"/{name.value}") if name.value else unknown(
            "the costmap's name is not known")
    parent, local = values[1], values[2]
    if local.value is None and local.parameter is None:  # use_sim_time: kilted's order
        local = name
    if local.value is None or local.parameter is not None:
        return unknown(local.reason or "the costmap's namespace is not known")
    if parent.reason == NODE_NAMESPACE:
        return Resolved(local.value)
    if parent.value is not None and parent.value.startswith("/") and parent.parameter is None:
        return Resolved(f"{parent.value.rstrip('/')}/{local.value}")
    return unknown(f"the costmap's parent namespace: {parent.reason or parent.value}")


def member_endpoints(init: MemberInit, written: str, aliases: dict[str, str]
                     ) -> list[Endpoint]:
    """Return what a member initialiser creates, given the member's type from a header."""
    return _wrapper_endpoints(written, init.span, init.owner, init.node_arguments,
                              init.arguments, init.values, aliases)


def _member_init(context: _File, node: Node) -> list[MemberInit]:
    """Keep an initialiser of a member this file does not declare, for the target's headers."""
    if len(node.named_children) < 2:
        return []
    member = _variable(node.named_children[0]) or ""
    arguments = list(node.named_children[-1].named_children)
    if not member or member in context.types or not arguments:
        return []
    rest = _skip_nodes(context, arguments, keep_last=False)
    return [MemberInit(member, None, span(context.path, node), _owner(node),
                       len(arguments) - len(rest), len(arguments), _values(context, rest))]


def _make_call(context: _File, node: Node,
               deferred: list[MemberInit] | None = None) -> list[Endpoint]:
    """``std::make_shared<Wrapper>(args)`` and ``make_unique``."""
    _, name, template, _ = _callee(node.child_by_field_name("function"))
    if name not in ("make_shared", "make_unique") or template is None:
        return []
    if not template.named_children:
        return []
    return _wrapper(context, node, text(template.named_children[0]), _arguments(node), deferred)


# --------------------------------------------------------------------------- classes


def class_name(written: str) -> str:
    """Return a class's bare name: ``ns::RosFilter<T>`` -> ``RosFilter``."""
    return re.sub(r"<.*", "", "".join(written.split())).rsplit("::", 1)[-1]


def _classes(nodes: list[Node]) -> tuple[tuple[str, tuple[str, ...]], ...]:
    """Return each class with the classes it relates to: its bases and its members' types."""
    out: dict[str, set[str]] = {}
    for node in nodes:
        if node.type not in ("class_specifier", "struct_specifier"):
            continue
        name = node.child_by_field_name("name")
        body = node.child_by_field_name("body")
        if name is None or body is None:
            continue
        related = out.setdefault(class_name(text(name)), set())
        for child in node.named_children:
            if child.type == "base_class_clause":
                related.update(class_name(text(b)) for b in child.named_children
                               if b.type != "access_specifier")
        for member in body.named_children:
            written = member.child_by_field_name("type")
            if member.type == "field_declaration" and written is not None:
                related.update(text(t) for t in walk(written) if t.type == "type_identifier")
    return tuple(sorted((name, tuple(sorted(related))) for name, related in out.items()))


def _bases(nodes: list[Node]) -> tuple[tuple[str, str], ...]:
    """Return each class with its base classes as written (``nav2_util::LifecycleNode``)."""
    found: list[tuple[str, str]] = []
    for node in nodes:
        name = node.child_by_field_name("name")
        if node.type not in ("class_specifier", "struct_specifier") or name is None:
            continue
        for child in node.named_children:
            if child.type == "base_class_clause":
                found.extend((class_name(text(name)), "".join(text(b).split()))
                             for b in child.named_children if b.type != "access_specifier")
    return tuple(found)


def _loaders(nodes: list[Node]) -> tuple[str, ...]:
    """Return the base classes of ``pluginlib::ClassLoader<Base>`` members and variables.

    Plugins chosen by parameters at run time (nav2's controllers, planners, behaviours)
    create endpoints no source of the package names.
    """
    found = set()
    for node in nodes:
        if node.type in ("field_declaration", "declaration"):
            written = "".join(text(node.child_by_field_name("type")).split())
            if "ClassLoader<" in written:
                found.add(_template_arguments_in(written[written.index("ClassLoader<"):]) or "")
    return tuple(sorted(n for n in found if n))


def _instantiated(nodes: list[Node]) -> tuple[str, ...]:
    """Return the classes the code builds: ``make_shared<X>``, ``new X``, ``X x(...)``."""
    found: set[str] = set()
    for node in nodes:
        if node.type == "new_expression":
            found.add(class_name(text(node.child_by_field_name("type"))))
        elif node.type == "call_expression":
            _, name, template, _ = _callee(node.child_by_field_name("function"))
            if name in ("make_shared", "make_unique") and template is not None:
                found.add(class_name(_first_template(template) or ""))
        elif node.type == "declaration" and node.parent is not None and (
                node.parent.type == "compound_statement"):
            found.add(class_name(text(node.child_by_field_name("type"))))
    return tuple(sorted(n for n in found if n))


# --------------------------------------------------------------------------- node names


def _node_name_initializer(context: _File, node: Node) -> list[NodeName]:
    """``MyNode() : Node("talker")`` and ``rclcpp_lifecycle::LifecycleNode("x", options)``."""
    if len(node.named_children) < 2:
        return []
    written = text(node.named_children[0]).rsplit("::", 1)[-1]
    arguments = node.named_children[-1].named_children
    if written not in _NODE_CLASSES or not arguments:
        return []
    name = _resolve(context, arguments[0], 0).value
    return [NodeName(name, span(context.path, node), _owner(node))]


def _node_name_call(context: _File, node: Node) -> list[NodeName]:
    """``std::make_shared<rclcpp::Node>("x")`` and ``rclcpp::Node::make_shared("x")``."""
    scope, name, template, _ = _callee(node.child_by_field_name("function"))
    arguments = _arguments(node)
    if not arguments:
        return []
    if name in ("make_shared", "make_unique") and template is not None:
        cls = class_name(_first_template(template) or "")  # not Subscriber<T, LifecycleNode>
    elif name == "make_shared" and scope:
        cls = scope.strip(":").rsplit("::", 1)[-1]
    else:
        return []
    if cls not in _NODE_CLASSES:
        return []
    value = _resolve(context, arguments[0], 0).value
    return [NodeName(value, span(context.path, node), _owner(node))]
