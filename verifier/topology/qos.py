"""The QoS an endpoint is created with, as far as its code shows: reliability, durability.

Read from the text of the QoS argument (and, for a variable, of its initialiser and the
calls that change it): a named profile (``rclcpp::SensorDataQoS()``,
``qos_profile_sensor_data``, nav2's ``LatchedPublisherQoS``), a depth (the default:
reliable, volatile), then the policies set on it (``.best_effort()``,
``.transient_local()``, ``reliability=ReliabilityPolicy.BEST_EFFORT``). What the text does
not settle stays ``None``: a profile from a function, a parameter, the system default.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

RELIABLE, BEST_EFFORT = "reliable", "best_effort"
VOLATILE, TRANSIENT_LOCAL = "volatile", "transient_local"


@dataclass(frozen=True, slots=True)
class Qos:
    """An endpoint's reliability and durability (``None``: not known before run time)."""

    reliability: str | None
    durability: str | None
    overridable: bool = False  # built with QosOverridingOptions: qos_overrides.* apply

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
        return Qos(None, None, "QosOverridingOptions" in joined)
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
    return Qos(reliability, durability, "QosOverridingOptions" in joined)


def incompatible(writer: Qos, reader: Qos) -> str | None:
    """Return why a writer and a reader never match (rmw's rules), ``None`` if they may.

    A best-effort writer does not serve a reliable reader; a volatile writer does not
    serve a transient-local reader. The other way round is fine.
    """
    if writer.reliability == BEST_EFFORT and reader.reliability == RELIABLE:
        return "a best-effort publisher cannot serve a reliable subscription"
    if writer.durability == VOLATILE and reader.durability == TRANSIENT_LOCAL:
        return "a volatile publisher cannot serve a transient-local subscription"
    return None
