"""Small HTML helpers shared by the report's sections.

Everything the report shows that comes from a launch file, a parameter file or a path goes
through ``esc``: names, values and messages are attacker-controlled text as far as the
browser is concerned.
"""

from __future__ import annotations

import html
from collections import Counter
from collections.abc import Iterable
from pathlib import Path

from launchverify.engine import Report
from launchverify.render.inert import inert_block
from launchverify.span import Span


def esc(value: object) -> str:
    """Return ``value`` as text safe in HTML and SVG content and quoted attributes.

    Control characters and bidi overrides are shown visibly (``inert_block``): they
    could reorder what a reviewer reads.
    """
    return html.escape(inert_block(str(value)), quote=True)


def num(value: float) -> str:
    """Return a coordinate for SVG: one decimal, none when it is whole (``12``, ``12.5``)."""
    text = f"{value:.1f}"
    return text[:-2] if text.endswith(".0") else text


def clip(text: str, limit: int) -> str:
    """Return ``text`` cut to ``limit`` characters, marked with an ellipsis when cut."""
    return text if len(text) <= limit else text[: max(limit - 1, 0)] + "\u2026"


def where(report: Report, span: Span | None) -> str:
    """Return ``file:line`` as the user knows the file (plain text, not escaped)."""
    if span is None:
        return ""
    return f"{report.display_path(span.file)}:{span.line}"


def place(report: Report, file: Path, line: int | None) -> str:
    """Return an escaped ``file:line`` element for a location."""
    text = report.display_path(file) + (f":{line}" if line is not None else "")
    return f'<span class="loc">{esc(text)}</span>'


def short_place(text: str, parts: int = 3) -> str:
    """Return an escaped ``…/pkg/launch/name:line`` for a ``path:line``, all on hover.

    The last ``parts`` components tell files of one name apart (every package has its
    ``robot.launch.xml``) and keep table columns narrow.
    """
    pieces = text.replace("\\", "/").split("/")
    short = "/".join(pieces[-parts:])
    if len(pieces) > parts:
        short = "\u2026/" + short
    return f'<span class="loc" title="{esc(text)}">{esc(short)}</span>'


def distinct_tails(paths: Iterable[str]) -> dict[str, str]:
    """Return each path's shortest ending no other of ``paths`` shares (plain text).

    A file name alone when it tells the file apart, else as many folders before it as
    that takes (``…/example_1/test/test_robot.launch.py``): two packages' files of one
    name never look the same, and a column of them stays narrow. A path that is all of
    another's ending is shown whole.
    """
    split = {p: p.replace("\\", "/").split("/") for p in dict.fromkeys(paths)}
    longest = max((len(parts) for parts in split.values()), default=0)
    counts = [Counter("/".join(parts[-k:]) for parts in split.values())
              for k in range(longest + 1)]
    shown = {}
    for path, parts in split.items():
        k = next((k for k in range(1, len(parts) + 1)
                  if counts[k]["/".join(parts[-k:])] == 1), len(parts))
        tail = "/".join(parts[-k:])
        shown[path] = tail if k == 1 or k == len(parts) else "\u2026/" + tail
    return shown
