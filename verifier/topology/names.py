"""A name as far as the sources tell it: a literal, a parameter's default, or unknown.

Both extractors resolve expressions to a ``Resolved``; variables assigned in several
places are merged here, flow-insensitively: one agreeing answer, else unknown.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True, slots=True)
class Resolved:
    """What an expression is: ``value`` when known, ``parameter`` when it comes from one."""

    value: str | None = None
    parameter: str | None = None
    reason: str | None = None  # why ``value`` is unknown

    @property
    def known(self) -> bool:
        """Return whether the value (or its parameter) is known."""
        return self.value is not None or self.parameter is not None


def unknown(reason: str) -> Resolved:
    """Return an unknown value, saying why."""
    return Resolved(reason=reason)


def merge(variable: str, candidates: list[Resolved]) -> Resolved:
    """Return what a variable holds, given every value assigned to it in the file.

    A parameter read into the variable wins over the literal it was initialised with
    (``std::string topic_ = "scan"; ... get_parameter("topic", topic_)``): that literal is
    the usual default. Anything else that disagrees makes the variable unknown.
    """
    if not candidates:
        return unknown(f"'{variable}' is not assigned in this file")
    parameters = {c.parameter for c in candidates if c.parameter is not None}
    if len(parameters) == 1:
        parameter = parameters.pop()
        values = [c.value for c in candidates if c.parameter == parameter and c.value]
        literals = [c.value for c in candidates if c.parameter is None and c.value]
        default = next(iter(values or literals), None)
        if any(not c.known for c in candidates):
            reason = next(c.reason for c in candidates if not c.known)
            return unknown(f"'{variable}' is also assigned a value built at run time"
                           f" ({reason})")
        return Resolved(default, parameter)
    if len(parameters) > 1:
        return unknown(f"'{variable}' reads several parameters: "
                       + ", ".join(sorted(parameters)))
    failed = [c for c in candidates if not c.known]
    if failed:
        return unknown(f"via '{variable}': {failed[0].reason}")
    distinct = sorted({c.value for c in candidates if c.value is not None})
    if len(distinct) == 1:
        return candidates[0]
    return unknown(f"'{variable}' is assigned several values: "
                   + ", ".join(repr(v) for v in distinct))
