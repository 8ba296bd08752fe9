"""ROS name resolution of one endpoint: expansion, then the node's remap rules.

What rcl does when a node creates a publisher, subscription, service or client (and what
rcl_action does for an action name): the name is expanded against the node's namespace
and name (``~/x``, ``{node}``, relative names), then the node's remap rules are tried in
order; the first whose (expanded) source equals the expanded name gives the result, whose
replacement is expanded the same way (docs/launch-semantics §6.2 and §7). A rule that
cannot be read (a side unknown before launch) is not skipped: whether it would match is
unknown, so the name is too.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass

from launchverify.models.ros_names import expand_topic_name, validate_topic_name

_SUBSTITUTION = re.compile(r"\{([^{}]*)\}")
_SPECIAL = ("__node", "__name", "__ns")


@dataclass(frozen=True, slots=True)
class Rule:
    """One remap rule as passed to a node: ``[node:]src:=dst`` with both sides known.

    ``only`` is ``topic`` for ``rostopic://`` rules, ``service`` for ``rosservice://``
    ones, ``None`` for rules that apply to both.
    """

    src: str
    dst: str
    node: str | None = None
    only: str | None = None
    where: str = ""  # where the rule is written, for messages


@dataclass(frozen=True, slots=True)
class UnknownRule:
    """A remap rule one of whose sides is not known before launch."""

    reason: str
    node: str | None = None  # its ``node:`` prefix, when that much is known
    src: str | None = None  # its source name, when that much is known


RuleLike = Rule | UnknownRule


@dataclass(frozen=True, slots=True)
class Resolution:
    """A fully qualified name, or ``None`` with the reason it is not known."""

    name: str | None
    reason: str | None = None
    remapped_by: str | None = None  # where the rule that applied is written


def parse_rule(src: str, dst: str, where: str = "") -> Rule:
    """Split a launch remap ``(src, dst)`` into its node prefix, scheme and names.

    Examples:
        >>> parse_rule("talker:chatter", "news")
        Rule(src='chatter', dst='news', node='talker', only=None, where='')
        >>> parse_rule("rosservice://add", "/sum").only
        'service'
    """
    only = None
    for scheme, kind in (("rostopic://", "topic"), ("rosservice://", "service")):
        if src.startswith(scheme):
            return Rule(src[len(scheme):], _unscheme(dst), None, kind, where)
    node = None
    prefix, colon, rest = src.partition(":")
    if colon and not rest.startswith("//"):
        node, src = prefix, rest
        for scheme, kind in (("rostopic://", "topic"), ("rosservice://", "service")):
            if src.startswith(scheme):
                src, only = src[len(scheme):], kind
    return Rule(src, _unscheme(dst), node, only, where)


def _unscheme(name: str) -> str:
    for scheme in ("rostopic://", "rosservice://"):
        if name.startswith(scheme):
            return name[len(scheme):]
    return name


def expand(name: str, namespace: str, node_name: str | None) -> Resolution:
    """Expand a name as rcl does: substitutions, ``~``, then the namespace.

    Examples:
        >>> expand("chatter", "/robot1", "talker").name
        '/robot1/chatter'
        >>> expand("{node}/out", "/", "cam").name
        '/cam/out'
        >>> expand("~/status", "/", None).reason
        "a private name needs the node's name, which neither the launch nor the sources give"
    """
    problem = validate_topic_name(name)
    if problem is not None:
        return Resolution(None, f"'{name}' is not a valid name: {problem}")
    needs_node = name == "~" or name.startswith("~/") or "{node}" in name
    if needs_node and node_name is None:
        return Resolution(None, "a private name needs the node's name, which neither the "
                          "launch nor the sources give")
    for written in _SUBSTITUTION.findall(name):
        if written not in ("node", "ns", "namespace"):
            return Resolution(None, f"unknown substitution {{{written}}} in '{name}'")
    if "{" in name:
        namespace_text = "" if namespace in ("", "/") else namespace
        name = name.replace("{node}", node_name or "").replace("{namespace}", namespace_text)
        name = name.replace("{ns}", namespace_text)
    expanded = expand_topic_name(name, namespace, node_name or "")
    problem = validate_topic_name(expanded)
    if problem is not None or "//" in expanded:
        return Resolution(None, f"'{name}' expands to '{expanded}', which is not a valid "
                          "fully qualified name")
    return Resolution(expanded)


def node_identity(name: str | None, namespace: str | None, rules: Sequence[RuleLike],
                  launch_named: bool, launch_namespaced: bool,
                  ) -> tuple[str | None, str | None, str | None]:
    """Apply ``__node`` / ``__ns`` rules of the remappings: ``(name, namespace, reason)``.

    Launch passes its own ``__node:=`` and ``__ns:=`` before the remappings, and the first
    rule wins, so a remapping only renames what launch left to the executable. A rule whose
    source is not known may be such a rule: then what it could rename is unknown, and
    ``reason`` says so (``name`` / ``namespace`` come back ``None``).
    """
    for special, launch_sets in (("node", launch_named), ("ns", launch_namespaced)):
        if launch_sets:
            continue
        for rule in rules:
            if isinstance(rule, UnknownRule):
                if rule.src is None and (rule.node is None or rule.node == name):
                    what = "name" if special == "node" else "namespace"
                    return (None if special == "node" else name,
                            None if special == "ns" else namespace,
                            f"the node's {what} may be set by a remap rule not known before "
                            f"launch: {rule.reason}")
                continue
            if rule.src not in _SPECIAL or (special == "ns") != (rule.src == "__ns"):
                continue
            if rule.node is not None and rule.node != name:
                continue
            if special == "node":
                name = rule.dst
            else:
                namespace = rule.dst
            break
    return name, namespace, None


def resolve(name: str, namespace: str, node_name: str | None, rules: Sequence[RuleLike],
            *, service: bool = False) -> Resolution:
    """Return the fully qualified name an endpoint named ``name`` ends up with.

    ``rules`` are the node's remap rules in the order rcl tries them. ``service`` is true
    for services and their clients (``rosservice://`` rules apply, ``rostopic://`` ones
    do not); topics and action names take topic rules.

    Examples:
        >>> rules = [parse_rule("chatter", "/x")]
        >>> resolve("chatter", "/ns", "talker", rules).name
        '/x'
        >>> resolve("/ns/chatter", "/ns", "talker", rules).name
        '/x'
        >>> resolve("chatter", "/", "talker", [parse_rule("listener:chatter", "/y")]).name
        '/chatter'
    """
    expanded = expand(name, namespace, node_name)
    if expanded.name is None:
        return expanded
    for rule in rules:
        if isinstance(rule, UnknownRule):
            if rule.node is not None and node_name is not None and rule.node != node_name:
                continue
            if rule.src in _SPECIAL:
                continue
            if rule.src is not None:
                source = expand(rule.src, namespace, node_name)
                if source.name is not None and source.name != expanded.name:
                    continue  # matches another name: what it maps to does not matter
            return Resolution(None, f"{expanded.name} may be remapped by a rule not known "
                              f"before launch: {rule.reason}")
        if rule.src in _SPECIAL:
            continue
        if rule.only is not None and (rule.only == "service") != service:
            continue
        if rule.node is not None:
            if node_name is None:
                return Resolution(None, f"rule {rule.node}:{rule.src}:={rule.dst} applies "
                                  "only to a node of that name, and this node's name is "
                                  "not known")
            if rule.node != node_name:
                continue
        source = expand(rule.src, namespace, node_name)
        if source.name is None:
            return Resolution(None, f"remap rule {rule.src}:={rule.dst}: {source.reason}")
        if source.name != expanded.name:
            continue
        target = expand(rule.dst, namespace, node_name)
        if target.name is None:
            return Resolution(None, f"remap rule {rule.src}:={rule.dst}: {target.reason}")
        return Resolution(target.name, remapped_by=rule.where or None)
    return expanded
