"""The QoS an endpoint is created with, as far as its code shows: reliability, durability.

Read from the text of the QoS argument (and, for a variable, of its initialiser and the
calls that change it): a named profile (``rclcpp::SensorDataQoS()``,
``qos_profile_sensor_data``, nav2's ``LatchedPublisherQoS``), a depth (the default:
reliable, volatile), then the policies set on it (``.best_effort()``,
``.transient_local()``, ``reliability=ReliabilityPolicy.BEST_EFFORT``). What the text does
not settle stays ``None``: a profile from a function, a parameter, the system default.

An endpoint whose options carry ``QosOverridingOptions`` (rclcpp) or
``QoSOverridingOptions`` (rclpy) declares a read-only parameter
``qos_overrides.<topic>.<publisher|subscription>[_<id>].<policy>`` for each policy listed
there, ``<topic>`` being the name after expansion and remapping; the value the node
receives replaces the code's (``rclcpp/detail/qos_parameters.hpp``,
``rclpy/qos_overriding_options.py``). :class:`Overriding` records what the code opens;
:func:`overridden` applies what the launch gives.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from launchverify.parameters import Contribution, EffectiveParameters

RELIABLE, BEST_EFFORT = "reliable", "best_effort"
VOLATILE, TRANSIENT_LOCAL = "volatile", "transient_local"
JUDGED = ("reliability", "durability")  # the policies LV605 compares
# the override values that settle a judged policy (system_default, best_available do not)
_SETTLED = {"reliability": (RELIABLE, BEST_EFFORT), "durability": (VOLATILE, TRANSIENT_LOCAL)}


@dataclass(frozen=True, slots=True)
class Overriding:
    """What an endpoint's ``QosOverridingOptions`` open to ``qos_overrides`` parameters.

    ``policies``: the policy names listed (``None``: the list is not read here); ``entity``:
    the id that suffixes the parameters' role (``""`` none, ``None`` not read here).
    """

    policies: frozenset[str] | None
    entity: str | None = ""


@dataclass(frozen=True, slots=True)
class Qos:
    """An endpoint's reliability and durability (``None``: not known before run time)."""

    reliability: str | None
    durability: str | None
    overriding: Overriding | None = None  # built with QosOverridingOptions

    def describe(self) -> str:
        """Return ``best_effort, volatile`` (``?`` for what is not known)."""
        return f"{self.reliability or '?'}, {self.durability or '?'}"


# Named profiles: (pattern, reliability, durability); the first match is the base
_PROFILES: tuple[tuple[re.Pattern[str], str | None, str | None], ...] = tuple(
    (re.compile(pattern), reliability, durability) for pattern, reliability, durability in (
        (r"SensorDataQoS|sensor_data|SENSOR_DATA", BEST_EFFORT, VOLATILE),
        (r"\bClockQoS", BEST_EFFORT, VOLATILE),
        (r"Latched\w*QoS|RosoutQoS|qos_profile_rosout|map_qos|MapQoS", RELIABLE,
         TRANSIENT_LOCAL),
        (r"SystemDefaultsQoS|system_default|SYSTEM_DEFAULT|BestAvailableQoS|best_available",
         None, None),
        (r"ServicesQoS|ParametersQoS|ParameterEventsQoS|StandardTopicQoS|services_default"
         r"|parameter_events|qos_profile_parameters|SERVICES_DEFAULT|PARAMETERS",
         RELIABLE, VOLATILE),
        (r"^\s*\d+\s*$|\bQoS\s*[({]|KeepLast|KeepAll|QoSProfile\s*\(|qos_profile_default"
         r"|rmw_qos_profile_default", RELIABLE, VOLATILE),
    ))
_SETTERS = (
    (re.compile(r"\.best_effort\s*\(|BEST_EFFORT|BestEffort"), "reliability", BEST_EFFORT),
    (re.compile(r"\.reliable\s*\(|RELIABILITY_RELIABLE|Policy\.RELIABLE\b|::Reliable\b"),
     "reliability", RELIABLE),
    (re.compile(r"\.transient_local\s*\(|TRANSIENT_LOCAL|TransientLocal"), "durability",
     TRANSIENT_LOCAL),
    (re.compile(r"\.durability_volatile\s*\(|DURABILITY_VOLATILE|Policy\.VOLATILE\b"
                r"|::Volatile\b"), "durability", VOLATILE),
)
# a policy given by something the text does not settle (a variable, a parameter)
_OPEN_POLICY = re.compile(r"\.(?:reliability|durability)\s*\(\s*(?![A-Za-z_:]*"
                          r"(?:RELIAB|BEST_EFFORT|BestEffort|Reliable|DURABILITY|VOLATILE|"
                          r"TRANSIENT|Volatile|Transient))|\b(?:reliability|durability)\s*="
                          r"\s*(?![\w.]*(?:RELIABLE|BEST_EFFORT|VOLATILE|TRANSIENT_LOCAL))")


