"""Reading attributes of frontend entities the way ros2/launch's frontends do.

Strings become substitution expressions; typed attributes follow launch's coercion (XML:
YAML rules plus ``'1'``/``'0'``, a string kept when it cannot be converted; YAML: the
value's own type, strings always accepted). Everything that goes wrong is recorded as a
problem with the span of the offending attribute.
"""

from __future__ import annotations

import re
import shlex
from collections.abc import Callable
from pathlib import Path

import yaml

from launchverify.frontends.entity import Attr, Entity
from launchverify.frontends.subst_parser import (
    SubstitutionSyntaxError,
    parse_substitution,
    unescape,
)
from launchverify.ir import subst as s
from launchverify.ir.conditions import Condition, IfCondition, UnlessCondition
from launchverify.problems import ProblemSink
from launchverify.span import Span
from launchverify.suggest import edit_distance, typos


class MissingAttribute(Exception):
    """A required attribute is absent; the entity is skipped after a problem is recorded."""


class EntityReader:
    """Typed attribute access with problem recording, shared by every tag handler."""

    def __init__(self, path: Path, sink: ProblemSink) -> None:
        self.path = path
        self.sink = sink

    # ------------------------------------------------------------------ substitutions

    def parse_text(self, text: str, span: Span, written: Span | None = None) -> s.Sub:
        """Parse ``$(...)`` in text; a syntax error becomes a problem and an opaque value.

        ``written``: where ``text`` itself is, verbatim on one line; its literals are
        then located (``Text.where``).
        """
        try:
            return parse_substitution(text, None if written is None else _locator(written))
        except SubstitutionSyntaxError as error:
            self.sink.parse(f"invalid substitution in {text!r}: {error}", span)
            return s.Opaque(f"unparsable {text!r}")

    def sub(self, entity: Entity, name: str, *, required: bool = False) -> s.Sub | None:
        """Read a string attribute that may contain substitutions."""
        attr = self._attr(entity, name, required)
        if attr is None:
            return None
        text = self._string(entity, name, attr)
        return None if text is None else self.parse_text(text, attr.span, attr.value_at)

    def req(self, entity: Entity, name: str) -> s.Sub:
        """Read a required substitution attribute (raises ``MissingAttribute`` if absent)."""
        value = self.sub(entity, name, required=True)
        if value is None:
            raise MissingAttribute(name)
        return value

    def plain(self, entity: Entity, name: str, *, required: bool = False) -> str | None:
        """Read a string attribute that is not substituted, only unescaped (arg names)."""
        attr = self._attr(entity, name, required)
        if attr is None:
            return None
        text = self._string(entity, name, attr)
        if text is None:
            if required:
                raise MissingAttribute(name)
            return None
        return unescape(text)

    def cmdline(self, entity: Entity, name: str, *, required: bool = False) -> tuple[s.Sub, ...]:
        """Read a command line (``cmd``, ``args``, ``ros_args``) split as launch splits it."""
        attr = self._attr(entity, name, required)
        if attr is None:
            return ()
        text = self._string(entity, name, attr)
        if text is None:
            return ()
        parsed = self.parse_text(text, attr.span, attr.value_at)
        try:
            return split_cmdline(parsed)
        except ValueError as error:
            self.sink.parse(f"cannot split `{name}` like a shell line: {error}", attr.span)
            return (parsed,)

    # ------------------------------------------------------------------ typed values

    def typed(self, entity: Entity, name: str, kind: type) -> object:
        """Read a typed attribute (bool, int or float) with launch's coercion rules.

        Returns ``None`` when absent; a ``str`` when the text cannot be converted and launch
        keeps it as a string (a non-empty string is truthy where launch tests truthiness).
        """
        attr = entity.get(name)
        if attr is None:
            return None
        value = attr.value
        if entity.format == "yaml":
            if isinstance(value, str) or (isinstance(value, kind) and not (
                kind is int and isinstance(value, bool)
            )):
                return value
            if kind is float and isinstance(value, int) and not isinstance(value, bool):
                return float(value)
            self._type_error(entity, name, attr, kind.__name__)
            return None
        text = str(value)
        if kind is bool:
            text = {"1": "true", "0": "false"}.get(text, text)
            try:
                loaded = yaml.safe_load(text) if text else text
            except yaml.YAMLError:
                return text
            return loaded if isinstance(loaded, bool) else text
        try:
            return kind(text)
        except ValueError:
            return text

    def number(self, entity: Entity, name: str, kind: type, *, minimum: float | None = None
               ) -> float | int | None:
        """Read a float/int attribute that launch converts at parse time (no substitutions)."""
        value = self.typed(entity, name, kind)
        if value is None:
            return None
        attr = entity.attrs[name]
        if isinstance(value, str):
            self._type_error(entity, name, attr, kind.__name__)
            return None
        assert isinstance(value, (int, float))
        if minimum is not None and value < minimum:
            self.sink.parse(
                f"`{name}` of `{entity.tag}` must be non-negative, got {value}", attr.span
            )
            return None
        return value

    def flag(self, entity: Entity, name: str) -> bool | None:
        """Read a bool attribute that is not substituted (``scoped``, ``shell``).

        A value launch cannot convert stays a non-empty string, which launch treats as true.
        """
        value = self.typed(entity, name, bool)
        if value is None:
            return None
        return bool(value)

    def sub_or_bool(self, entity: Entity, name: str) -> s.Sub | bool | None:
        """Read a bool attribute that also accepts substitutions (``respawn``, ``prepend``)."""
        value = self.typed(entity, name, bool)
        if value is None or isinstance(value, bool):
            return value
        return self.parse_text(str(value), entity.attrs[name].span)

    # ------------------------------------------------------------------ structure

    def condition(self, entity: Entity) -> Condition | None:
        """Read ``if``/``unless``; both together is a load error in launch."""
        if_value = self.sub(entity, "if")
        unless_value = self.sub(entity, "unless")
        if if_value is not None and unless_value is not None:
            self.sink.parse(
                "`if` and `unless` cannot be used together (ros2 launch refuses the file)",
                entity.attrs["unless"].span,
            )
            return IfCondition(if_value)
        if if_value is not None:
            return IfCondition(if_value)
        if unless_value is not None:
            return UnlessCondition(unless_value)
        return None

    def spans(self, entity: Entity) -> dict[str, Span]:
        """Return the span of every attribute of the entity."""
        return {name: attr.span for name, attr in entity.attrs.items()}

    def finish(self, entity: Entity) -> None:
        """Report attributes and nested tags that no handler read, as launch does.

        Not after a required attribute was missing: launch stops there.
        """
        if entity.missing:
            return
        for name in entity.unread_attributes():
            self.sink.parse(
                f"unexpected attribute `{name}` in `{entity.tag}` (ros2 launch refuses it)"
                f"{_spelling(name, entity.unwritten(nested=False))}",
                entity.attrs[name].span,
            )
        for name in entity.unread_nested():
            if name == "children":
                continue
            first = entity.nested[name][0]
            word = "nested tag" if entity.format == "xml" else "key"
            self.sink.parse(
                f"unexpected {word} `{name}` in `{entity.tag}` (ros2 launch refuses it)"
                f"{_spelling(name, entity.unwritten(nested=True))}",
                first.span,
            )
        if entity.child_list and "children" not in entity.read and entity.format == "yaml":
            self.sink.parse(f"`{entity.tag}` does not take children", entity.span)

    # ------------------------------------------------------------------ internals

    def _attr(self, entity: Entity, name: str, required: bool) -> Attr | None:
        attr = entity.get(name)
        if attr is None and required:
            # launch stops at the first attribute missing: the unread ones go unreported,
            # and one that misspells it is named here
            entity.missing = True
            written = [other for other in entity.attrs
                       if other not in entity.read and misspelt(other, {name})]
            hint = f"; `{written[0]}` may misspell it" if written else ""
            self.sink.parse(f"`{entity.tag}` requires the attribute `{name}`{hint}",
                            entity.span)
            raise MissingAttribute(name)
        return attr

    def _string(self, entity: Entity, name: str, attr: Attr) -> str | None:
        if isinstance(attr.value, str):
            return attr.value
        self._type_error(entity, name, attr, "str")
        return None

    def _type_error(self, entity: Entity, name: str, attr: Attr, expected: str) -> None:
        got = type(attr.value).__name__
        hint = " (quote it)" if entity.format == "yaml" and expected == "str" else ""
        self.sink.parse(
            f"attribute `{name}` of `{entity.tag}` must be {expected}, "
            f"got {got} {attr.value!r}{hint}",
            attr.span,
        )


