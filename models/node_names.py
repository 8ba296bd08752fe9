"""What common executables call their nodes, when the workspace has not their sources.

Two facts launch files rely on without writing them down. A node started without `name=`
is called what its code calls it: nav2's ``map_saver_server`` runs ``map_saver``, ros2_control's
``ros2_control_node`` runs ``controller_manager``. And a parameter file given to a process
reaches every node the process creates, not only the one launch names: nav2's controller
server runs a costmap node ``<ns>/local_costmap/local_costmap``, a ros2_control manager a
node per controller. Both tables are learned from the packages' sources (navigation2: the
servers' constructors, ``Costmap2DROS`` child options, ``BtActionServer`` client nodes;
ros2_control: ``ros2_control_node``'s main and one node per controller, in the manager's
namespace).
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass


@dataclass(frozen=True)
class InnerNode:
    """A node created inside a process: where, relative to the process's own node."""

    namespace: str  # relative to the process node's namespace ("" for the same one)
    name: str  # a glob; "{node}" is the process node's own name

    def pattern(self, node_name: str | None) -> str:
        """Return the name as a glob, the process node's name filled in (``*`` unknown)."""
        return self.name.replace("{node}", node_name if node_name is not None else "*")


# (package, executable) -> the name its code gives the node launch starts
BUILTIN_NAMES: dict[tuple[str, str], str] = {
    ("controller_manager", "ros2_control_node"): "controller_manager",
    ("nav2_map_server", "map_saver_server"): "map_saver",
    ("nav2_lifecycle_manager", "lifecycle_manager"): "lifecycle_manager",
    **{(package, executable): executable for package, executable in (
        ("nav2_amcl", "amcl"), ("nav2_behaviors", "behavior_server"),
        ("nav2_bt_navigator", "bt_navigator"), ("nav2_collision_monitor", "collision_monitor"),
        ("nav2_collision_monitor", "collision_detector"),
        ("nav2_controller", "controller_server"), ("nav2_loopback_sim", "loopback_simulator"),
        ("nav2_map_server", "map_server"),
        ("nav2_map_server", "costmap_filter_info_server"), ("nav2_planner", "planner_server"),
        ("nav2_route", "route_server"), ("nav2_smoother", "smoother_server"),
        ("nav2_velocity_smoother", "velocity_smoother"),
        ("nav2_waypoint_follower", "waypoint_follower"),
    )},
}


def builtin_name(package: str | None, executable: str | None) -> str | None:
    """Return the name an executable's code gives its node, when known here.

    Examples:
        >>> builtin_name("nav2_map_server", "map_saver_server")
        'map_saver'
        >>> builtin_name("demo_nodes_cpp", "talker") is None
        True
    """
    if package is None or executable is None:
        return None
    return BUILTIN_NAMES.get((package, executable))


INNER_NODES: dict[tuple[str, str], tuple[InnerNode, ...]] = {
    ("nav2_controller", "controller_server"): (InnerNode("local_costmap", "local_costmap"),),
    ("nav2_planner", "planner_server"): (InnerNode("global_costmap", "global_costmap"),),
    ("nav2_bt_navigator", "bt_navigator"): (InnerNode("", "{node}_*_rclcpp_node"),),
}

# Processes that start a node per controller: listed as ``<controller>.type`` in the
# manager's parameters, or (jazzy on) a block of the controller's own holding ``type``.
CONTROLLER_MANAGERS = frozenset({
    ("controller_manager", "ros2_control_node"),
})


def inner_nodes(package: str | None, executable: str | None,
                parameters: Iterable[tuple[str, str]] = ()) -> tuple[InnerNode, ...]:
    """Return the nodes a process creates inside, given the parameters its files hold.

    ``parameters`` are ``(block's node name, parameter name)`` pairs.

    Examples:
        >>> [n.name for n in inner_nodes("controller_manager", "ros2_control_node",
        ...     [("controller_manager", "arm_controller.type"), ("gripper", "type")])]
        ['arm_controller', 'gripper']
        >>> inner_nodes("demo_nodes_cpp", "talker")
        ()
    """
    if package is None or executable is None:
        return ()
    found = INNER_NODES.get((package, executable), ())
    if (package, executable) in CONTROLLER_MANAGERS:
        found += tuple(InnerNode("", name) for name in controller_names(parameters))
    return found


def controller_names(parameters: Iterable[tuple[str, str]]) -> list[str]:
    """Return the controllers parameter files declare, in order.

    A manager's ``<name>.type``, or a block of the controller's own with ``type`` in it.
    """
    names = []
    for node, parameter in parameters:
        if parameter == "type" and node not in ("*", "**"):
            names.append(node)
        elif parameter.endswith(".type") and "." not in parameter.removesuffix(".type"):
            names.append(parameter.removesuffix(".type"))
    return list(dict.fromkeys(name for name in names if name))
