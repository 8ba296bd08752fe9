"""Read a ``.launch.xml`` file into entities, safely and with line and column spans.

lxml is configured so that nothing outside the file is ever read: no DTD loading, no
network, no entity expansion; documents that declare entities are refused outright, which
defuses entity bombs. lxml reports only the line of an element, so columns of tags and
attributes are recovered from the source text.
"""

from __future__ import annotations

import bisect
import re
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

from lxml import etree

from launchverify.frontends.entity import Attr, Entity
from launchverify.problems import ProblemSink
from launchverify.span import Span
from launchverify.workspace.reading import long_number, long_number_message

_ENTITY_DECL = re.compile(rb"<!ENTITY", re.IGNORECASE)


_PREDEFINED_ENTITIES = frozenset({"lt", "gt", "amp", "quot", "apos"})
_ENTITY_REF = re.compile(r"&([A-Za-z_][\w.-]*);")
_TAG_REST = re.compile(r"""[^"'>]*(?:(?:"[^"]*"|'[^']*')[^"'>]*)*>""")  # up to the closing >
_TAG_NAME = re.compile(r"[^\s/>]*")
_ATTRIBUTE = re.compile(r"""([^\s=/>]+)\s*=\s*(?:"([^"]*)"|'([^']*)')""")


@dataclass(frozen=True, slots=True)
class _StartTag:
    """Offsets of one start tag in the source text, and of its attributes."""

    start: int
    end: int
    attributes: dict[str, tuple[int, int]]
    values: dict[str, tuple[int, int]]  # each attribute's text between its quotes


def scan_start_tags(text: str) -> list[_StartTag]:
    """Return every start tag in document order, skipping comments, CDATA and the like.

    lxml reports only the line where a start tag ends; this scan gives the exact start of
    each element and of each attribute, in the same order as the elements lxml yields.
    """
    tags: list[_StartTag] = []
    index = text.find("<")
    while index >= 0:
        if text.startswith("<!--", index):
            close = text.find("-->", index + 4)
            index = text.find("<", close + 3 if close >= 0 else len(text))
            continue
        if text.startswith("<![CDATA[", index):
            close = text.find("]]>", index)
            index = text.find("<", close + 3 if close >= 0 else len(text))
            continue
        if text.startswith("<!", index):
            index = text.find("<", _declaration_end(text, index))
            continue
        if text.startswith("<?", index):
            close = text.find("?>", index)
            index = text.find("<", close + 2 if close >= 0 else len(text))
            continue
        end = _start_tag_end(text, index)
        if not text.startswith("</", index):
            body = text[index:end]
            name = _TAG_NAME.match(text, index + 1, end)
            name_end = name.end() if name is not None else index + 1
            matches = list(_ATTRIBUTE.finditer(body, name_end - index))
            attributes = {match.group(1): (index + match.start(1), index + match.end())
                          for match in matches}
            values = {match.group(1): (index + match.end() - 1 - len(_quoted(match)),
                                       index + match.end() - 1) for match in matches}
            tags.append(_StartTag(index, end, attributes, values))
        index = text.find("<", end)
    return tags


def _quoted(match: re.Match[str]) -> str:
    """Return the text between an attribute's quotes."""
    double = match.group(2)
    return double if double is not None else match.group(3)


def _declaration_end(text: str, index: int) -> int:
    """Return the end of ``<!DOCTYPE ...>``, including a bracketed internal subset."""
    depth = 0
    for position in range(index + 2, len(text)):
        char = text[position]
        if char == "[":
            depth += 1
        elif char == "]":
            depth -= 1
        elif char == ">" and depth <= 0:
            return position + 1
    return len(text)


def _start_tag_end(text: str, index: int) -> int:
    """Return the index just past the ``>`` that closes the tag starting at ``index``.

    A ``>`` inside a quoted attribute value does not close it; without a closing ``>``
    (an unclosed quote) the tag runs to the end of the text.
    """
    match = _TAG_REST.match(text, index + 1)
    return match.end() if match is not None else len(text)


class _Locator:
    """Turns text offsets into spans."""

    def __init__(self, path: Path, text: str) -> None:
        self.path = path
        self.line_starts = [0]
        for match in re.finditer("\n", text):
            self.line_starts.append(match.end())

    def span(self, start: int, end: int | None = None) -> Span:
        """Return the span between two offsets."""
        line = bisect.bisect_right(self.line_starts, start)
        column = start - self.line_starts[line - 1] + 1
        if end is None:
            return Span(self.path, line, column)
        end_line = bisect.bisect_right(self.line_starts, end)
        return Span(self.path, line, column, end_line, end - self.line_starts[end_line - 1] + 1)


def read_xml(path: Path, data: bytes, sink: ProblemSink) -> Entity | None:
    """Parse XML launch text into the root entity; record problems, never raise."""
    long = long_number(data)
    if long is not None:
        sink.parse(long_number_message(long[1]), Span(path, long[0]))
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
    undefined = _undefined_entity(text)
    if undefined is not None:
        name, offset = undefined
        line = text.count("\n", 0, offset) + 1
        sink.parse(f"undefined XML entity &{name};", Span(path, line))
        return None
    locator = _Locator(path, text)
    elements = [e for e in root.iter() if isinstance(e.tag, str)]
    tags = scan_start_tags(text)
    if len(tags) != len(elements):  # should not happen; fall back to lxml's lines
        tags = []
    return _convert(root, locator, iter(zip(elements, tags, strict=False)) if tags else None,
                    text)


def _undefined_entity(text: str) -> tuple[str, int] | None:
    """Return the first reference to an entity XML does not predefine, outside comments."""
    for match in _ENTITY_REF.finditer(_blank_comments(text)):
        if match.group(1) not in _PREDEFINED_ENTITIES:
            return match.group(1), match.start()
    return None


def _blank_comments(text: str) -> str:
    """Return ``text`` with comments blanked (same offsets), in one linear pass.

    (A regular expression ``<!--.*?-->`` is quadratic on a text with many ``<!--`` and no
    ``-->``, such as a CDATA section holding them.)
    """
    parts = []
    position = 0
    while True:
        start = text.find("<!--", position)
        if start < 0:
            break
        end = text.find("-->", start + 4)
        if end < 0:
            break
        parts += [text[position:start], " " * (end + 3 - start)]
        position = end + 3
    parts.append(text[position:])
    return "".join(parts)


def _convert(
    element: etree._Element,
    locator: _Locator,
    tags: Iterator[tuple[etree._Element, _StartTag]] | None,
    text: str,
) -> Entity:
    tag = str(element.tag)
    start_tag = None
    if tags is not None:
        matched, start_tag = next(tags)
        assert matched is element
    if start_tag is None:
        line = element.sourceline if isinstance(element.sourceline, int) else 1
        span = Span(locator.path, line)
    else:
        span = locator.span(start_tag.start, start_tag.end)
    entity = Entity(tag=tag, span=span, format="xml")
    for name, value in element.attrib.items():
        key = str(name)
        where = start_tag.attributes.get(key) if start_tag is not None else None
        inside = start_tag.values.get(key) if start_tag is not None else None
        verbatim = inside is not None and text[inside[0]:inside[1]] == str(value) \
            and "\n" not in str(value)
        entity.attrs[key] = Attr(str(value), locator.span(*where) if where else span,
                                 locator.span(*inside) if inside and verbatim else None)
    children: list[Entity] = []
    for child in element:
        if not isinstance(child.tag, str):
            continue  # comments, processing instructions
        converted = _convert(child, locator, tags, text)
        children.append(converted)
        entity.nested.setdefault(converted.tag, []).append(converted)
    entity.child_list = children
    return entity
