"""Hover texts (Markdown): a finding with its rule's explanation, a launch argument.

A finding shows what ``check --explain`` prints under it: the argument values that make
it happen, the include chain that reached the file, why the rule matters and how to fix
it. A ``$(var name)`` shows the argument's declaration: default, description, choices,
and the value it has as checked.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from pathlib import Path

from launchverify.graph import ArgumentRecord, LaunchGraph
from launchverify.lsp.lookup import INCLUDE, PARAMETER_FILE, Reference
from launchverify.registry import rule_of
from launchverify.rule import Finding
from launchverify.span import Span

Display = Callable[[Path], str]


def _place(span: Span, display: Display) -> str:
    return f"`{display(span.file)}:{span.line}`"


def finding_text(finding: Finding, display: Display) -> str:
    """Return the hover text of one finding."""
    parts = [f"**{finding.code}** `{finding.slug}` ({finding.severity.value})",
             finding.message]
    if finding.witness:
        values = " ".join(f"{k}:={v}" for k, v in sorted(finding.witness.items()))
        parts.append(f"**When:** `{values}`")
    if finding.chain:
        chain = " ← ".join(_place(span, display) for span in reversed(finding.chain))
        parts.append(f"**Included from:** {chain}")
    for related in finding.related:
        parts.append(f"*{related.message}:* {_place(related.span, display)}")
    rule = rule_of(finding.code)
    if rule is not None:
        parts.append(f"*{rule.summary()}*")
        for heading in ("Why it matters", "Fix"):
            body = rule.section(heading)
            if body:
                parts.append(f"**{heading}:** {body}")
        parts.append(f"`launchverify explain {finding.code}` prints the whole rule.")
    return "\n\n".join(parts)


def reference_text(reference: Reference, display: Display) -> str | None:
    """Return the hover text of a launch argument or a file reference (``None``: nothing)."""
    if reference.kind in (INCLUDE, PARAMETER_FILE) and reference.file is not None:
        what = "Includes" if reference.kind == INCLUDE else "Parameter file"
        return f"{what} `{display(reference.file)}`"
    if reference.name is None:
        return None
    if not reference.declarations:
        lets = "".join(f"\n\nset at {_place(s.span, display)}" for s in reference.settings)
        return f"launch configuration `{reference.name}`, declared by no argument{lets}"
    parts = []
    for record in reference.declarations:
        lines = [f"launch argument `{record.name}` (declared at "
                 f"{_place(record.origin.span, display)})"]
        if record.description:
            lines.append(record.description)
        default = "none: it must be given" if record.default is None else \
            f"`{record.default.describe()}`"
        lines.append(f"**Default:** {default}")
        if record.choices:
            lines.append("**Choices:** " + ", ".join(f"`{c}`" for c in record.choices))
        value = _value(reference.graphs, record)
        if value is not None:
            lines.append(f"**Value with the arguments as given:** `{value}`")
        parts.append("\n\n".join(lines))
    return "\n\n---\n\n".join(parts)


def _value(graphs: Sequence[LaunchGraph], declared: ArgumentRecord) -> str | None:
    """Return the argument's value under the arguments as given (each root's, if they differ)."""
    values = {graph.base(record.value) for graph in graphs for record in graph.arguments
              if record.origin.span == declared.origin.span}
    known = sorted(value for value in values if value is not None)
    return "` or `".join(known) if known else None


def join(texts: Sequence[str | None]) -> str | None:
    """Return hover texts as one (``None`` when there is none)."""
    kept = [text for text in texts if text]
    return "\n\n---\n\n".join(kept) if kept else None
