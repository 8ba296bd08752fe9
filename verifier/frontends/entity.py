"""The frontend-neutral view of one XML element or YAML mapping, with source spans.

Mirrors ros2/launch's ``launch.frontend.Entity``: a tag (``type_name``), attributes read by
name, nested entity lists (``<param>``, ``<remap>``...), children (actions of ``<group>``),
and a record of what was read so unread attributes can be reported like launch does.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from launchverify.span import Span

Scalar = str | int | float | bool | None


@dataclass(frozen=True, slots=True)
class Attr:
    """An attribute value as written (text for XML; a YAML scalar or list) and its span.

    ``value_at``: where the value's own text is, when it is written verbatim on one line
    (no entity, escape or alias): its substitutions' literals are then located too.
    """

    value: Scalar | list[Scalar]
    span: Span
    value_at: Span | None = None


@dataclass(eq=False)
class Entity:
    """One entity of a launch file, whatever its format."""

    tag: str
    span: Span
    format: str
    attrs: dict[str, Attr] = field(default_factory=dict)
    nested: dict[str, list[Entity]] = field(default_factory=dict)
    child_list: list[Entity] | None = None
    read: set[str] = field(default_factory=set)
    # every name a handler asked for, written or not: what the tag takes, for the spelling
    # an unread attribute or nested tag may miss
    asked: set[str] = field(default_factory=set)
    asked_nested: set[str] = field(default_factory=set)
    missing: bool = False  # a required attribute is not written (launch stops there)

    def get(self, name: str) -> Attr | None:
        """Return an attribute and mark it read."""
        self.asked.add(name)
        attr = self.attrs.get(name)
        if attr is not None:
            self.read.add(name)
        return attr

    def get_nested(self, name: str) -> list[Entity] | None:
        """Return the nested entities written under ``name`` and mark them read."""
        self.asked_nested.add(name)
        items = self.nested.get(name)
        if items is not None:
            self.read.add(name)
        return items

    def children(self) -> list[Entity]:
        """Return the action children (XML child elements, YAML list or ``children:``)."""
        self.read.add("children")
        if self.format == "xml":
            self.read.update(self.nested)
        return list(self.child_list or [])

    def unread_attributes(self) -> list[str]:
        """Return attribute names never read, in source order."""
        return [n for n in self.attrs if n not in self.read]

    def unread_nested(self) -> list[str]:
        """Return nested tags never read."""
        return [n for n in self.nested if n not in self.read]

    def unwritten(self, *, nested: bool) -> set[str]:
        """Return the attribute (or nested tag) names asked for but not written.

        In YAML both are keys of one mapping, so either kind may misspell the other.
        """
        names = self.asked_nested if nested else self.asked
        if self.format == "yaml":
            names = self.asked | self.asked_nested
        return names - self.attrs.keys() - self.nested.keys()
