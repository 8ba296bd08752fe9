"""Each node's DDS domain and discovery range, from the environment its process gets.

launch gives a process the caller's environment, changed by the
``SetEnvironmentVariable``/``UnsetEnvironmentVariable``/``AppendEnvironmentVariable`` in
scope and then by the process's own ``additional_env`` (``ProcessSettings.env``, in that
order), or replaced whole by ``ExecuteProcess(env=...)``. A component runs in its
container's process.

rcl reads ``ROS_DOMAIN_ID`` (absent or empty: domain 0). From iron on it also reads
``ROS_AUTOMATIC_DISCOVERY_RANGE`` (``OFF``, ``LOCALHOST``, ``SUBNET``,
``SYSTEM_DEFAULT``; empty: ``SUBNET``; anything else: ``LOCALHOST``), which a
``ROS_LOCALHOST_ONLY`` starting with ``1`` overrides to ``LOCALHOST``. Humble knows only
``ROS_LOCALHOST_ONLY``. Launch starts every process on one machine, so only ``OFF`` keeps
two processes apart (rcl's ``discovery_options.c`` and ``init.c``).

What the launch does not set comes from the caller's environment, which launchverify does
not read: such a node is in the *caller's* domain, the same for every node that leaves it
alone, and its value is not known (``--env ROS_DOMAIN_ID=7`` says it). A caller's
discovery range is taken to be the default: were it ``OFF``, nothing would meet.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from launchverify.graph import LaunchGraph, LaunchRecord, NodeRecord
from launchverify.ir.subst import Sub
from launchverify.models import distros

DOMAIN = "ROS_DOMAIN_ID"
RANGE = "ROS_AUTOMATIC_DISCOVERY_RANGE"
LOCALHOST_ONLY = "ROS_LOCALHOST_ONLY"
CALLER = "<the caller's>"  # a value left to the environment launch is started in
RANGES = ("OFF", "LOCALHOST", "SUBNET", "SYSTEM_DEFAULT")


@dataclass(frozen=True, slots=True)
class Discovery:
    """A node's domain and discovery range, as texts (``None``: not known before launch).

    ``CALLER`` stands for a value the launch leaves to its caller's environment: equal for
    every node that leaves it, unknown otherwise. ``range`` is the range rcl uses, for the
    distribution checked; ``localhost_only`` is ``ROS_LOCALHOST_ONLY`` as given.
    ``process`` tells processes apart (components share their container's);
    ``domain_source`` is the expression the domain comes from, equal for equal settings.
    """

    domain: str | None
    range: str | None
    localhost_only: str | None = None
    process: int | None = field(default=None, compare=False)
    domain_source: object = field(default=None, compare=False)

    def same_domain(self, other: Discovery) -> bool | None:
        """Return whether two nodes share a domain (``None``: it depends on the caller).

        Examples:
            >>> Discovery("7", "SUBNET").same_domain(Discovery("07", "SUBNET"))
            True
            >>> Discovery(CALLER, "SUBNET").same_domain(Discovery("7", "SUBNET")) is None
            True
        """
        if self.domain_source is not None and self.domain_source == other.domain_source:
            return True
        if self.domain is None or other.domain is None:
            return None
        if self.domain == other.domain:
            return True
        if CALLER in (self.domain, other.domain):
            return None
        return domain_number(self.domain) == domain_number(other.domain)

    def off(self) -> bool | None:
        """Return whether the node discovers nothing outside its process."""
        if self.range is None:
            return None
        return self.range == "OFF"

    def meets(self, other: Discovery, assume_default: bool = False) -> bool | None:
        """Return whether two nodes discover each other (``None``: not known here).

        ``False`` only on facts: different domains the launch sets, or a range ``OFF``
        between two processes. Rules that report a collision or a meeting need ``True``;
        a rule that reports a node cut off needs ``False``. ``assume_default`` takes the
        caller's domain to be the default (0), which only a warning may rest on.
        """
        if self.process is not None and self.process == other.process:
            return True  # one process, one participant
        if assume_default:
            return self.defaulted().meets(other.defaulted())
        same = self.same_domain(other)
        if same is False or self.off() is True or other.off() is True:
            return False
        if same is None or self.off() is None or other.off() is None:
            return None
        return True

    def defaulted(self) -> Discovery:
        """Return this discovery with the caller's domain taken to be the default."""
        if self.domain != CALLER:
            return self
        return Discovery("0", self.range, self.localhost_only, self.process, "0")

    def why_apart(self, other: Discovery) -> str:
        """Return what keeps two nodes apart, for messages (``meets`` is ``False``)."""
        if self.off() is True:
            return "its discovery range is OFF"
        if other.off() is True:
            return "the other's discovery range is OFF"
        return f"domain {self.domain} against domain {other.domain}"


def discovery_of(graph: LaunchGraph, node: NodeRecord) -> Discovery:
    """Return the domain and discovery range of a node's process (computed once per node)."""
    kept = graph.derived.setdefault("discovery", {})
    found = kept.get(id(node))
    if isinstance(found, Discovery):
        return found
    launch = _process_of(graph, node)
    domain, source = _variable(graph, launch, DOMAIN, "0")
    localhost_only, _ = _variable(graph, launch, LOCALHOST_ONLY, "")
    range_given, _ = _variable(graph, launch, RANGE, "")
    found = Discovery(domain, effective_range(range_given, localhost_only),
                      localhost_only, None if launch is None else id(launch), source)
    kept[id(node)] = found
    return found


def meet(graph: LaunchGraph, first: NodeRecord, second: NodeRecord,
         assume_default: bool = False) -> bool | None:
    """Return whether two nodes discover each other (see ``Discovery.meets``)."""
    return discovery_of(graph, first).meets(discovery_of(graph, second), assume_default)


def effective_range(given: str | None, localhost_only: str | None) -> str | None:
    """Return the discovery range rcl uses, for the distribution being checked.

    Examples:
        >>> effective_range("OFF", "")
        'OFF'
        >>> effective_range("OFF", "1")
        'LOCALHOST'
        >>> effective_range("off", "")
        'LOCALHOST'
        >>> with distros.checking("humble"):
        ...     effective_range("OFF", "")
        'SUBNET'
    """
    if localhost_only is not None and localhost_only.startswith("1"):
        return "LOCALHOST"
    if distros.missing(RANGE) is not None:
        return "SUBNET"  # humble: the variable does not exist
    if given is None or localhost_only is None:
        return None  # not known; or the caller's ROS_LOCALHOST_ONLY=1 may override it
    if given == CALLER:
        return CALLER
    if given == "":
        return "SUBNET"
    return given if given in RANGES else "LOCALHOST"


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
              default: str) -> tuple[str | None, object]:
    """Return what a process's environment holds for ``name`` (``default`` when empty).

    With it the expression it comes from (``CALLER`` when the launch leaves it).
    """
    if launch is None:
        return None, None
    settings = launch.settings
    if settings.replace_env is not None:
        for key, value in reversed(settings.replace_env):
            if graph.base(key) == name:
                return _text(graph, value, default), value
        return default, default  # a replaced environment without it
    for written, set_to in reversed(settings.env):
        if written == name:
            if set_to is None:
                return default, default
            return _text(graph, set_to, default), set_to
    given = graph.environment.get(name)
    if given is None:
        return CALLER, CALLER
    return given or default, given or default


def _text(graph: LaunchGraph, value: Sub, default: str) -> str | None:
    text = graph.base(value)
    if text is None:
        return None
    return text.strip() or default


def domain_number(text: str | None) -> object:
    """Return a domain as rcl reads it (a number), or the text when it is not one."""
    if text is None:
        return None
    try:
        return int(text.strip(), 10)
    except ValueError:
        return text
