"""Read a ROS 2 parameter file the way rcl's YAML parameter parser does, with lines.

A parameter file maps node keys (``/ns/node``, ``node``, ``/**``, nested mappings of
namespaces) to ``ros__parameters`` blocks whose nested mappings become dotted parameter
names. rcl types plain scalars itself (``y``/``n`` are booleans, ``5`` an integer, ``5.0``
a double; quoted values are strings) and rejects what it cannot represent: a value before
``ros__parameters``, ``ros__parameters`` without a node key, sequences mixing types,
nested sequences, empty values. We record those as problems (the file would stop the node
from starting) together with what PyYAML would hide: duplicate keys, of which it keeps
the last, and node keys with no ``ros__parameters`` under them, which ROS ignores.

Who reads the file matters. rcl (``--params-file``, for nodes) parses events, so a node key
or a nested mapping written twice is merged; launch_ros (for loaded components) uses
``yaml.safe_load``, which keeps only the last, and takes a file without any
``ros__parameters`` as one flat set of parameters. ``ParamFile.problems_for`` answers per
reader.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path

import yaml

from launchverify.frontends.subst_parser import SubstitutionSyntaxError, parse_substitution
from launchverify.frontends.yaml_reader import YamlLoadError, compose, span_of
from launchverify.ir.subst import Sub
from launchverify.problems import Problem, ProblemSink
from launchverify.span import Span
from launchverify.workspace.reading import long_number, long_number_message, read_file

MAX_NODES = 200_000  # alias expansion budget, as for launch files
PARAMETERS_KEY = "ros__parameters"

_TRUE = frozenset({"y", "Y", "yes", "Yes", "YES", "true", "True", "TRUE", "on", "On", "ON"})
_FALSE = frozenset({"n", "N", "no", "No", "NO", "false", "False", "FALSE", "off", "Off",
                    "OFF"})
# strtol with base 0, as rcl reads integers: decimal, 0x hexadecimal, 0 octal
_INTEGER = re.compile(r"[+-]?(0[xX][0-9a-fA-F]+|0[0-7]*|[1-9][0-9]*)")
_INT64 = (-(1 << 63), (1 << 63) - 1)
_SPECIAL_FLOATS = {".nan": float("nan"), ".NaN": float("nan"), ".NAN": float("nan"),
                   ".inf": float("inf"), ".Inf": float("inf"), ".INF": float("inf"),
                   "-.inf": float("-inf"), "-.Inf": float("-inf"), "-.INF": float("-inf")}


@dataclass(frozen=True, slots=True)
class FileParameter:
    """One parameter value as a node would receive it."""

    value: object
    kind: str  # bool, integer, double, string, or <kind>_array
    span: Span  # the key of a scalar (the value of a list)
    value_span: Span | None = None  # a scalar's value as written


@dataclass
class ParamBlock:
    """One ``ros__parameters`` block and the node key (pattern) it applies to."""

    key: str  # as rcl reads it, with a leading "/": "/amcl", "/**", "/robot1/*/planner"
    span: Span  # the node key as written
    parameters: dict[str, FileParameter] = field(default_factory=dict)


@dataclass
class ParamFile:
    """What a parameter file holds, and what is wrong with it."""

    path: Path
    blocks: list[ParamBlock] = field(default_factory=list)
    sink: ProblemSink = field(default_factory=ProblemSink)
    # What only rcl rejects: launch_ros reads files for loaded components itself.
    rcl_sink: ProblemSink = field(default_factory=ProblemSink)
    # Of those, keys without a value: written again by PyYAML (RewrittenYaml), ``null``.
    empty_sink: ProblemSink = field(default_factory=ProblemSink)
    # What only launch_ros's yaml.safe_load loses (a mapping written twice: rcl merges).
    yaml_sink: ProblemSink = field(default_factory=ProblemSink)
    # Node keys without ros__parameters: ignored, unless launch_ros reads a flat file.
    ignored_sink: ProblemSink = field(default_factory=ProblemSink)
    readable: bool = True

    def problems_for(self, reader: str) -> list[Problem]:
        """Return what is wrong with the file for ``"rcl"``, ``"launch_ros"`` or ``"rewritten"``.

        ``"rewritten"``: PyYAML loads it and rcl reads what PyYAML writes again (nav2's
        ``RewrittenYaml``): what YAML loses counts, and what rcl refuses in any text, but
        not a key without a value (PyYAML writes ``null``, which rcl takes as text).
        """
        problems = list(self.sink.problems)
        if reader == "rcl":
            return (problems + self.rcl_sink.problems + self.empty_sink.problems
                    + self.ignored_sink.problems)
        problems += self.yaml_sink.problems
        if reader == "rewritten":
            return problems + self.rcl_sink.problems + self.ignored_sink.problems
        if self.blocks:  # without any ros__parameters, launch_ros takes the whole file
            problems += self.ignored_sink.problems
        return problems


def load_param_file(path: Path) -> ParamFile:
    """Read a parameter file; problems are recorded, never raised."""
    result = ParamFile(path)
    try:
        data = read_file(path)
    except OSError as error:
        result.readable = False
        result.sink.cannot_read(error, Span(path, 1), "parameter file")
        return result
    long = long_number(data)
    if long is not None:
        result.readable = False
        result.sink.parse(long_number_message(long[1]), Span(path, long[0]))
        return result
    try:
        root = compose(data.decode("utf-8"))
    except UnicodeDecodeError:
        result.readable = False
        result.sink.parse("parameter file is not UTF-8", Span(path, 1))
        return result
    except YamlLoadError as error:
        result.readable = False
        result.sink.parse(str(error), Span(path, error.line, error.column))
        return result
    if root is None:
        return result
    if not isinstance(root, yaml.MappingNode):
        result.sink.parse("a parameter file must map node names to ros__parameters",
                          span_of(path, root))
        return result
    try:
        _Reader(result).node_level(root, [])
    except _Budget:
        result.readable = False
        result.sink.parse("YAML aliases expand to more than the allowed document size",
                          Span(path, 1))
    except _Recursive as error:
        result.readable = False
        result.sink.parse("a YAML alias refers to a node that contains it (infinite "
                          "document)", span_of(path, error.node))
    except RecursionError:
        result.readable = False
        result.sink.parse("the parameter file nests too deeply", Span(path, 1))
    return result


class _Budget(Exception):
    """Alias expansion makes the document too large."""


class _Recursive(Exception):
    """An alias refers to a node that contains it."""

    def __init__(self, node: yaml.Node) -> None:
        super().__init__("recursive alias")
        self.node = node


class _Reader:
    def __init__(self, result: ParamFile) -> None:
        self.result = result
        self.path = result.path
        self.count = 0
        self.open: set[int] = set()  # mappings being read (an alias back to one: a cycle)

    def problem(self, message: str, node: yaml.Node) -> None:
        self.result.sink.parse(message, span_of(self.path, node))

    def rcl_problem(self, message: str, node: yaml.Node) -> None:
        self.result.rcl_sink.parse(message, span_of(self.path, node))

    def yaml_problem(self, message: str, node: yaml.Node) -> None:
        self.result.yaml_sink.parse(message, span_of(self.path, node))

    def enter(self, node: yaml.Node) -> None:
        """Mark a collection as being read; meeting it again inside itself is a cycle."""
        if id(node) in self.open:
            raise _Recursive(node)
        self.open.add(id(node))

    def pairs(self, mapping: yaml.MappingNode) -> list[tuple[str, yaml.Node, yaml.Node]]:
        """Return (key, key node, value node), duplicate keys as rcl reads them.

        A mapping written twice is merged by rcl and replaced by ``yaml.safe_load``; a
        value written twice is the last one for both.
        """
        seen: dict[str, tuple[yaml.Node, yaml.Node]] = {}
        out: list[tuple[str, yaml.Node, yaml.Node]] = []
        self.count += len(mapping.value)
        if self.count > MAX_NODES:
            raise _Budget
        for key_node, value_node in mapping.value:
            if key_node.tag == "tag:yaml.org,2002:merge" and isinstance(
                    value_node, yaml.MappingNode):
                self.enter(value_node)
                try:
                    out.extend(self.pairs(value_node))  # ``<<: *defaults``
                finally:
                    self.open.discard(id(value_node))
                continue
            key = str(key_node.value) if isinstance(key_node, yaml.ScalarNode) else ""
            if key in seen:
                first_key, first_value = seen[key]
                line = first_key.start_mark.line + 1
                if isinstance(first_value, yaml.MappingNode) and isinstance(
                        value_node, yaml.MappingNode):
                    self.yaml_problem(f"duplicate key {key!r}: launch_ros reads this file "
                                      "with yaml.safe_load, which keeps only the last one "
                                      f"(the first is at line {line}; rcl would merge them)",
                                      key_node)
                else:
                    self.problem(f"duplicate key {key!r}: only the last one is used (the "
                                 f"first is at line {line})", key_node)
                    out = [item for item in out if item[0] != key]
            seen[key] = (key_node, value_node)
            out.append((key, key_node, value_node))
        return out

    def node_level(self, mapping: yaml.MappingNode, names: list[tuple[str, yaml.Node]]) -> bool:
        """Read node keys down to ``ros__parameters``; return whether any block was found."""
        self.enter(mapping)
        try:
            return self._node_level(mapping, names)
        finally:
            self.open.discard(id(mapping))

    def _node_level(self, mapping: yaml.MappingNode,
                    names: list[tuple[str, yaml.Node]]) -> bool:
        found = False
        for key, key_node, value in self.pairs(mapping):
            if key == PARAMETERS_KEY:
                if not names:
                    self.rcl_problem("ros__parameters without a node name above it (rcl: "
                                     "there are no node names before ros__parameters)",
                                     key_node)
                    continue
                block = ParamBlock(_node_key([n for n, _ in names]),
                                   span_of(self.path, names[-1][1]))
                if isinstance(value, yaml.MappingNode):
                    self.parameters(value, "", block)
                elif not _empty(value):
                    self.problem("ros__parameters must hold a mapping of parameters", value)
                self.result.blocks.append(block)
                found = True
            elif isinstance(value, yaml.MappingNode):
                if self.node_level(value, [*names, (key, key_node)]):
                    found = True
                else:
                    self.result.ignored_sink.parse(f"no ros__parameters under {key!r}: ROS "
                                                   "ignores this block",
                                                   span_of(self.path, key_node))
            else:
                self.rcl_problem(f"{key!r} holds a value before any ros__parameters (rcl "
                                 "rejects the file)", key_node)
        return found

    def parameters(self, mapping: yaml.MappingNode, prefix: str, block: ParamBlock) -> None:
        self.enter(mapping)
        try:
            pairs = self.pairs(mapping)
            self._parameters(pairs, prefix, block)
        finally:
            self.open.discard(id(mapping))

    def _parameters(self, pairs: list[tuple[str, yaml.Node, yaml.Node]], prefix: str,
                    block: ParamBlock) -> None:
        for key, key_node, value in pairs:
            name = f"{prefix}.{key}" if prefix else key
            if isinstance(value, yaml.MappingNode):
                self.parameters(value, name, block)
            elif isinstance(value, yaml.SequenceNode):
                parameter = self.sequence(name, value)
                if parameter is not None:
                    block.parameters[name] = parameter
            else:
                assert isinstance(value, yaml.ScalarNode)
                if _empty(value):
                    self.result.empty_sink.parse(f"parameter {name!r} has no value",
                                                 span_of(self.path, key_node))
                    continue
                parsed, kind = scalar(value)
                block.parameters[name] = FileParameter(parsed, kind,
                                                       span_of(self.path, key_node),
                                                       span_of(self.path, value))

    def sequence(self, name: str, node: yaml.SequenceNode) -> FileParameter | None:
        values: list[object] = []
        kinds: set[str] = set()
        inner_lists = 0
        self.count += len(node.value)
        if self.count > MAX_NODES:
            raise _Budget
        for item in node.value:
            if isinstance(item, yaml.SequenceNode):
                inner_lists += 1
                if inner_lists == 2:
                    self.rcl_problem(f"parameter {name!r}: a list of lists (rcl: sequences "
                                     "cannot be key)", item)
                    return None
                continue
            if not isinstance(item, yaml.ScalarNode):
                return None  # what rcl makes of mappings in lists is not modelled
            parsed, kind = scalar(item)
            if kinds and kind not in kinds:
                self.rcl_problem(f"parameter {name!r}: a list must hold values of one type; "
                                 f"this {kind} follows {next(iter(kinds))} values (rcl: "
                                 "sequence should be of same type)", item)
                return None
            kinds.add(kind)
            values.append(parsed)
        if inner_lists:
            return None
        kind = f"{next(iter(kinds))}_array" if kinds else "string_array"
        return FileParameter(values, kind, span_of(self.path, node))


def scalar(node: yaml.ScalarNode) -> tuple[object, str]:
    """Type a scalar as rcl does: quoted is a string, else bool, integer, double, string."""
    text = str(node.value)
    if node.style in ("'", '"'):
        return text, "string"
    if text in _TRUE:
        return True, "bool"
    if text in _FALSE:
        return False, "bool"
    integer = _c_integer(text)
    if integer is not None:
        return integer, "integer"
    if text in _SPECIAL_FLOATS:
        return _SPECIAL_FLOATS[text], "double"
    if "_" in text:  # Python's float() accepts 1_000, strtod does not
        return text, "string"
    try:
        number = float(text)
    except ValueError:
        return text, "string"
    if math.isinf(number) and "inf" not in text.lower():
        return text, "string"  # strtod: out of range (ERANGE), so rcl keeps the text
    return number, "double"


def _c_integer(text: str) -> int | None:
    """Return the integer strtol(text, 0) reads in full without overflow, else ``None``."""
    if len(text) > 24:  # longer than any 64-bit integer: out of range (long texts: no scan)
        return None
    match = _INTEGER.fullmatch(text)
    if match is None:
        return None
    body = match.group(1)
    base = 16 if body[:2] in ("0x", "0X") else 8 if body.startswith("0") and body != "0" else 10
    value = int(body, base) * (-1 if text.startswith("-") else 1)
    return value if _INT64[0] <= value <= _INT64[1] else None


def _empty(node: yaml.Node) -> bool:
    """A plain scalar with nothing written (libyaml spells the plain style ``''``)."""
    return isinstance(node, yaml.ScalarNode) and node.value == "" and not node.style


def _node_key(parts: list[str]) -> str:
    joined = "/".join(part.strip("/") for part in parts if part.strip("/"))
    return "/" + joined


MAX_SUBSTITUTED_FILE = 1024 * 1024  # bytes read of a file loaded with allow_substs


@dataclass(frozen=True, slots=True)
class InlineSubstitution:
    """One line of a parameter file holding ``$(...)``: parsed, or why it does not parse."""

    where: Span
    expression: Sub | None
    error: str | None = None


def substitutions_in(path: Path) -> tuple[InlineSubstitution, ...]:
    """Return the lines of a parameter file that launch substitutes with ``allow_substs``.

    Parsed once per file and run (the walker caches them): a parameter file shared by a
    launch's nodes is substituted again for each node, in that node's context.
    """
    try:
        content = read_file(path, prefix=MAX_SUBSTITUTED_FILE).decode("utf-8", "replace")
    except OSError:
        return ()
    found = []
    for number, line in enumerate(content.splitlines(), 1):
        column = line.find("$(")
        if column < 0:
            continue
        where = Span(path, number, column + 1)
        try:
            found.append(InlineSubstitution(where, parse_substitution(line)))
        except SubstitutionSyntaxError as error:
            found.append(InlineSubstitution(where, None, str(error)))
    return tuple(found)
