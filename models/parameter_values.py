"""How launch_ros types a parameter value given as text.

A value written in a frontend (``<param value="5"/>``) or computed by substitutions in
Python (``{'rate': LaunchConfiguration('rate')}``) reaches the node as text that launch_ros
parses with YAML rules: ``'5'`` is an int, ``'true'`` a bool, ``'[1, 2]'`` a list, ``''``
stays an empty string. A ``type=`` (frontend) or ``value_type`` (``ParameterValue``)
forces the type. A plain Python ``str`` is never parsed; the frontends keep it as text.
"""

from __future__ import annotations

import functools

import yaml

_SCALARS = (bool, int, float, str)


@functools.lru_cache(maxsize=8192)
def typed_parameter(text: str, value_type: str | None = None) -> object:
    """Return the value a node receives for ``text`` (the text itself when it cannot tell).

    Values launch_ros would reject (a YAML mapping or null, a mixed list) are returned as
    text: reporting them is a rule's job, not the graph's. Lists come back as tuples
    (values are shared between callers).
    """
    value = _typed(text, value_type)
    return tuple(value) if isinstance(value, list) else value


def _typed(text: str, value_type: str | None) -> object:
    if value_type == "str":
        return text
    if value_type in ("int", "float", "bool"):
        return _forced(text, value_type)
    if not text:
        return text
    try:
        value = yaml.safe_load(text)
    except yaml.YAMLError:
        return text
    if isinstance(value, _SCALARS):
        return value
    if isinstance(value, list) and value and _uniform(value):
        return value
    return text


def _uniform(items: list[object]) -> bool:
    kinds = {bool if isinstance(i, bool) else float if isinstance(i, (int, float)) else type(i)
             for i in items}
    return len(kinds) == 1 and kinds <= {bool, float, str}


def _forced(text: str, value_type: str) -> object:
    """Apply ``type=int|float|bool``; text that does not convert stays text."""
    try:
        value = yaml.safe_load(text)
    except yaml.YAMLError:
        return text
    if value_type == "bool":
        return value if isinstance(value, bool) else text
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return text
    return int(value) if value_type == "int" and float(value).is_integer() else (
        float(value) if value_type == "float" else text)
