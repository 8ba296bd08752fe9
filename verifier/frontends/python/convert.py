"""Python values built by a launch file, turned into IR.

Launch accepts strings, substitutions and lists of them almost everywhere
(``SomeSubstitutionsType``); parameters take files, dicts and descriptions; remappings are
pairs. ``PythonConverter`` maps each to the IR the XML and YAML frontends produce, turning
placeholders (values only known on the robot) back into symbolic expressions. Each model
object maps to one IR object, so event handlers keep pointing at their target.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping
from typing import Any

from launchverify.frontends.python.locate import CallLocator
from launchverify.frontends.python.sandbox import TimeLimitExceeded
from launchverify.ir import actions as a
from launchverify.ir import conditions as c
from launchverify.ir import subst as s
from launchverify.models.launch_api import base, launch_ros
from launchverify.models.launch_api.placeholders import PATTERN, has_placeholder, parsed, read
from launchverify.models.launch_api.unknown import Opaque, handed
from launchverify.span import Span

Unmodeled = Callable[[str, Span], None]


def placeholder_sub(text: str) -> s.Sub:
    """Return text as an expression, with placeholders as the symbolic values they stand for.

    Text holding a piece of a placeholder (``'⟨env:ROBOT_ID⟩'.split('_')[1]``) is a piece
    of an unknown value: unknown as a whole.
    """
    if not has_placeholder(text):
        return s.Text(text)
    parts: list[s.Sub] = []
    position = 0
    for match in PATTERN.finditer(text):
        found = parsed(match)
        if found is None:
            continue  # brackets of the launch file's own: pieces of an unknown, below
        parts.append(_known(text[position:match.start()]))
        kind, name = found
        if kind == "env":
            variable, equals, default = name.partition("=")
            parts.append(s.EnvVar(s.Text(variable), s.Text(default) if equals else None))
        elif kind in ("pkg", "prefix"):  # the lookup itself was recorded where it was made
            folder = "share folder" if kind == "pkg" else "install prefix"
            parts.append(s.PackageLookup(f"{folder} of {name}", name))
        elif kind == "arg":
            parts.append(s.LaunchConfig(s.Text(name)))
        else:
            parts.append(s.Opaque(name))
        position = match.end()
    parts.append(_known(text[position:]))
    return s.concat(parts)


def _known(text: str) -> s.Sub:
    """Return text between placeholders: a piece of one is unknown."""
    return s.Opaque("a part of an unknown value") if has_placeholder(text) else s.Text(text)


# The attribute an exception raised while an action becomes IR carries: the action's span
# (the model's own frames are not the launch file's, so the traceback names no line).
BLAMED = "_launchverify_blamed_span"


class Converted:
    """The records model objects became, by the object's id (kept alive while they count).

    Shared by the conversions of one launch file (its description, each OpaqueFunction's
    result): an object met again is its record again, as launch compares actions by
    identity (an event handler's target).
    """

    def __init__(self) -> None:
        self.records: dict[int, a.Action | None] = {}
        self.kept: list[Any] = []  # the objects whose ids are keys


class PythonConverter:
    """Implements ``launch_api.base.Converter`` for one launch file."""

    def __init__(self, unmodeled: Unmodeled, opaque_function: Callable[[Any], a.Action],
                 fallback: Span, fail: Unmodeled | None = None, context: Any = None,
                 converted: Converted | None = None) -> None:
        self._unmodeled = unmodeled
        self.context = context  # the concrete LaunchContext, inside an OpaqueFunction
        self._fail = fail or unmodeled
        self._fallback = fallback  # where to point when an object knows no line
        self._claimed: set[int] = set()  # description sources already used by an include
        self._opaque_function = opaque_function
        converted = converted or Converted()
        self._memo = converted.records
        self._keep = converted.kept  # keep converted objects alive while their id is a key
        self._locator = CallLocator()
        self.handed: list[a.Action] = []  # actions given to code launchverify cannot see

    # ------------------------------------------------------------------ values

    def sub(self, value: Any) -> s.Sub:
        if isinstance(value, s.Sub):
            return value
        if isinstance(value, base.Substitution):
            return value.to_sub(self)
        if isinstance(value, str):
            return placeholder_sub(value)
        if isinstance(value, os.PathLike):
            return placeholder_sub(os.fspath(value))
        if isinstance(value, (list, tuple)):
            return s.concat([self.sub(item) for item in value])
        if isinstance(value, (set, frozenset)):  # launch iterates it as a list would be
            items = list(value)
            if len(items) == 1:  # ``{path}``: the path
                return self.sub(items[0])
            return s.Opaque("<the items of a set, in an order no run fixes>")
        if isinstance(value, bool):
            return s.Text("true" if value else "false")
        if isinstance(value, (int, float)):
            return s.Text(str(value))
        if value is None:
            return s.Text("")
        return placeholder_sub(str(value))

    def performed(self, value: base.Substitution) -> s.Sub | None:
        """Perform a launch file's own Substitution subclass, where a context is concrete.

        Inside an OpaqueFunction the configurations have values, so the subclass's
        ``perform`` gives the text launch would use; elsewhere it stays unknown.
        """
        if self.context is None or type(value).perform is base.Substitution.perform:
            return None
        try:
            result = value.perform(self.context)
        except TimeLimitExceeded:
            raise
        except Exception:  # the user's code: what it would give is unknown here
            return None
        return placeholder_sub(result) if isinstance(result, str) else None

    def opt_sub(self, value: Any) -> s.Sub | None:
        return None if value is None else self.sub(value)

    def condition(self, value: Any) -> c.Condition | None:
        if value is None:
            return None
        if isinstance(value, base.Condition):
            return value.to_condition(self)
        if isinstance(value, Opaque):
            return c.OpaqueCondition(f"condition {read(str(value))}, of code launchverify "
                                     "cannot see")
        return c.OpaqueCondition(f"condition {type(value).__name__}")

    def keyword_keys(self, call: Span, keyword: str) -> dict[str, Span]:
        return self._locator.keyword_keys(call, keyword)

    def keyword_values(self, call: Span) -> dict[str, Span]:
        return self._locator.keyword_values(call)

    def written(self, call: Span, value: Any, *, position: int | None = None,
                keyword: str | None = None, item: int | None = None,
                items: int | None = None) -> s.Sub:
        sub = self.sub(value)
        if isinstance(value, str) and sub == s.Text(value):
            where = self._locator.literal(call, value, position=position, keyword=keyword,
                                          item=item, items=items)
            if where is not None:
                return s.Text(value, where)
        return sub

    def written_key(self, call: Span, keyword: str, key: Any) -> s.Sub:
        sub = self.sub(key)
        if isinstance(key, str) and sub == s.Text(key):
            where = self._locator.key_literal(call, keyword, key)
            if where is not None:
                return s.Text(key, where)
        return sub

    def pairs(self, value: Any) -> tuple[tuple[s.Sub, s.Sub], ...]:
        items = value.items() if isinstance(value, Mapping) else value
        return tuple((self.sub(k), self.sub(v)) for k, v in items)

    # ------------------------------------------------------------------ actions

    def action(self, entity: Any) -> a.Action | None:
        key = id(entity)
        if key in self._memo:
            return self._memo[key]
        self._memo[key] = None  # a cycle through handlers resolves to nothing
        self._keep.append(entity)
        if isinstance(entity, base.LaunchDescriptionEntity):
            try:
                result = entity.to_ir(self)
            except Exception as error:  # launch rejects a value: blame the action's line
                del self._memo[key]  # (another conversion may meet it again)
                span = getattr(entity, "_span", None)
                if isinstance(span, Span) and not hasattr(error, BLAMED):
                    setattr(error, BLAMED, span)
                raise
            if result is not None and handed(entity):
                self.handed.append(result)
        elif isinstance(entity, Opaque):  # what it does is unknown: declare, set, start
            made = entity._span if isinstance(entity._span, Span) else self._fallback
            self._unmodeled(f"{read(str(entity))} is an action of code launchverify cannot "
                            "see; what it does is unknown", made)
            result = a.OpaqueAction(span=made, description=read(str(entity)))
        else:
            result = None
            span = getattr(entity, "_span", None)
            what = getattr(entity, "_description", None) or type(entity).__name__
            self._unmodeled(f"{what} is not a launch entity launchverify models",
                            span if isinstance(span, Span) else self._fallback)
        self._memo[key] = result
        return result

    def actions(self, entities: Any) -> tuple[a.Action, ...]:
        out = []
        for entity in base.flatten(entities if isinstance(entities, (list, tuple)) else
                                   [entities]):
            if entity is None:
                continue
            result = self.action(entity)
            if result is not None:
                out.append(result)
        return tuple(out)

    def claim(self, source: Any) -> bool:
        """Return ``False`` when an include reuses another include's description source."""
        if id(source) in self._claimed:
            return False
        self._claimed.add(id(source))
        self._keep.append(source)
        return True

    def fail(self, message: str, span: Span) -> None:
        """Record that the launch would raise here (LV002)."""
        self._fail(message, span)

    def opaque_function(self, function: Any) -> a.Action:
        """Return the IR of an OpaqueFunction (runs later, with a concrete context)."""
        return self._opaque_function(function)

    # ------------------------------------------------------------------ node pieces

    def parameters(self, value: Any, span: Span) -> tuple[a.ParamEntry, ...]:
        out: list[a.ParamEntry] = []
        # a vendor's list holds parameters nobody can list: one unknown entry, not none
        items = [value] if isinstance(value, Opaque) else list(value or [])
        written = self._locator.keyword_items(span, "parameters")
        if len(written) != len(items):
            written = [(span, {})] * len(items)  # not written out: the call it is in
        for item, (item_span, keys) in zip(items, written, strict=True):
            own = getattr(item, "_span", None)
            where = own if isinstance(own, Span) else item_span
            if isinstance(item, launch_ros.ParameterFile):
                allow = item.allow_substs
                out.append(a.ParamFile(path=self.sub(item.param_file), span=item._span,
                                       allow_substs=allow if isinstance(allow, bool)
                                       else self.sub(allow)))
            elif isinstance(item, Mapping):
                out.append(a.ParamDict(items=tuple(self._items(item, (), where, keys)),
                                       span=where))
            elif isinstance(item, launch_ros.Parameter):
                out.append(a.ParamDict(items=(a.ParamItem(
                    name=self.sub(item.name), value=self.param_value(item.value),
                    span=item._span),), span=item._span))
            else:
                out.append(a.ParamFile(path=self.sub(item), span=where))
        return tuple(out)

    def _items(self, mapping: Mapping[Any, Any], prefix: tuple[s.Sub, ...],
               span: Span, keys: Mapping[str, Span] | None = None) -> list[a.ParamItem]:
        """Flatten a parameter dict; ``keys``: where its top-level keys are written."""
        out: list[a.ParamItem] = []
        for key, value in mapping.items():
            name = (*prefix, self.sub(key))
            here = (keys or {}).get(key, span) if isinstance(key, str) else span
            if isinstance(value, Mapping):
                out.extend(self._items(value, name, here))
                continue
            dotted: list[s.Sub] = []
            for index, part in enumerate(name):
                if index:
                    dotted.append(s.Text("."))
                dotted.append(part)
            out.append(a.ParamItem(name=s.concat(dotted), value=self.param_value(value),
                                   span=here))
        return out

    def param_value(self, value: Any) -> a.ParamValue:
        """Return a parameter value; plain ``str`` stays text, substitutions get YAML rules.

        Also inside ``ParameterValue``: ``ParameterValue('7')`` reaches the node as the
        string ``'7'`` (checked against launch_ros).
        """
        if isinstance(value, launch_ros.ParameterValue):
            value_type = value.value_type
            name = getattr(value_type, "__name__", None) if value_type is not None else None
            inner = self.param_value(value.value)
            return a.ParamValue(value=inner.value, value_type=name or (
                str(value_type) if value_type else inner.value_type))
        if isinstance(value, Opaque):  # any value, of any type
            return a.ParamValue(value=self.sub(value))
        if isinstance(value, (bool, int, float)) or value is None:
            return a.ParamValue(value=value)
        if isinstance(value, str):
            return self.plain_text(value)
        if isinstance(value, (list, tuple)) and not any(
            isinstance(item, base.Substitution) for item in value
        ) and all(isinstance(item, (bool, int, float, str)) for item in value):
            return a.ParamValue(value=tuple(
                self.plain_text(item).value if isinstance(item, str) else item
                for item in value), value_type="str")
        return a.ParamValue(value=self.sub(value))

    def plain_text(self, text: str) -> a.ParamValue:
        """A Python ``str`` reaches the node as a string, never YAML-parsed."""
        if has_placeholder(text):  # computed from values we only know symbolically
            return a.ParamValue(value=self.sub(text), value_type="str")
        return a.ParamValue(value=text)

    def remaps(self, value: Any, span: Span) -> tuple[a.Remap, ...]:
        """Return the rules of ``remappings=``, each at its own pair where the list is written.

        ``remappings=[('/scan', 'scan_raw')]`` puts the rule at the tuple, as XML's
        ``<remap>`` has its own line; a list built at run time leaves them at the call.
        """
        pairs = list(value or [])
        written = [where for where, _ in self._locator.keyword_items(span, "remappings")]
        if len(written) != len(pairs):
            written = [span] * len(pairs)
        out = []
        for pair, where in zip(pairs, written, strict=True):
            try:
                src, dst = pair
            except (TypeError, ValueError):
                self._unmodeled(f"remapping {pair!r} is not a (from, to) pair", where)
                continue
            out.append(a.Remap(src=self.sub(src), dst=self.sub(dst), span=where,
                               call=None if where == span else span))
        return tuple(out)

    def unmodeled(self, what: str, span: Span) -> None:
        self._unmodeled(what, span)
