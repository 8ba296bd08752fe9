"""Generic walks over IR records: every nested action, every substitution."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator
from functools import cache

from launchverify.ir import actions as a
from launchverify.ir import conditions as c
from launchverify.ir import subst as s


def iter_actions(actions: tuple[a.Action, ...]) -> Iterator[a.Action]:
    """Yield every action, nested ones included (groups, timers, handlers, on_exit)."""
    for action in actions:
        yield action
        yield from iter_actions(action.sub_actions())


def iter_subs(record: object) -> Iterator[s.Sub]:
    """Yield every substitution expression held by a record, at any depth."""
    stack: list[object] = [record]
    while stack:
        item = stack.pop()
        if isinstance(item, s.Sub):
            yield from s.walk(item)
        elif isinstance(item, (a.Action, a.ProcessOptions, a.ComposableNode, a.ParamDict,
                               a.ParamFile, a.ParamItem, a.ParamValue, a.Remap, a.IncludeArg,
                               a.EventHandler, c.Condition)):
            stack.extend(
                getattr(item, f.name) for f in dataclasses.fields(item)  # type: ignore[arg-type]
                if f.name not in ("span", "attr_spans")
            )
        elif isinstance(item, (tuple, list)):
            stack.extend(item)


@cache
def configuration_names(launch: a.LaunchFile) -> frozenset[str]:
    """Return every configuration name a file reads literally (``$(var name)``).

    Cached per parsed file: rules ask for it once per launch the file takes part in.
    """
    names: set[str] = set()
    for action in iter_actions(launch.actions):
        for sub in iter_subs(action):
            if isinstance(sub, s.LaunchConfig) and isinstance(sub.name, s.Text):
                names.add(sub.name.text)
        if isinstance(action.condition, c.ConfigEquals) and isinstance(
            action.condition.name, s.Text
        ):
            names.add(action.condition.name.text)
    return frozenset(names)
