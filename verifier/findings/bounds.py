"""What one launch file can put into the verdict is bounded.

A name or a value comes from the checked file: a 60 MB node name would otherwise reach
every output format whole, once per finding that quotes it. Each text of a finding is
cut past its bound, with a marker that says how much was left out.
"""

from __future__ import annotations

import dataclasses

from launchverify.rule import Finding, Related

MESSAGE_CHARACTERS = 2000  # a message (names, values and the sentence around them)
NOTE_CHARACTERS = 1000  # a related place's note, a trace step
VALUE_CHARACTERS = 500  # an argument value of a witness


def cut(text: str, most: int) -> str:
    """Return ``text``, or its first ``most`` characters and a marker when it is longer."""
    if len(text) <= most:
        return text
    return f"{text[:most]}... ({len(text) - most} more characters)"


def bounded(finding: Finding) -> Finding:
    """Return the finding with every text within its bound (itself when all are)."""
    texts = [finding.message, *(r.message for r in finding.related),
             *(step.text for step in finding.trace), *(finding.witness or {}).values()]
    if all(len(text) <= VALUE_CHARACTERS for text in texts):
        return finding
    return dataclasses.replace(
        finding,
        message=cut(finding.message, MESSAGE_CHARACTERS),
        related=tuple(Related(r.span, cut(r.message, NOTE_CHARACTERS))
                      for r in finding.related),
        trace=tuple(dataclasses.replace(step, text=cut(step.text, NOTE_CHARACTERS))
                    for step in finding.trace),
        witness=None if finding.witness is None else {
            cut(name, VALUE_CHARACTERS): cut(value, VALUE_CHARACTERS)
            for name, value in finding.witness.items()},
    )
