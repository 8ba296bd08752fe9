"""LV508 unknown-lifecycle-label."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.lifecycle.verdicts import report, unknown_handler_labels
from launchverify.rule import Finding, Rule, RuleContext, Severity


class UnknownLifecycleLabel(Rule):
    """A lifecycle event handler waits for a state or transition label no event carries.

    ## What it does
    Checks the labels of every `OnStateTransition(start_state=, goal_state=,
    transition=)` against rcl's state machine, at the argument to change, with the label
    most likely meant. launch_ros compares each with the event's label by `==`, so the
    handler never fires when a label is not one rcl publishes in its field
    (`'activated'`, `'configured'`, `'Active'`, `transition='activating'`, a
    substitution), or when a state is never left or reached (`start_state='finalized'`).
    Before rolling, rcl publishes
    events with an empty transition label (ros2/rcl#1019), so for a distribution checked
    (`--distro`, `ROS_DISTRO`) up to kilted any `transition=` is reported too. A handler
    with its own `matcher` is not checked: launch_ros then ignores the labels.

    What such a handler gates in the bring-up (the activation it would send, the nodes
    waiting for it) is LV503's. Labels rcl publishes, each in its field, that no single
    event carries together (`start_state='unconfigured', goal_state='inactive'`) await a
    transition the node cannot take from that state: LV504's.

    ## Why it matters
    Nothing is logged at all: the handler never fires, and what it runs (the activation,
    the nodes that wait for it) never starts. The robot sits with inactive drivers.

    ## Example
    ```python
    RegisterEventHandler(OnStateTransition(
        target_lifecycle_node=talker, goal_state='activated',  # rcl says 'active'
        entities=[Node(package='demo_nodes_cpp', executable='listener')]))
    ```

    ## Fix
    Write the labels rcl publishes, lower case: states `unconfigured`, `inactive`,
    `active`, `finalized` and the transition states `configuring`, `activating`, ...;
    filter on `start_state`/`goal_state` rather than `transition`.
    """

    code = "LV508"
    slug = "unknown-lifecycle-label"
    severity = Severity.ERROR
    message = "{text}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        for verdict in unknown_handler_labels(graph):
            yield report(self, verdict)
