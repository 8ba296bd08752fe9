"""The parameters a node ends up with, and where each value comes from.

launch_ros turns a node's parameter sources into command-line rules, in this order:
``SetParameter`` (``-p name:=value``, for every node: key ``/**``) and
``SetParametersFromFile`` in scope, then the node's own ``parameters`` (files as
``--params-file``; dicts as a file keyed by the node's name, or ``/**`` when that is not
known). rcl merges all of them into one table keyed by node pattern, each key placed where
it first appears; a node takes the parameters of every key that matches its name, in that
order, later ones winning. So a node-specific block wins over ``/**`` only when its key
appears after the first ``/**`` (docs/launch-semantics §8.2).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from launchverify.frontends.param_file import ParamBlock
from launchverify.graph import LaunchGraph, NodeRecord, ParamRecord
from launchverify.ir.subst import Rewritten, Sub, walk
from launchverify.ir.symbolic import Arg
from launchverify.models.parameter_values import typed_parameter
from launchverify.models.rewritten_yaml import (
    added,
    converted,
    inside_a_leaf,
    paths_of,
    reads_as_text,
    replaces_a_mapping,
    rewrite_for,
    rewrite_of,
    rooted,
)
from launchverify.models.ros_names import node_key_matches
from launchverify.span import Span

EVERY_NODE = "/**"


@dataclass(frozen=True, slots=True)
class Contribution:
    """One value a parameter source gives a parameter."""

    value: object
    kind: str  # bool, integer, double, string, <kind>_array, or "unknown"
    span: Span  # where the value is written
    layer: str  # what kind of source: set_parameter, file, inline
    written: Sub | None = None  # the launch's expression, for a value not known here
    key: str = EVERY_NODE  # the node key it is given under (a file's block, or the node's)
    value_span: Span | None = None  # a file's scalar value as written (for fixes)

    @property
    def shared(self) -> bool:
        """Return whether the value is given to every node alike (``/**``, SetParameter).

        Such a value is meant for whichever nodes use it: one that does not is no mistake.
        """
        return self.layer == "set_parameter" or (
            self.layer == "file" and self.key.strip("/") in ("**", "*"))


@dataclass
class EffectiveParameters:
    """Every parameter of one node, each with its contributions in precedence order."""

    node: NodeRecord
    fqn: str | None
    values: dict[str, list[Contribution]] = field(default_factory=dict)
    complete: bool = True  # False when a source could not be read or matched

    def winner(self, name: str) -> Contribution | None:
        """Return the contribution the node receives for ``name`` (the last one)."""
        found = self.values.get(name)
        return found[-1] if found else None


def kind_of(value: object) -> str:
    """Return the ROS parameter type of a Python value."""
    if isinstance(value, bool):
        return "bool"
    if isinstance(value, int):
        return "integer"
    if isinstance(value, float):
        return "double"
    if isinstance(value, str):
        return "string"
    if isinstance(value, (list, tuple)):
        kinds = {kind_of(item) for item in value}
        return f"{kinds.pop()}_array" if len(kinds) == 1 else "unknown"
    return "unknown"


def effective_parameters(graph: LaunchGraph, node: NodeRecord) -> EffectiveParameters:
    """Return what a node receives, under the arguments as given (computed once)."""
    cache = graph.derived.setdefault("effective_parameters", {})
    found = cache.get(id(node))
    if not isinstance(found, EffectiveParameters):
        found = _resolve(graph, node)
        cache[id(node)] = found
    return found


def _resolve(graph: LaunchGraph, node: NodeRecord) -> EffectiveParameters:
    fqn = graph.base(node.fqn)
    result = EffectiveParameters(node, fqn)
    component = node.composable
    table: dict[str, list[tuple[str, Contribution]]] = {}  # key -> [(name, value)] in order
    own_key = fqn if fqn is not None else EVERY_NODE
    for param in node.parameters:
        if param.scope and graph.runs(param.origin) is False:
            continue  # a SetParameter under a condition these arguments make false
        if param.file is not None:
            _add_file(graph, param, table, result)
        else:
            name = graph.base(param.name) if param.name is not None else None
            if name is None:
                result.complete = False
                continue
            value = _inline_value(graph, param)
            layer = "set_parameter" if param.scope else "inline"
            key = EVERY_NODE if param.scope else own_key
            written = param.value if value is None and isinstance(param.value, Sub) else None
            table.setdefault(key, []).append((name, Contribution(
                value, kind_of(value) if value is not None else "unknown",
                param.origin.span, layer, written, key)))
    for key, entries in table.items():
        if not _applies(key, fqn, component):
            continue
        for name, contribution in entries:
            result.values.setdefault(name, []).append(contribution)
    return result


def file_readers(graph: LaunchGraph) -> dict[Path, list[tuple[NodeRecord, ParamRecord]]]:
    """Return, per parameter file, the nodes that load it and how (computed once)."""
    cache = graph.derived.setdefault("file_readers", {})
    cached = cache.get(0)
    if isinstance(cached, dict):
        return cached
    found: dict[Path, list[tuple[NodeRecord, ParamRecord]]] = {}
    for node in graph.nodes:
        for param in node.parameters:
            if param.source is not None:
                found.setdefault(param.source, []).append((node, param))
    cache[0] = found
    return found


def _applies(key: str, fqn: str | None, component: bool) -> bool:
    if key == EVERY_NODE:
        return True
    if fqn is None:
        return False
    if component:
        return key.strip("/") == fqn.strip("/")
    return node_key_matches(key, fqn)


def _add_file(graph: LaunchGraph, param: ParamRecord,
              table: dict[str, list[tuple[str, Contribution]]],
              result: EffectiveParameters) -> None:
    source = param.source
    loaded = graph.param_files.get(source) if source is not None else None
    if loaded is None or not loaded.readable:
        result.complete = False
        return
    rewrite = rewrite_of(param.file)
    if rewrite is not None:
        _add_rewritten(graph, param, rewrite, loaded.blocks, table, result)
        return
    for block in loaded.blocks:
        entries = table.setdefault(block.key, [])
        for name, parameter in block.parameters.items():
            entries.append((name, Contribution(parameter.value, parameter.kind,
                                               parameter.span, "file", key=block.key,
                                               value_span=parameter.value_span)))


def _add_rewritten(graph: LaunchGraph, param: ParamRecord, rewrite: Rewritten,
                   blocks: list[ParamBlock], table: dict[str, list[tuple[str, Contribution]]],
                   result: EffectiveParameters) -> None:
    """Add a file as ``RewrittenYaml`` gives it (``models/rewritten_yaml.py``).

    A rewritten value is set where the launch gives the file (``param``'s place).
    """
    root = graph.base(rewrite.root_key) if rewrite.root_key is not None else None
    if not rewrite.exact or (rewrite.root_key is not None and root is None):
        result.complete = False  # what the file becomes is not known here
        return
    rewrites, values = dict(rewrite.params), dict(rewrite.values)
    present = {path for block in blocks for name in block.parameters
               for path in paths_of(block.key, name)}
    if inside_a_leaf(rewrites, present) or not all(map(reads_as_text, values)) or \
            replaces_a_mapping(rewrites, (block.key for block in blocks),
                               (name for block in blocks for name in block.parameters)):
        result.complete = False  # a list's item, a whole mapping, a number: not followed
        return
    given = _Given(graph, param, rewrite.convert, values)
    for block in blocks:
        if root and "*" in block.key:
            result.complete = False  # how rcl reads a pattern under a node key: not known
            continue
        key = rooted(block.key, root)
        entries = table.setdefault(key, [])
        for name, parameter in block.parameters.items():
            by = rewrite_for(block.key, name, rewrites)
            entries.append((name, given.value(rewrites[by], key) if by is not None else
                            given.replaced(parameter.value, key) or Contribution(
                                parameter.value, parameter.kind, parameter.span, "file",
                                key=key, value_span=parameter.value_span)))
    for path, block_key, name in added(rewrites, present):
        key = rooted(block_key, root)
        table.setdefault(key, []).append((name, given.value(rewrites[path], key)))


@dataclass(frozen=True)
class _Given:
    """The values a ``RewrittenYaml`` gives, set where the launch gives the file."""

    graph: LaunchGraph
    param: ParamRecord
    convert: bool
    values: dict[str, Sub]  # value_rewrites: applied last, to every value

    def value(self, value: Sub, key: str) -> Contribution:
        """Return what a rewrite gives (then replaced if a value rewrite names it)."""
        known = self._known(value)
        if known is None:
            return self._contribution(None, key, value)
        return self.replaced(known, key) or self._contribution(known, key)

    def replaced(self, value: object, key: str) -> Contribution | None:
        """Return a value as ``value_rewrites`` replace it or its items (``None``: as is)."""
        if not isinstance(value, list):
            named = self.values.get(str(value))
            return None if named is None else self._contribution(self._known(named), key,
                                                                  named)
        if not any(str(item) in self.values for item in value):
            return None
        items = [self._known(self.values[str(item)]) if str(item) in self.values else item
                 for item in value]
        return self._contribution(None if None in items else items, key)

    def _known(self, value: Sub) -> object:
        text = None if _includer_decides(self.graph, value) else self.graph.base(value)
        return None if text is None else converted(text, self.convert)

    def _contribution(self, known: object, key: str, written: Sub | None = None) -> Contribution:
        return Contribution(known, kind_of(known) if known is not None else "unknown",
                            self.param.origin.span, "file",
                            written if known is None else None, key)


def _inline_value(graph: LaunchGraph, param: ParamRecord) -> object:
    """Return an inline value as the node receives it (``None`` when not known)."""
    value = param.value
    if isinstance(value, Sub):
        if _includer_decides(graph, value):
            return None
        text = graph.base(value)
        return None if text is None else typed_parameter(text, param.value_type)
    if isinstance(value, tuple):
        items = [_inline_item(graph, item, param.value_type) for item in value]
        return None if any(item is None for item in items) else items
    return value


def _includer_decides(graph: LaunchGraph, value: Sub) -> bool:
    """Return whether a value rests on arguments of a file meant to be included.

    Its includers pass their own values (a list where the default is one topic): what the
    default gives is no claim to make on the file alone.
    """
    return not graph.launchable_alone() and any(isinstance(part, Arg) for part in walk(value))


def _inline_item(graph: LaunchGraph, item: object, value_type: str | None) -> object:
    if isinstance(item, Sub):
        if _includer_decides(graph, item):
            return None
        text = graph.base(item)
        return None if text is None else typed_parameter(text, value_type)
    return item
