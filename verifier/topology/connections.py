"""Topics, services and actions: the composed endpoints of all nodes, grouped by name.

A topic gathers the publishers and subscriptions that resolve to one fully qualified name
(services and actions: servers and clients). Endpoints whose name is unknown are not
guessed into any of them; ``unresolved`` lists them with their reasons.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

from launchverify.topology.compose import ComposedEndpoint, NodeEndpoints
from launchverify.topology.model import EndpointKind

# kind -> (section, role)
ROLES: dict[EndpointKind, tuple[str, str]] = {
    EndpointKind.PUBLISHER: ("topics", "publishers"),
    EndpointKind.SUBSCRIPTION: ("topics", "subscribers"),
    EndpointKind.SERVICE: ("services", "servers"),
    EndpointKind.CLIENT: ("services", "clients"),
    EndpointKind.ACTION_SERVER: ("actions", "servers"),
    EndpointKind.ACTION_CLIENT: ("actions", "clients"),
}
SECTIONS = {"topics": ("publishers", "subscribers"), "services": ("servers", "clients"),
            "actions": ("servers", "clients")}


@dataclass
class Connection:
    """One fully qualified topic, service or action and the endpoints on it, by role."""

    section: str
    name: str
    ends: dict[str, list[ComposedEndpoint]] = field(default_factory=dict)

    def types(self) -> list[str]:
        """Return the distinct known types of its endpoints, sorted."""
        return sorted({e.endpoint.type for ends in self.ends.values() for e in ends
                       if e.endpoint.type is not None})

    def endpoints(self) -> list[ComposedEndpoint]:
        """Return every endpoint on it, role by role."""
        return [e for role in SECTIONS[self.section] for e in self.ends.get(role, [])]


def connections(nodes: Iterable[NodeEndpoints]) -> dict[str, list[Connection]]:
    """Group the resolved endpoints by section and name (names sorted)."""
    found: dict[tuple[str, str], Connection] = {}
    for node in nodes:
        for composed in node.endpoints:
            if composed.name is None:
                continue
            section, role = ROLES[composed.endpoint.kind]
            key = (section, composed.name)
            connection = found.setdefault(key, Connection(section, composed.name))
            connection.ends.setdefault(role, []).append(composed)
    out: dict[str, list[Connection]] = {section: [] for section in SECTIONS}
    for (section, _name), connection in sorted(found.items()):
        out[section].append(connection)
    return out
