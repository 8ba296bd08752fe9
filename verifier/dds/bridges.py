"""What domain_bridge carries between DDS domains, read from its configuration.

A ``domain_bridge`` node takes a YAML file (its first argument, or the ``config`` of its
launch file): ``from_domain`` and ``to_domain``, then ``topics`` by name, each with its
``type`` and optionally its own domains or ``bidirectional: true``. A bridge whose file is
not known or cannot be read may carry anything (``None``).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import yaml

from launchverify.graph import LaunchGraph, LaunchRecord
from launchverify.workspace.reading import Unreadable, read_text

MAX_CONFIG_BYTES = 1_000_000


@dataclass(frozen=True, slots=True)
class Crossing:
    """One topic a bridge forwards from one domain to another."""

    topic: str  # as the bridge names it (relative names are in its namespace, usually /)
    type: str | None
    source: str
    target: str


def crossings(graph: LaunchGraph) -> list[Crossing] | None:
    """Return what every bridge of the launch forwards, ``None`` when one is not known."""
    kept = graph.derived.setdefault("bridges", {})
    if "crossings" in kept:
        known = kept["crossings"]
        return known if isinstance(known, list) else None
    found: list[Crossing] = []
    result: list[Crossing] | None = found
    for launch in graph.launches:
        node = launch.node
        if node is None or graph.base(node.package) != "domain_bridge" or \
                graph.runs(launch.origin) is False:
            continue
        read = _read(graph, launch)
        if read is None:
            result = None
            break
        found.extend(read)
    kept["crossings"] = result
    return result


def _read(graph: LaunchGraph, launch: LaunchRecord) -> list[Crossing] | None:
    words = [graph.base(a) for a in launch.arguments]
    configs = [w for w in words if w and w.endswith((".yaml", ".yml"))]
    if len(configs) != 1 or any(w is None for w in words):
        return None
    try:
        document = yaml.safe_load(read_text(Path(configs[0]), prefix=MAX_CONFIG_BYTES))
    except (Unreadable, OSError, yaml.YAMLError, ValueError):
        return None
    return parse(document)


def parse(document: object) -> list[Crossing] | None:
    """Return the topics a configuration forwards (``None`` when it is not one).

    Examples:
        >>> found = parse({"from_domain": 7, "to_domain": 0, "topics": {
        ...     "battery": {"type": "sensor_msgs/msg/BatteryState"},
        ...     "cmd": {"type": "std_msgs/msg/String", "bidirectional": True}}})
        >>> [(c.topic, c.source, c.target) for c in found]
        [('battery', '7', '0'), ('cmd', '7', '0'), ('cmd', '0', '7')]
    """
    if not isinstance(document, dict):
        return None
    topics = document.get("topics") or {}
    if not isinstance(topics, dict):
        return None
    found: list[Crossing] = []
    for name, options in topics.items():
        options = options if isinstance(options, dict) else {}
        source = options.get("from_domain", document.get("from_domain"))
        target = options.get("to_domain", document.get("to_domain"))
        if source is None or target is None:
            return None  # a default launch gives it: not known here
        kind = options.get("type")
        crossing = Crossing(str(name), str(kind) if kind is not None else None, str(source),
                            str(target))
        found.append(crossing)
        if options.get("bidirectional") is True:
            found.append(Crossing(crossing.topic, crossing.type, crossing.target,
                                  crossing.source))
    return found


def carried(bridges: list[Crossing], topic: str, source: str | None,
            target: str | None) -> bool:
    """Return whether some bridge forwards ``topic`` from one domain to the other."""
    return any(c.topic.strip("/") == topic.strip("/") and c.source == source
               and c.target == target for c in bridges)
