"""The checks a parameter's declaration puts on its value.

As generate_parameter_library names them (``bounds``, ``gt``, ``gt_eq``, ``lt``,
``lt_eq``, ``one_of``): whether a value surely fails one, and how to say what one allows.
"""

from __future__ import annotations

Limit = tuple[str, tuple[object, ...]]

_WORDS = {"bounds": "within [{0}, {1}]", "gt": "greater than {0}", "gt_eq": "at least {0}",
          "lt": "less than {0}", "lt_eq": "at most {0}", "one_of": "one of {0}"}


def allowed(limit: Limit) -> str:
    """Return what a check allows, in words.

    Examples:
        >>> allowed(("gt", (0.0,))), allowed(("bounds", (1, 2)))
        ('greater than 0.0', 'within [1, 2]')
    """
    check, arguments = limit
    return _WORDS.get(check, check + " {0}").format(*arguments, "", "")


def failed_check(limits: tuple[Limit, ...], value: object) -> Limit | None:
    """Return the first check a value surely fails, ``None`` when none does."""
    return next((limit for limit in limits if violates(limit, value)), None)


def violates(limit: Limit, value: object) -> bool:
    """Return whether a value surely fails a check (``False`` when it cannot be told).

    Examples:
        >>> violates(("bounds", (0.0, 1.0)), 2.5), violates(("bounds", (0.0, 1.0)), 0.5)
        (True, False)
        >>> violates(("one_of", (["a", "b"],)), "c"), violates(("gt", (0,)), [1])
        (True, False)
    """
    check, arguments = limit
    if check == "one_of":
        choices = arguments[0] if arguments else None
        return isinstance(choices, list) and isinstance(value, (str, int, float)) and \
            value not in choices
    number = _number(value)
    limits = [_number(a) for a in arguments]
    if number is None or not limits or any(x is None for x in limits):
        return False
    if check == "bounds" and len(limits) == 2:
        low, high = limits
        return not (low <= number <= high)  # type: ignore[operator]
    bound = limits[0]
    assert bound is not None
    return {"gt": number <= bound, "gt_eq": number < bound, "lt": number >= bound,
            "lt_eq": number > bound}.get(check, False)


def _number(value: object) -> float | None:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    return float(value)



