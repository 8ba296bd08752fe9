"""Expected-finding markers written inside corpus launch files.

``expect: LV101 LV102`` marks findings on the line of the comment (or, when the comment
stands alone on its line, on the next line with content); ``expect-info: LV204`` (or
``-warning``, ``-error``) marks one that must also have that severity (where a rule reports
a lesser case as an info); ``expect-not: LV101`` marks a deliberate near miss that must
stay quiet.
"""

from __future__ import annotations

import re
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

MARKER = re.compile(
    r"(?:<!--|#)\s*(expect(?:-not|-info|-warning|-error)?):\s*((?:LV\d{3}\s*)+)")
MARKED_SUFFIXES = (".xml", ".yaml", ".yml", ".py")


@dataclass
class Expectations:
    """What the markers of one corpus tree promise."""

    expected: Counter[tuple[str, int, str]] = field(default_factory=Counter)
    forbidden: set[tuple[str, int, str]] = field(default_factory=set)
    severities: dict[tuple[str, int, str], str] = field(default_factory=dict)  # if marked


def read_markers(tree: Path) -> Expectations:
    """Collect every marker below ``tree``; keys are (relative path, line, code)."""
    result = Expectations()
    for path in sorted(tree.rglob("*")):
        if not path.is_file() or not path.name.endswith(MARKED_SUFFIXES):
            continue
        lines = path.read_text(encoding="utf-8").splitlines()
        relative = path.relative_to(tree).as_posix()
        for index, line in enumerate(lines):
            for match in MARKER.finditer(line):
                target = index + 1
                if not line[: match.start()].strip():
                    target = next(
                        (j + 1 for j in range(index + 1, len(lines)) if lines[j].strip()),
                        index + 1,
                    )
                for code in match.group(2).split():
                    key = (relative, target, code)
                    if match.group(1) == "expect-not":
                        result.forbidden.add(key)
                        continue
                    result.expected[key] += 1
                    if match.group(1) != "expect":
                        result.severities[key] = match.group(1).removeprefix("expect-")
    return result
