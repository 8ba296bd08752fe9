"""LV506 unknown-container."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph, LoadRecord
from launchverify.ir.subst import Sub
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity
from launchverify.suggest import sole_spelling

CONTAINER_EXECUTABLES = ("component_container", "component_container_mt",
                         "component_container_isolated", "component_container_event")


class UnknownContainer(Rule):
    """Components loaded into a container whose name is not the one the launch starts.

    ## What it does
    Resolves the target of each `LoadComposableNodes(target_container=...)` and
    `<load_composable_node target="...">` as launch_ros does: a container action is that
    container; a name is taken from `/`, because launch's own node makes the request
    (`PushRosNamespace` does not apply to it). It reports a target that no node of the
    launch has, when a container the launch does start has nearly that name: the same
    name in another namespace (a namespace pushed around the container but written
    without it in the target), or a misspelling of it.

    A target that no container comes close to is not reported: the container may come
    from another launch or a robot's running system. Nor is one when a node's name is not
    known before launch, when a process started by command may be a container, when part
    of the launch could not be read, or in a file that another launch file includes,
    checked alone (its includers' namespaces decide where the container runs; it is
    judged through them).

    ## Why it matters
    launch_ros waits for `<target>/_container/load_node` with no timeout: the components
    never load, nothing is logged until shutdown (`Abandoning wait for the ... service`),
    and the launch never finishes starting.

    ## Example
    ```python
    GroupAction([PushRosNamespace('camera'),
                 ComposableNodeContainer(name='container', namespace='', package=
                                         'rclcpp_components', executable='component_container')]),
    LoadComposableNodes(target_container='container',  # the container is /camera/container
                        composable_node_descriptions=[...])
    ```

    ## Fix
    Give the container's full name (`/camera/container`), or pass the container action
    itself as `target_container`.
    """

    code = "LV506"
    slug = "unknown-container"
    severity = Severity.ERROR
    message = ("{count} loaded into {target}, which no node of this launch is: the load "
               "waits for it forever (did you mean {meant}?)")

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        loads = [load for load in graph.loads if graph.runs(load.origin) is not False
                 and load.target is not None]
        if not loads or not graph.launchable_alone() or not graph.complete_as_given():
            return  # an includer's namespaces may put the container where the target says
        if any(_may_host(graph, p.cmd) for p in graph.processes
               if graph.runs(p.origin) is not False):
            return  # a process started by command may be the container, renamed
        names: set[str] = set()
        containers: dict[str, object] = {}
        for node in graph.nodes:
            if graph.runs(node.origin) is False:
                continue
            fqn = graph.base(node.fqn)
            if fqn is None:
                return  # a node whose name is not known may be the container
            names.add(fqn)
            if node.kind == "node_container" or graph.base(node.executable) in \
                    CONTAINER_EXECUTABLES:
                containers[fqn] = node
        for load in loads:
            yield from self.load(graph, load, names, containers)

    def load(self, graph: LaunchGraph, load: LoadRecord, names: set[str],
             containers: dict[str, object]) -> Iterator[Finding]:
        """Yield the finding for one load whose target misses a container by a little."""
        written = graph.base(load.target) if load.target is not None else None
        if not written or not written.strip("/"):
            return
        target = "/" + written.strip("/")
        if target in names:
            return
        meant = _near(target, list(containers))
        if meant is None:
            return
        container = containers[meant]
        origin = getattr(container, "origin", None)
        related = () if origin is None else (Related(origin.span, f"{meant} is started here"),)
        count = f"{load.components} component{'s' * (load.components != 1)}"
        yield self.finding(load.origin, related=related, count=count, target=target,
                           meant=repr(meant))


def _may_host(graph: LaunchGraph, cmd: tuple[Sub, ...]) -> bool:
    """Return whether a process's command may start a container (or is not known)."""
    words = [graph.base(word) for word in cmd]
    return any(w is None or "container" in w for w in words)


def _near(target: str, containers: list[str]) -> str | None:
    """Return the container ``target`` nearly names: its name elsewhere, or one typo off.

    Examples:
        >>> _near("/container", ["/camera/container"]), _near("/camra/container",
        ...     ["/camera/container"]), _near("/other", ["/camera/container"])
        ('/camera/container', '/camera/container', None)
    """
    leaf = target.rsplit("/", 1)[-1]
    same_leaf = [c for c in containers if c.rsplit("/", 1)[-1] == leaf]
    if len(same_leaf) == 1:
        return same_leaf[0]
    return sole_spelling(target, containers)