def misspelt(name: str, known: set[str]) -> list[str]:
    """Return the names of a tag that ``name`` may misspell, likeliest first.

    ``typos``' candidates, and any one edit away: a tag takes a handful of names, so a
    swap of neighbours in a short one (``nmae``), which ``typos`` leaves out, is meant too.

    Examples:
        >>> misspelt("nmae", {"name", "namespace", "exec"}), misspelt("colour", {"name"})
        (['name'], [])
    """
    found = typos(name, known)
    found += sorted(c for c in known - set(found) if edit_distance(name, c, 1) <= 1)
    return found


def _spelling(name: str, known: set[str]) -> str:
    """Return ``"; did you mean `x`?"`` for the names ``name`` may misspell, or nothing."""
    found = misspelt(name, known)
    if not found:
        return ""
    return f"; did you mean {' or '.join(f'`{candidate}`' for candidate in found[:3])}?"


def _words(part: s.Text) -> list[s.Text]:
    """Return literal text shell-split, each word located when the text is and it can be."""
    where = part.where
    words = shlex.split(part.text)
    if where is None or where.end_line not in (None, where.line) or any(
            mark in part.text for mark in "'\"\\"):
        return [s.Text(word) for word in words]
    located = list(re.finditer(r"\S+", part.text))
    return [s.Text(m.group(), Span(where.file, where.line, where.column + m.start(),
                                   where.line, where.column + m.end())) for m in located]


def _locator(written: Span) -> Callable[[int, int], Span]:
    """Return where offsets of a text written verbatim on one line, at ``written``, are."""
    def locate(start: int, end: int) -> Span:
        return Span(written.file, written.line, written.column + start, written.line,
                    written.column + end)

    return locate


def split_cmdline(parsed: s.Sub) -> tuple[s.Sub, ...]:
    """Split a parsed command line into argv entries like launch's ``_parse_cmdline``.

    Literal text is shell-split; a substitution sticks to the text beside it unless
    whitespace separates them. A word of located text with no quote or escape in it
    keeps its place (``Text.where``).
    """
    parts = parsed.parts if isinstance(parsed, s.Concat) else (parsed,)
    result: list[list[s.Sub]] = []
    arg: list[s.Sub] = []

    def flush() -> None:
        nonlocal arg
        result.append(arg)
        arg = []

    for part in parts:
        if not isinstance(part, s.Text):
            arg.append(part)
            continue
        if not part.text:
            continue
        tokens = _words(part)
        if not tokens:
            flush()
            continue
        if part.text[0].isspace() and arg:
            flush()
        arg.append(tokens[0])
        if len(tokens) > 1:
            flush()
            arg.append(tokens[-1])
        if len(tokens) > 2:
            result.extend([t] for t in tokens[1:-1])
        if part.text[-1].isspace():
            flush()
    if arg:
        result.append(arg)
    return tuple(s.concat(a) for a in result)
