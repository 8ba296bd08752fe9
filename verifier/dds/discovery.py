"""Each node's DDS domain and discovery range, from the environment its process gets.

launch gives a process the caller's environment, changed by the
``SetEnvironmentVariable``/``UnsetEnvironmentVariable``/``AppendEnvironmentVariable`` in
scope and then by the process's own ``additional_env`` (``ProcessSettings.env``, in that
order), or replaced whole by ``ExecuteProcess(env=...)``. A component runs in its
container's process. rcl reads ``ROS_DOMAIN_ID`` (absent or empty: domain 0) and
``ROS_AUTOMATIC_DISCOVERY_RANGE`` (jazzy on; ``ROS_LOCALHOST_ONLY=1`` before it).

What the launch does not set comes from the caller's environment, which launchverify does
not read: such a node is in the *caller's* domain, the same for every node that leaves it
alone, and its value is not known (``--env ROS_DOMAIN_ID=7`` says it).
"""

from __future__ import annotations

from dataclasses import dataclass

from launchverify.graph import LaunchGraph, LaunchRecord, NodeRecord
from launchverify.ir.subst import Sub

DOMAIN = "ROS_DOMAIN_ID"
RANGE = "ROS_AUTOMATIC_DISCOVERY_RANGE"
LOCALHOST_ONLY = "ROS_LOCALHOST_ONLY"
CALLER = "<the caller's>"  # a value left to the environment launch is started in


@dataclass(frozen=True, slots=True)
class Discovery:
    """A node's domain and discovery range, as texts (``None``: not known before launch).

    ``CALLER`` stands for a value the launch leaves to its caller's environment: equal for
    every node that leaves it, unknown otherwise.
    """

    domain: str | None
    range: str | None

    def apart(self, other: Discovery) -> bool:
        """Return whether two nodes surely never discover each other (different domains).

        Only values the launch sets count: a domain not known, or the caller's beside a
        set one, may be the same.
        """
        return (self.domain is not None and other.domain is not None
                and CALLER not in (self.domain, other.domain)
                and _number(self.domain) != _number(other.domain))


def discovery_of(graph: LaunchGraph, node: NodeRecord) -> Discovery:
    """Return the domain and discovery range of a node's process (computed once per node)."""
    kept = graph.derived.setdefault("discovery", {})
    found = kept.get(id(node))
    if isinstance(found, Discovery):
        return found
    launch = _process_of(graph, node)
    found = Discovery(_variable(graph, launch, DOMAIN, "0"),
                      _variable(graph, launch, RANGE, "SUBNET"))
    kept[id(node)] = found
    return found


def _process_of(graph: LaunchGraph, node: NodeRecord) -> LaunchRecord | None:
    """Return the process a node runs in: its own, or its container's."""
    if node.container is None:
        return graph.launch_of(node)
    containers = graph.derived.get("containers_by_name")
    if not isinstance(containers, dict):  # built once per graph: components are many
        containers = {graph.base(r.fqn): r for r in graph.nodes if not r.composable}
        graph.derived["containers_by_name"] = containers
    name = graph.base(node.container)
    container = containers.get("/" + name.strip("/")) if name is not None else None
    return graph.launch_of(container) if isinstance(container, NodeRecord) else None


def _variable(graph: LaunchGraph, launch: LaunchRecord | None, name: str,
              default: str) -> str | None:
    """Return what a process's environment holds for ``name`` (``default`` when empty)."""
    if launch is None:
        return None
    settings = launch.settings
    if settings.replace_env is not None:
        for key, value in reversed(settings.replace_env):
            if graph.base(key) == name:
                return _text(graph, value, default)
        return default  # a replaced environment without it
    for written, set_to in reversed(settings.env):
        if written == name:
            return default if set_to is None else _text(graph, set_to, default)
    given = graph.environment.get(name)
    return CALLER if given is None else (given or default)


def _text(graph: LaunchGraph, value: Sub, default: str) -> str | None:
    text = graph.base(value)
    if text is None:
        return None
    return text.strip() or default


def _number(text: str) -> object:
    """Return a domain as rcl reads it (a number), or the text when it is not one."""
    try:
        return int(text.strip(), 10)
    except ValueError:
        return text
