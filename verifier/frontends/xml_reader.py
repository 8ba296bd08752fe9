"""Read a ``.launch.xml`` file into entities, safely and with line and column spans.

lxml is configured so that nothing outside the file is ever read: no DTD loading, no
network, no entity expansion; documents that declare entities are refused outright, which
defuses entity bombs. lxml reports only the line of an element, so columns of tags and
attributes are recovered from the source text.
"""

from __future__ import annotations

import re
from pathlib import Path

from lxml import etree

from launchverify.frontends.entity import Attr, Entity
from launchverify.problems import ProblemSink
from launchverify.span import Span

MAX_BYTES = 5 * 1024 * 1024
_ENTITY_DECL = re.compile(rb"<!ENTITY", re.IGNORECASE)


class _Locator:
    """Finds columns of start tags and attributes in the source text."""

    def __init__(self, path: Path, text: str) -> None:
        self.path = path
        self.lines = text.splitlines()
        self.cursor: dict[int, int] = {}

    def element(self, tag: str, line: int) -> tuple[Span, str]:
        """Return the span of ``<tag`` on ``line`` and the start-tag text that follows it."""
        source = self.lines[line - 1] if 0 < line <= len(self.lines) else ""
        start = self.cursor.get(line, 0)
        found = source.find("<" + tag, start)
        if found < 0:
            found = max(source.find("<"), 0)
        self.cursor[line] = found + 1
        tail = "\n".join([source[found:], *self.lines[line : line + 40]])
        end = _start_tag_end(tail)
        return Span(self.path, line, found + 1), tail[:end]

    def attribute(self, element_span: Span, start_tag: str, name: str) -> Span:
        """Return the span of ``name="..."`` inside the start tag, or the element's span."""
        match = re.search(r"(?:^|\s)(" + re.escape(name) + r")\s*=\s*(['\"])", start_tag)
        if match is None:
            return element_span
        offset = match.start(1)
        before = start_tag[:offset]
        line = element_span.line + before.count("\n")
        column = (
            element_span.column + offset if "\n" not in before else offset - before.rfind("\n")
        )
        value_end = start_tag.find(match.group(2), match.end())
        end_text = start_tag[:value_end + 1] if value_end >= 0 else start_tag[: match.end()]
        end_line = element_span.line + end_text.count("\n")
        end_column = (
            element_span.column + len(end_text)
            if "\n" not in end_text
            else len(end_text) - end_text.rfind("\n")
        )
        return Span(element_span.file, line, column, end_line, end_column)


def _start_tag_end(text: str) -> int:
    """Return the index just past the ``>`` closing the start tag at the beginning of text."""
    quote = ""
    for index, char in enumerate(text):
        if quote:
            if char == quote:
                quote = ""
        elif char in "\"'":
            quote = char
        elif char == ">":
            return index + 1
    return len(text)


def read_xml(path: Path, data: bytes, sink: ProblemSink) -> Entity | None:
    """Parse XML launch text into the root entity; record problems, never raise."""
    whole = Span.of_file(path)
    if len(data) > MAX_BYTES:
        sink.parse(f"file is larger than {MAX_BYTES // (1024 * 1024)} MiB; not read", whole)
        return None
    declaration = _ENTITY_DECL.search(data)
    if declaration is not None:
        line = data[: declaration.start()].count(b"\n") + 1
        sink.parse("XML entity declarations are not allowed in launch files", Span(path, line))
        return None
    parser = etree.XMLParser(
        resolve_entities=False,
        no_network=True,
        load_dtd=False,
        dtd_validation=False,
        huge_tree=False,
        remove_pis=True,
    )
    try:
        root = etree.fromstring(data, parser=parser)
    except etree.XMLSyntaxError as error:
        line, column = error.position if error.position else (1, 1)
        message = str(error.msg or error).split(" (line")[0]
        sink.parse(f"invalid XML: {message}", Span(path, max(line, 1), max(column, 1)))
        return None
    text = data.decode("utf-8", errors="replace")
    locator = _Locator(path, text)
    return _convert(root, locator)


def _convert(element: etree._Element, locator: _Locator) -> Entity:
    tag = str(element.tag)
    line = element.sourceline
    span, start_tag = locator.element(tag, line if isinstance(line, int) else 1)
    entity = Entity(tag=tag, span=span, format="xml")
    for name, value in element.attrib.items():
        key = str(name)
        entity.attrs[key] = Attr(str(value), locator.attribute(span, start_tag, key))
    children: list[Entity] = []
    for child in element:
        if not isinstance(child.tag, str):
            continue  # comments, entity references
        converted = _convert(child, locator)
        children.append(converted)
        entity.nested.setdefault(converted.tag, []).append(converted)
    entity.child_list = children
    return entity
