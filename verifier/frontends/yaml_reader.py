"""Read a ``.launch.yaml`` file into entities with line and column spans.

PyYAML's composer gives every node its position; we build entities from the node tree
ourselves so that spans survive and duplicate keys (which PyYAML silently collapses) are
seen. Aliases can make a small file expand enormously, so conversion has a node budget.
"""

from __future__ import annotations

import re
from pathlib import Path

import yaml

from launchverify.frontends.entity import Attr, Entity, Scalar
from launchverify.problems import ProblemSink
from launchverify.span import Span
from launchverify.workspace.reading import long_number, long_number_message

# libyaml composes about 16 times faster and keeps the same marks; PyYAML may lack it.
_COMPOSER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
MAX_NODES = 200_000
MAX_FLOW_DEPTH = 1000  # libyaml's composer recurses in C: far deeper overflows its stack
MAX_BLOCK_INDENT = 4000  # columns of indentation (each block level adds at least one)


class _Budget(Exception):
    """Raised when alias expansion makes the document too large."""


class _Recursive(Exception):
    """Raised when an alias refers to a node that contains it."""

    def __init__(self, node: yaml.Node) -> None:
        super().__init__("recursive alias")
        self.node = node


class YamlLoadError(Exception):
    """A YAML document that cannot be read; carries its position."""

    def __init__(self, message: str, line: int, column: int) -> None:
        super().__init__(message)
        self.line = line
        self.column = column


def span_of(path: Path, node: yaml.Node) -> Span:
    """Return the span of a YAML node (PyYAML marks are 0-based)."""
    start, end = node.start_mark, node.end_mark
    return Span(path, start.line + 1, start.column + 1, end.line + 1, end.column + 1)


def compose(text: str) -> yaml.Node | None:
    """Compose one YAML document safely, raising ``YamlLoadError`` with a position."""
    _check_depth(text)
    try:
        return yaml.compose(text, Loader=_COMPOSER)
    except yaml.MarkedYAMLError as error:
        mark = error.problem_mark or error.context_mark
        line, column = (mark.line + 1, mark.column + 1) if mark else (1, 1)
        raise YamlLoadError(f"invalid YAML: {error.problem or error}", line, column) from None
    except yaml.YAMLError as error:
        raise YamlLoadError(f"invalid YAML: {error}", 1, 1) from None
    except RecursionError:
        raise YamlLoadError("invalid YAML: nesting too deep", 1, 1) from None


def _check_depth(text: str) -> None:
    """Refuse what would nest deeper than libyaml's composer can recurse (linear scan).

    Brackets are counted wherever they are (even quoted): a real file never comes near.
    """
    depth = deepest = 0
    for char in re.finditer(r"[\[\]{}]", text):
        depth = max(depth + (1 if char.group() in "[{" else -1), 0)
        if depth > deepest:
            deepest = depth
            if deepest > MAX_FLOW_DEPTH:
                line = text.count("\n", 0, char.start()) + 1
                raise YamlLoadError(f"YAML nested more than {MAX_FLOW_DEPTH} levels deep",
                                    line, 1)
    for match in re.finditer(rf"^ {{{MAX_BLOCK_INDENT},}}", text, re.MULTILINE):
        line = text.count("\n", 0, match.start()) + 1
        raise YamlLoadError(f"YAML indented more than {MAX_BLOCK_INDENT} columns", line, 1)


class ScalarReader:
    """Turns scalar nodes into Python values by YAML 1.1 rules (as PyYAML's safe_load)."""

    def __init__(self) -> None:
        self._constructor = yaml.SafeLoader("")

    def value(self, node: yaml.ScalarNode) -> Scalar:
        """Return the typed value of a scalar node."""
        try:
            result = self._constructor.construct_object(node, deep=True)
        except (yaml.YAMLError, ValueError):  # a value PyYAML cannot convert
            return str(node.value)
        if isinstance(result, (str, int, float, bool)) or result is None:
            return result
        return str(node.value)


def read_yaml(path: Path, data: bytes, sink: ProblemSink) -> Entity | None:
    """Parse YAML launch text into the root entity; record problems, never raise."""
    whole = Span.of_file(path)
    long = long_number(data)
    if long is not None:
        sink.parse(long_number_message(long[1]), Span(path, long[0]))
        return None
    try:
        text = decode(data)
        root = compose(text)
    except YamlLoadError as error:
        sink.parse(str(error), Span(path, error.line, error.column))
        return None
    if not isinstance(root, yaml.MappingNode) or len(root.value) != 1:
        sink.parse("a YAML launch file must be a mapping with one root key, 'launch'", whole)
        return None
    key, value = root.value[0]
    converter = _Converter(path, sink, text)
    try:
        return converter.entity(str(key.value), value, span_of(path, key))
    except _Budget:
        sink.parse("YAML aliases expand to more than the allowed document size", whole)
    except _Recursive as error:
        sink.parse("a YAML alias refers to a node that contains it (infinite document)",
                   span_of(path, error.node))
    except RecursionError:
        sink.parse("the YAML document nests too deeply", whole)
    return None


