"""What nav2_common's ``RewrittenYaml`` does to a parameter file at launch time.

It loads the YAML, gives every leaf whose key is a ``param_rewrites`` key that value,
then every dotted path it names (``amcl.ros__parameters.alpha1``), adds the dotted paths
through ``ros__parameters`` the file does not have, and, with a non-empty ``root_key``,
moves the whole content under that key. Values are text: with ``convert_types`` a number
becomes one, and ``true``/``false`` (any case) a boolean either way. Both launchverify's
view of a node's parameters (``parameters.py``) and the executor's rewritten file follow
these functions.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator, Mapping
from typing import Any

import yaml

from launchverify.ir.subst import Rewritten

PARAMETERS = "ros__parameters"
HELPER = "RewrittenYaml"  # how the IR names it (``Rewritten.description``)


def rewrite_of(value: object) -> Rewritten | None:
    """Return the ``RewrittenYaml`` a (reduced) file value is, if it is one."""
    return value if isinstance(value, Rewritten) and value.description == HELPER else None


def under_root(value: object) -> bool:
    """Return whether a file value is rewritten with its keys moved under a root key."""
    rewrite = rewrite_of(value)
    return rewrite is not None and rewrite.root_key is not None


def converted(text: str, convert: bool) -> object:
    """Return a rewrite's value as the rewritten file holds it."""
    if convert:
        try:
            return float(text) if "." in text else int(text)
        except ValueError:
            pass
    if text.lower() == "true":
        return True
    if text.lower() == "false":
        return False
    return text


def rooted(key: str, root: str | None) -> str:
    """Return a block's node key once the content moves under ``root``.

    Examples:
        >>> rooted("/amcl", "robot1"), rooted("/**", "/robot1"), rooted("/amcl", None)
        ('/robot1/amcl', '/robot1/**', '/amcl')
    """
    return key if not root else f"/{root.strip('/')}{key}"


def rewrite_for(key: str, name: str, rewrites: Mapping[str, Any]) -> str | None:
    """Return the ``param_rewrites`` key that sets parameter ``name`` of block ``key``.

    A dotted path wins over a leaf's key, as it is applied after.

    Examples:
        >>> rewrites = {"use_sim_time": 1, "amcl.ros__parameters.alpha1": 2}
        >>> [rewrite_for("/amcl", n, rewrites) for n in ("use_sim_time", "alpha1", "beta")]
        ['use_sim_time', 'amcl.ros__parameters.alpha1', None]
        >>> rewrite_for("/planner", "GridBased.use_sim_time", rewrites)
        'use_sim_time'
    """
    for path in paths_of(key, name):
        if path in rewrites:
            return path
    leaf = name.rpartition(".")[2]
    return leaf if leaf in rewrites else None


def paths_of(key: str, name: str) -> tuple[str, ...]:
    """Return the dotted paths a parameter of block ``key`` may be written as.

    The YAML may write ``/**``, ``robot1: amcl:`` or ``/robot1/amcl`` as the node key.
    """
    forms = dict.fromkeys((key.strip("/").replace("/", "."), key, key.lstrip("/")))
    return tuple(f"{form}.{PARAMETERS}.{name}" for form in forms)


def added(rewrites: Mapping[str, Any], present: set[str]) -> Iterator[tuple[str, str, str]]:
    """Yield (rewrite, node key, parameter) for the paths a file gains.

    ``present``: the dotted paths the file has. Only a path through ``ros__parameters``
    is added.

    Examples:
        >>> list(added({"amcl.ros__parameters.a": 1, "use_sim_time": 2}, set()))
        [('amcl.ros__parameters.a', '/amcl', 'a')]
    """
    for path in rewrites:
        node, found, name = path.partition(f".{PARAMETERS}.")
        if found and node and name and path not in present:
            yield path, "/" + node.strip("/").replace(".", "/"), name


def inside_a_leaf(rewrites: Mapping[str, Any], present: set[str]) -> bool:
    """Return whether a dotted path goes inside a value (a list's item...).

    Examples:
        >>> inside_a_leaf({"amcl.ros__parameters.topics.0": "x"}, {"amcl.ros__parameters.topics"})
        True
    """
    return any(path.startswith(f"{leaf}.") for path in rewrites for leaf in present)


