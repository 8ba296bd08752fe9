"""The two truth rules of ROS 2 launch, and ``equals`` comparison.

Conditions (``if``/``unless``) accept only ``true``/``1``/``false``/``0`` after strip and
lower-casing; anything else raises at run time. Boolean substitutions and typed attributes
coerce with YAML rules instead (``yes``/``on`` are true), plus ``'1'``/``'0'``.
"""

from __future__ import annotations

import functools
import math

import yaml

CONDITION_TRUE = ("true", "1")
CONDITION_FALSE = ("false", "0")


class InvalidBoolean(ValueError):
    """A value that a truth rule rejects (launch raises at run time)."""


def condition_truth(value: str) -> bool:
    """Apply the condition rule; raise ``InvalidBoolean`` like launch.

    Examples:
        >>> condition_truth(" TRUE ")
        True
        >>> condition_truth("yes")
        Traceback (most recent call last):
        ...
        launchverify.models.booleans.InvalidBoolean: invalid condition expression, expected one of [true, 1, false, 0] but got 'yes'
    """  # noqa: E501
    text = value.strip().lower()
    if text in CONDITION_TRUE:
        return True
    if text in CONDITION_FALSE:
        return False
    raise InvalidBoolean(
        f"invalid condition expression, expected one of [true, 1, false, 0] but got {value!r}"
    )


def typed_truth(value: str) -> bool:
    """Apply the typed coercion of boolean substitutions (``$(not)``, ``respawn``...)."""
    if value == "1":
        return True
    if value == "0":
        return False
    loaded = _yaml_bool(value)
    if loaded is not None:
        return loaded
    raise InvalidBoolean(f"cannot convert value {value!r} to a boolean")


@functools.lru_cache(maxsize=1024)
def _yaml_bool(value: str) -> bool | None:
    """Return what YAML makes of a value when it is a boolean (a few values, asked often)."""
    try:
        loaded = yaml.safe_load(value) if value else None
    except yaml.YAMLError:
        return None
    return loaded if isinstance(loaded, bool) else None


def _as_bool(text: str) -> bool | None:
    lowered = text.lower()
    if lowered in ("true", "1"):
        return True
    if lowered in ("false", "0"):
        return False
    return None


def _as_float(text: str) -> float | None:
    try:
        return float(text)
    except ValueError:
        return None


def launch_equals(left: str, right: str) -> bool:
    """Compare like ``EqualsSubstitution``: as booleans, else as numbers, else as text.

    Examples:
        >>> launch_equals("True", "1"), launch_equals("1.0", "1"), launch_equals("a", "A")
        (True, True, False)
    """
    left_bool, right_bool = _as_bool(left), _as_bool(right)
    if left_bool is not None and right_bool is not None:
        return left_bool == right_bool
    left_num, right_num = _as_float(left), _as_float(right)
    if left_num is not None and right_num is not None:
        return math.isclose(left_num, right_num)
    return left == right


def bool_text(value: bool) -> str:
    """Return launch's spelling of a boolean result."""
    return "true" if value else "false"