def decode(data: bytes) -> str:
    """Decode YAML bytes as UTF-8 (or UTF-16/32 with a byte-order mark), strictly."""
    marks = ((b"\xef\xbb\xbf", "utf-8-sig"), (b"\xff\xfe\x00\x00", "utf-32"),
             (b"\x00\x00\xfe\xff", "utf-32"), (b"\xff\xfe", "utf-16"), (b"\xfe\xff", "utf-16"))
    codec = next((name for bom, name in marks if data.startswith(bom)), "utf-8")
    try:
        return data.decode(codec)
    except UnicodeDecodeError as error:
        line = data[: error.start].count(b"\n") + 1
        raise YamlLoadError(f"the file is not valid {codec.upper()}: {error.reason}", line,
                            1) from None


# An anchor (``&name``): one node may then stand for several places.
_ANCHOR = re.compile(r"(?:^|[\s:,\[{-])&[^\s,\[\]{}]")


class _Converter:
    def __init__(self, path: Path, sink: ProblemSink, text: str = "") -> None:
        self.path = path
        self.sink = sink
        # values are located only in a document without anchors (no alias shares a node)
        self.lines = [] if _ANCHOR.search(text) else text.split("\n")
        self.scalars = ScalarReader()
        self.count = 0
        self.open: set[int] = set()  # collections being converted (to catch cycles)

    def _tick(self) -> None:
        self.count += 1
        if self.count > MAX_NODES:
            raise _Budget

    def entity(self, tag: str, node: yaml.Node, span: Span) -> Entity:
        if id(node) in self.open:
            raise _Recursive(node)
        self.open.add(id(node))
        try:
            return self._entity(tag, node, span)
        finally:
            self.open.discard(id(node))

    def _entity(self, tag: str, node: yaml.Node, span: Span) -> Entity:
        self._tick()
        entity = Entity(tag=tag, span=span, format="yaml")
        if isinstance(node, yaml.SequenceNode):
            entity.child_list = self._children(node)  # the same node: already marked open
            return entity
        if isinstance(node, yaml.ScalarNode):
            if node.value not in ("", "~", "null"):
                self.sink.parse(
                    f"`{tag}` must hold a mapping of attributes or a list of children",
                    span_of(self.path, node),
                )
            return entity
        assert isinstance(node, yaml.MappingNode)
        for key_node, value_node in node.value:
            self._tick()
            name = str(key_node.value)
            key_span = span_of(self.path, key_node)
            if name in entity.attrs or name in entity.nested or (
                name == "children" and entity.child_list is not None
            ):
                self.sink.parse(
                    f"duplicate key `{name}` in `{tag}`: ros2 launch silently uses the last one",
                    key_span,
                )
            if name == "children" and isinstance(value_node, yaml.SequenceNode):
                entity.child_list = self.children(value_node)
                entity.attrs.pop(name, None)
            elif isinstance(value_node, yaml.SequenceNode) and value_node.value and all(
                isinstance(item, yaml.MappingNode) for item in value_node.value
            ):
                entity.nested[name] = [
                    self.entity(name, item, span_of(self.path, item)) for item in value_node.value
                ]
            else:
                entity.attrs[name] = Attr(self.plain(value_node), key_span,
                                          self.written(value_node))
        return entity

    def children(self, node: yaml.SequenceNode) -> list[Entity]:
        if id(node) in self.open:
            raise _Recursive(node)
        self.open.add(id(node))
        try:
            return self._children(node)
        finally:
            self.open.discard(id(node))

    def _children(self, node: yaml.SequenceNode) -> list[Entity]:
        out: list[Entity] = []
        for item in node.value:
            self._tick()
            if not isinstance(item, yaml.MappingNode) or len(item.value) != 1:
                self.sink.parse(
                    "each child must be a mapping with one key, the entity type",
                    span_of(self.path, item),
                )
                continue
            key, value = item.value[0]
            out.append(self.entity(str(key.value), value, span_of(self.path, key)))
        return out

    def written(self, node: yaml.Node) -> Span | None:
        """Return where a scalar's text is, when written verbatim on one line.

        Plain scalars and quoted ones without escapes qualify; block scalars do not.
        """
        start, end = node.start_mark, node.end_mark
        if (not isinstance(node, yaml.ScalarNode) or node.style not in (None, "", "'", '"')
                or start.line != end.line or start.line >= len(self.lines)):
            return None
        first, last = start.column, end.column
        if node.style:  # quoted
            first, last = first + 1, last - 1
        if self.lines[start.line][first:last] != node.value or not node.value:
            return None
        return Span(self.path, start.line + 1, first + 1, start.line + 1, last + 1)

    def plain(self, node: yaml.Node) -> Scalar | list[Scalar]:
        """Return a scalar or a list of scalars; anything deeper becomes its YAML text."""
        self._tick()
        if isinstance(node, yaml.ScalarNode):
            return self.scalars.value(node)
        if isinstance(node, yaml.SequenceNode):
            items: list[Scalar] = []
            for item in node.value:
                self._tick()
                if isinstance(item, yaml.ScalarNode):
                    items.append(self.scalars.value(item))
                else:
                    self.sink.parse("nested collections are not allowed here",
                                    span_of(self.path, item))
            return items
        self.sink.parse("a mapping is not allowed here", span_of(self.path, node))
        return None