def replaces_a_mapping(rewrites: Mapping[str, Any], keys: Iterable[str],
                       names: Iterable[str]) -> bool:
    """Return whether a leaf rewrite names a mapping: RewrittenYaml replaces it whole.

    ``keys``: the blocks' node keys; ``names``: their parameters' dotted names.

    Examples:
        >>> replaces_a_mapping({"GridBased": "x"}, ["/planner"], ["GridBased.tolerance"])
        True
        >>> replaces_a_mapping({"tolerance": "x"}, ["/planner"], ["GridBased.tolerance"])
        False
    """
    mappings = {PARAMETERS, *(part for key in keys for part in key.split("/") if part)}
    mappings.update(part for name in names for part in name.split(".")[:-1])
    return any(key in mappings for key in rewrites if "." not in key)


def rewrite_document(data: Any, rewrites: Mapping[str, str], replaced: Mapping[str, str],
                     root: str | None, convert: bool) -> Any:
    """Return a loaded YAML document as ``RewrittenYaml`` writes it.

    ``rewrites``: its ``param_rewrites``; ``replaced``: its ``value_rewrites``.

    Examples:
        >>> rewrite_document({"amcl": {"ros__parameters": {"use_sim_time": False,
        ...                                                 "on": ["ZONE", 1]}}},
        ...                  {"use_sim_time": "True", "amcl.ros__parameters.a": "1"},
        ...                  {"ZONE": "false"}, "robot1", True)
        {'robot1': {'amcl': {'ros__parameters': {'use_sim_time': True, 'on': [False, 1], 'a': 1}}}}
    """
    values = {key: converted(text, convert) for key, text in rewrites.items()}
    if isinstance(data, dict):
        for mapping, key in list(_keys(data)):
            if key in values:
                mapping[key] = values[key]
        present = set(_paths(data, ""))
        for path, value in values.items():
            if path in present:
                _set(data, path.split("."), value)
        present = set(_paths(data, ""))
        for path, value in values.items():
            if path not in present and PARAMETERS in path.split("."):
                _set(data, path.split("."), value)
        data = _replaced(data, {key: converted(text, convert) for key, text in replaced.items()})
    return {root: data} if root else data


def _replaced(value: Any, replaced: Mapping[str, object]) -> Any:
    """Return a value with every value whose text ``replaced`` names replaced."""
    if isinstance(value, dict):
        return {key: _replaced(item, replaced) for key, item in value.items()}
    if isinstance(value, list):
        return [_replaced(item, replaced) for item in value]
    return replaced.get(str(value), value)


def _keys(mapping: dict[Any, Any]) -> Iterator[tuple[dict[Any, Any], Any]]:
    """Yield every key of nested mappings (not inside lists), the inner ones first."""
    for key, value in mapping.items():
        if isinstance(value, dict):
            yield from _keys(value)
        yield mapping, key


def _paths(value: Any, prefix: str) -> Iterator[str]:
    """Yield the dotted path of every value that is not a mapping or a list."""
    if isinstance(value, dict):
        for key, item in value.items():
            yield from _paths(item, f"{prefix}.{key}" if prefix else str(key))
    elif isinstance(value, list):
        for index, item in enumerate(value):
            yield from _paths(item, f"{prefix}.{index}" if prefix else str(index))
    else:
        yield prefix


def _set(data: Any, keys: list[str], value: object) -> None:
    """Set a dotted path's value, making the mappings on the way.

    As nav2 does, it stops at the first key named like the last one.
    """
    node = data
    for key in keys:
        if key == keys[-1]:
            break
        node = node[int(key)] if isinstance(node, list) else node.setdefault(key, {})
    if isinstance(node, list):
        node[int(keys[-1])] = value
    else:
        node[keys[-1]] = value


def reads_as_text(value: str) -> bool:
    """Return whether a ``value_rewrites`` key is text as YAML reads it.

    Only then does launchverify's typed view of a file tell which values it replaces
    (``str(value)`` of what PyYAML loaded).

    Examples:
        >>> reads_as_text("KEEPOUT_ZONE_ENABLED"), reads_as_text("5"), reads_as_text("yes")
        (True, False, False)
    """
    try:
        return isinstance(yaml.safe_load(value), str)
    except yaml.YAMLError:
        return False
