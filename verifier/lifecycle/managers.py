"""nav2 lifecycle managers: which nodes they bring up, and where they look for them.

A ``nav2_lifecycle_manager`` node (executable ``lifecycle_manager``, or the component
``nav2_lifecycle_manager::LifecycleManager``) reads ``node_names``; each name is a
relative ROS name resolved in the manager's own namespace (an absolute one is taken as
it is). With ``autostart: true`` it waits until every node's services exist, then
configures them all in list order, then activates them all in list order; a refused
transition aborts the bring-up (docs/launch-semantics §10.3).
"""

from __future__ import annotations

from dataclasses import dataclass

from launchverify.graph import LaunchGraph, NodeRecord
from launchverify.models.ros_names import expand_topic_name
from launchverify.parameters import effective_parameters
from launchverify.span import Span

MANAGER_PACKAGE = "nav2_lifecycle_manager"
MANAGER_EXECUTABLES = ("lifecycle_manager", "nav2_lifecycle_manager::LifecycleManager")


@dataclass(frozen=True)
class ManagerSpec:
    """What one lifecycle manager is asked to manage.

    ``names`` are the entries of ``node_names`` as written and ``resolved`` the FQNs the
    manager looks for (``None`` when the list is not known); ``autostart`` is ``None``
    when its value is not known.
    """

    record: NodeRecord
    fqn: str | None
    namespace: str
    names: tuple[str, ...] | None
    resolved: tuple[str, ...] | None
    autostart: bool | None
    names_span: Span | None


def is_manager(graph: LaunchGraph, record: NodeRecord) -> bool:
    """Return whether a node is a nav2 lifecycle manager."""
    return (graph.base(record.package) == MANAGER_PACKAGE
            and graph.base(record.executable) in MANAGER_EXECUTABLES)


def manager_spec(graph: LaunchGraph, record: NodeRecord) -> ManagerSpec:
    """Read a manager's ``node_names`` and ``autostart`` as the node receives them."""
    fqn = graph.base(record.fqn)
    namespace = graph.base(record.namespace) if record.namespace is not None else "/"
    parameters = effective_parameters(graph, record)
    listed = parameters.winner("node_names")
    names: tuple[str, ...] | None = None
    if listed is not None and isinstance(listed.value, (list, tuple)) and all(
            isinstance(item, str) for item in listed.value):
        names = tuple(listed.value)
    elif listed is None and parameters.complete:
        names = ()  # nothing to manage (the manager itself refuses to start)
    resolved = None
    if names is not None and fqn is not None and namespace is not None:
        node_name = fqn.rsplit("/", 1)[-1]
        resolved = tuple(resolve_name(name, namespace, node_name) for name in names)
    flag = parameters.winner("autostart")
    autostart: bool | None = False if flag is None and parameters.complete else None
    if flag is not None and isinstance(flag.value, bool):
        autostart = flag.value
    return ManagerSpec(record, fqn, namespace or "/", names, resolved, autostart,
                       listed.span if listed is not None else None)


def resolve_name(name: str, namespace: str, node_name: str) -> str:
    """Return the FQN a manager resolves one of its ``node_names`` to.

    Examples:
        >>> resolve_name("amcl", "/robot1", "lifecycle_manager")
        '/robot1/amcl'
        >>> resolve_name("/map_server", "/robot1", "lifecycle_manager")
        '/map_server'
    """
    return expand_topic_name(name, namespace, node_name)