def qos_of(texts: list[str]) -> Qos | None:
    """Return the QoS that the written profile and the policies set on it give.

    ``texts`` is the argument's text, then (for a variable) its initialiser and the
    statements that change it. ``None`` when no named profile or depth starts it.
    """
    if not texts:
        return None
    joined = " ".join(" ".join(t.split()) for t in texts)
    base = next(((r, d) for pattern, r, d in _PROFILES if pattern.search(joined)), None)
    if base is None:
        return None
    reliability, durability = base
    if _OPEN_POLICY.search(joined):
        return Qos(None, None)
    found: dict[str, set[str]] = {"reliability": set(), "durability": set()}
    for pattern, policy, value in _SETTERS:
        if pattern.search(joined):
            found[policy].add(value)
    if len(found["reliability"]) == 1:
        reliability = found["reliability"].pop()
    elif found["reliability"]:
        reliability = None  # set both ways somewhere: which one holds is flow's business
    if len(found["durability"]) == 1:
        durability = found["durability"].pop()
    elif found["durability"]:
        durability = None
    return Qos(reliability, durability)


def incompatible(writer: Qos, reader: Qos) -> str | None:
    """Return why a writer and a reader never match (rmw's rules), ``None`` if they may.

    A best-effort writer does not serve a reliable reader; a volatile writer does not
    serve a transient-local reader. The other way round is fine.
    """
    policy = clash(writer, reader)
    return None if policy is None else _WHY[policy]


def clash(writer: Qos, reader: Qos) -> str | None:
    """Return the policy on which a writer and a reader never match, ``None`` if none."""
    if writer.reliability == BEST_EFFORT and reader.reliability == RELIABLE:
        return "reliability"
    if writer.durability == VOLATILE and reader.durability == TRANSIENT_LOCAL:
        return "durability"
    return None


_WHY = {"reliability": "a best-effort publisher cannot serve a reliable subscription",
        "durability": "a volatile publisher cannot serve a transient-local subscription"}


# --------------------------------------------------------------------------- overrides

_OPTIONS = re.compile(r"Q[oO][sS]OverridingOptions|qos_overriding_options")
_DEFAULTS = re.compile(r"with_default_policies")
_DEFAULT_POLICIES = frozenset({"history", "depth", "reliability"})  # both libraries' default
_CPP_KIND = re.compile(r"QosPolicyKind\s*::\s*(\w+)")
_PY_KIND = re.compile(r"QoSPolicyKind\s*\.\s*([A-Z_]+)")
# an empty list: QosOverridingOptions(), {}, ({}), QoSOverridingOptions([]), (policy_kinds=())
_EMPTY = re.compile(r"Q[oO][sS]OverridingOptions\s*(?:\(\s*\)|\{\s*\}|\(\s*"
                    r"(?:policy_kinds\s*=\s*)?(?:\{\s*\}|\[\s*\]|\(\s*\))\s*\))")
_COMMENT = re.compile(r"/\*.*?\*/|(?://|#)[^\n]*", re.DOTALL)  # a commented-out id is none
_PY_ENTITY = re.compile(r"entity_id\s*=\s*(?:'([^']*)'|\"([^\"]*)\"|(None)\b|.)")


def overriding_of(texts: Iterable[str]) -> Overriding | None:
    """Return what an endpoint's options text opens to overrides (``None``: nothing).

    ``texts`` is the options argument, then (for a variable) the statements that set its
    ``qos_overriding_options``. C++ names policies ``QosPolicyKind::Reliability``, Python
    ``QoSPolicyKind.RELIABILITY``; ``with_default_policies`` opens history, depth and
    reliability. A list the text does not spell out is ``None``: not known here.
    """
    joined = " ".join(" ".join(_COMMENT.sub(" ", t).split()) for t in texts)
    if not _OPTIONS.search(joined):
        return None
    policies = {_snake(kind) for kind in _CPP_KIND.findall(joined)}
    policies |= {kind.lower() for kind in _PY_KIND.findall(joined)}
    policies.discard("invalid")
    if _DEFAULTS.search(joined):
        policies |= _DEFAULT_POLICIES
    if not policies:
        return None if _EMPTY.search(joined) else Overriding(None, _entity(joined))
    return Overriding(frozenset(policies), _entity(joined))


