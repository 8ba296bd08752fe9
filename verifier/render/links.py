"""Where each rule's documentation lives on the web, for every format that links to it.

The base is the package's "Documentation" project URL (``pyproject.toml``); each rule is
an anchor on that page (``#lv101-duplicate-node-name``, as ``docs/rules.md`` is
generated). Without the metadata (a copy run from sources), there is no link.
"""

from __future__ import annotations

from functools import cache

from launchverify.process.distributions import project_urls as distribution_urls
from launchverify.rule import Rule


@cache
def project_urls() -> dict[str, str]:
    """Return the package's ``Project-URL`` entries by lower-case label (none if absent)."""
    return distribution_urls("launchverify")


def documentation_base() -> str | None:
    """Return the rules page that rule anchors hang off, from the "Documentation" URL."""
    base = project_urls().get("documentation")
    return base.partition("#")[0] if base else None


def help_uri(rule: type[Rule], base: str | None) -> str | None:
    """Return the link to a rule's section: ``<base>#lv101-duplicate-node-name``."""
    return f"{base}#{rule.code.lower()}-{rule.slug}" if base else None


def rule_url(code: str) -> str | None:
    """Return the link to the documentation of the rule with ``code``, if known."""
    from launchverify.registry import rule_of

    base = documentation_base()
    rule = rule_of(code) if base is not None else None
    return help_uri(rule, base) if base is not None and rule is not None else None
