"""The rule registry: built-in rules plus ``launchverify.rules`` entry points.

Codes and slugs are unique; ``resolve`` accepts either (``LV101`` or
``duplicate-node-name``), and a family prefix such as ``LV1`` for selection.
"""

from __future__ import annotations

from functools import cache
from typing import Any

from launchverify.rule import Rule


class RegistryError(ValueError):
    """Two rules claim one code or slug, or a selector names no rule."""


@cache
def all_rules() -> tuple[type[Rule], ...]:
    """Return every rule class, built-in first, sorted by code."""
    from launchverify.rules import BUILTIN

    rules: list[type[Rule]] = list(BUILTIN)
    from launchverify.process.distributions import entry_points, load

    for _name, reference in entry_points("launchverify.rules"):
        loaded: Any = load(reference)
        rules.extend(loaded if isinstance(loaded, (list, tuple)) else [loaded])
    seen: dict[str, type[Rule]] = {}
    for rule in rules:
        for key in (rule.code, rule.slug):
            if key in seen and seen[key] is not rule:
                raise RegistryError(
                    f"{key} is claimed by {seen[key].__name__} and {rule.__name__}"
                )
            seen[key] = rule
    return tuple(sorted(set(rules), key=lambda r: r.code))


def resolve(selector: str) -> list[type[Rule]]:
    """Return the rules a selector names: a code, a slug, or a code prefix like ``LV2``."""
    wanted = selector.strip()
    rules = all_rules()
    exact = [r for r in rules if wanted in (r.code, r.slug)]
    if exact:
        return exact
    prefixed = [r for r in rules if wanted and r.code.startswith(wanted.upper())]
    if prefixed:
        return prefixed
    raise RegistryError(f"no rule is called {selector!r}")


def rule_of(code: str) -> type[Rule] | None:
    """Return the rule that reports a code (``None`` for a code no rule has any more)."""
    try:
        found = resolve(code)
    except RegistryError:
        return None
    return next((rule for rule in found if rule.code == code), None)


def select(select: list[str] | None, ignore: list[str] | None) -> list[type[Rule]]:
    """Return the enabled rules for ``--select``/``--ignore`` lists."""
    chosen = all_rules() if not select else tuple(
        {r: None for s in select for r in resolve(s)}
    )
    dropped = {r for s in ignore or [] for r in resolve(s)}
    return [r for r in chosen if r not in dropped]