def _snake(kind: str) -> str:
    """``LivelinessLeaseDuration`` -> ``liveliness_lease_duration`` (rmw's names)."""
    return re.sub(r"(?<!^)(?=[A-Z])", "_", kind).lower()


def _entity(joined: str) -> str | None:
    """Return the options' id: rclpy's ``entity_id=``, rclcpp's last string argument.

    rclcpp takes it third (``{kinds}, callback, "id"``) or second (``with_default_policies(
    callback, "id")``); a third or second argument that is no literal is not known here.
    """
    python = _PY_ENTITY.search(joined)
    if python is not None:
        literal = python.group(1) if python.group(1) is not None else python.group(2)
        return literal if literal is not None else ("" if python.group(3) else None)
    arguments = _cpp_arguments(joined)
    if arguments is None or all(_CPP_KIND.search(a) for a in arguments):
        return ""  # none written, or the kinds themselves: {QosPolicyKind::Depth, ...}
    at = 1 if _DEFAULTS.search(joined) else 2
    if len(arguments) <= at:
        return ""
    literal = re.fullmatch(r'"([^"]*)"', arguments[at].strip())
    return None if literal is None else literal.group(1)


def _cpp_arguments(joined: str) -> list[str] | None:
    """Return the top-level arguments of the C++ options' construction, if one is written."""
    found = re.search(r"(?:QosOverridingOptions\s*(?:::\s*with_default_policies\s*)?|"
                      r"qos_overriding_options\s*=\s*)([({])", joined)
    if found is None:
        return None
    closing = {"(": ")", "{": "}"}[found.group(1)]
    depth, parts, current = 0, [], ""
    for char in joined[found.end():]:
        if char in "({[":
            depth += 1
        elif char in ")}]":
            if depth == 0:
                parts.append(current)
                return [p for p in parts if p.strip()] if char == closing else None
            depth -= 1
        elif char == "," and depth == 0:
            parts.append(current)
            current = ""
            continue
        current += char
    return None


def overridden(profile: Qos, topic: str, role: str, received: EffectiveParameters,
               python: bool = False) -> tuple[Qos, list[tuple[str, Contribution]]]:
    """Return ``profile`` with the ``qos_overrides`` the node receives applied.

    Only the policies its options open are read, under ``topic`` (the resolved, remapped
    name) and ``role`` (``publisher``, ``subscription``). A value not known before launch,
    or one that does not settle the policy, leaves it unknown; so does a parameter source
    that could not be read, and an id not known here makes every parameter of the topic and
    role that ends in the policy a candidate. rclpy reads a value whatever its case, rclcpp
    only lowercase. Also returns the values that settled a policy, with their names.
    """
    overriding = profile.overriding
    if overriding is None:
        return profile, []
    complete = _complete(received)
    changed: dict[str, str | None] = {}
    settled: list[tuple[str, Contribution]] = []
    for policy in JUDGED:
        if overriding.policies is not None and policy not in overriding.policies:
            continue
        if overriding.entity is None:  # under some id: any such parameter may be its own
            prefix, suffix = f"qos_overrides.{topic}.{role}", f".{policy}"
            if not complete or any(n.startswith(prefix) and n.endswith(suffix)
                                   for n in received.values):
                changed[policy] = None
            continue
        entity = f"_{overriding.entity}" if overriding.entity else ""
        name = f"qos_overrides.{topic}.{role}{entity}.{policy}"
        winner = received.winner(name)
        if winner is None:
            if not complete:
                changed[policy] = None
            continue
        changed[policy] = _settled(policy, winner.value, python) if (
            overriding.policies is not None) else None
        if changed[policy] is not None:
            settled.append((name, winner))
    reliability = changed.get("reliability", profile.reliability)
    durability = changed.get("durability", profile.durability)
    return replace(profile, reliability=reliability, durability=durability), settled


def _complete(received: EffectiveParameters) -> bool:
    """Return whether every source of the node's parameters was read and placed.

    A parameter file is read by node name: with the name not known, a block of the file
    may be the node's.
    """
    return received.complete and not (received.fqn is None and any(
        param.file is not None for param in received.node.parameters))


def _settled(policy: str, value: object, python: bool) -> str | None:
    """Return the policy an override value gives, ``None`` when it settles none."""
    if not isinstance(value, str):
        return None
    written = value.lower() if python else value
    return written if written in _SETTLED[policy] else None
