"""LV404 inconsistent-sim-time."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph, NodeRecord
from launchverify.parameters import effective_parameters
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity
from launchverify.smt import reasoner_for


class InconsistentSimTime(Rule):
    """Nodes that run together disagree on `use_sim_time`.

    ## What it does
    Resolves `use_sim_time` for every node of a launch (from `set_parameter`, parameter
    files and the node's own values, as ROS 2 merges them) and reports a launch where some
    nodes that can run together use simulated time and others do not (`false`, or not set:
    the default is `false`). The finding is on the first node that does not, names one
    that does, and gives the argument values under which they run together when those
    are not the defaults. Containers, static transform publishers, the Gazebo bridge and
    one-shot spawners (`ros_gz_sim create`, `spawn_entity.py`, controller `spawner`) are
    left out: their clock does not matter. Where the launch includes something
    launchverify cannot see, a node without the parameter is not judged (the include may
    set it with `set_parameter`).

    ## Why it matters
    Nodes on wall-clock time next to nodes on the `/clock` of a simulator or a bag see
    timestamps decades apart: TF lookups fail with extrapolation errors, message filters
    drop everything, timeouts fire at once. The node that was forgotten usually starts
    fine and fails much later, far from the launch file.

    ## Example
    ```xml
    <set_parameter name="use_sim_time" value="true"/>   <!-- only inside the group -->
    <node pkg="rviz2" exec="rviz2"/>                      <!-- on wall-clock time -->
    ```

    ## Fix
    Give every node the same value, typically with one `<set_parameter
    name="use_sim_time" value="$(var use_sim_time)"/>` at the top of the launch.
    """

    code = "LV404"
    slug = "inconsistent-sim-time"
    severity = Severity.WARNING
    message = ("use_sim_time is {state} for this node while nodes running with it use "
               "simulated time")

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        simulated: list[NodeRecord] = []
        wall_clock: list[tuple[NodeRecord, str]] = []
        for node in graph.nodes:
            if graph.runs(node.origin) is False or keeps_no_time(graph, node):
                continue
            winner = effective_parameters(graph, node).winner("use_sim_time")
            if winner is None:
                if graph.complete:  # else an include we could not see may set it
                    wall_clock.append((node, "not set"))
            elif winner.value is True:
                simulated.append(node)
            elif winner.value is False:
                wall_clock.append((node, "false"))
        if not simulated:
            return
        for node, state in wall_clock:
            partners = [s for s in simulated
                        if reasoner_for(graph).together(s.origin.path, node.origin.path)
                        is not None]
            if not partners:
                continue
            example = partners[0]
            witness = reasoner_for(graph).together(example.origin.path, node.origin.path)
            others = f"{_label(graph, example)} and {len(partners) - 1} more" if len(
                partners) > 1 else _label(graph, example)
            yield self.finding(
                node.origin,
                related=(Related(example.origin.span, f"use_sim_time is true for {others}"),),
                witness=(witness.values or None) if witness is not None else None,
                state=state,
            )
            return  # one finding per launch: the first node that is off


def _label(graph: LaunchGraph, node: NodeRecord) -> str:
    return graph.base(node.fqn) or node.executable_label()


# Nodes whose behaviour does not depend on the clock they use: containers (their
# components have their own parameters), static transforms (valid at any time), the
# Gazebo bridges and Webots' supervisor (stamps come from the simulator), filters that
# stamp their output with their input's stamps and read no clock for anything else
# (imu_filter_madgwick's ROS 2
# node, rtabmap's depth-to-cloud converters; not obstacles_detection, whose TF buffer
# runs on the node's clock) and one-shot helpers that spawn models or controllers and
# exit.
TIMELESS = frozenset({
    ("rclcpp_components", "component_container"),
    ("rclcpp_components", "component_container_mt"),
    ("rclcpp_components", "component_container_isolated"),
    ("ros_gz_bridge", "parameter_bridge"),
    ("ros_gz_image", "image_bridge"),  # converts gz images, stamps and all
    ("webots_ros2_driver", "ros2_supervisor.py"),  # Webots' clock: it publishes /clock
    ("imu_filter_madgwick", "imu_filter_madgwick_node"),  # stamps from the IMU messages
    ("rtabmap_util", "point_cloud_xyz"),  # clouds stamped as their images; now() only logs
    ("rtabmap_util", "point_cloud_xyzrgb"),
    ("tf2_ros", "static_transform_publisher"),
    ("ros_gz_sim", "create"),
    ("gazebo_ros", "spawn_entity.py"),
    ("controller_manager", "spawner"),
    ("controller_manager", "unspawner"),
    ("controller_manager", "hardware_spawner"),
})


def keeps_no_time(graph: LaunchGraph, node: NodeRecord) -> bool:
    """Return whether a node's clock does not matter (see ``TIMELESS``)."""
    if node.kind == "node_container":
        return True
    return (graph.base(node.package), graph.base(node.executable)) in TIMELESS
