"""LV507 unknown-controller."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.models.ros2_control import SPAWNER
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity
from launchverify.suggest import did_you_mean


class UnknownController(Rule):
    """A ros2_control spawner names a controller its controller manager does not define.

    ## What it does
    Reads each `controller_manager spawner` command line (its controllers, `-c`/
    `--controller-manager`, `--param-file`, `--controller-type`), finds the manager it
    talks to among the launch's `ros2_control_node`s, and looks for the controller's type
    as the spawner and the manager do: `--controller-type`, else a `type` for the
    controller in the spawner's `--param-file`, else the manager's own `<controller>.type`
    parameter. It reports a controller whose type none of them gives, with the controller
    the manager does define that was probably meant.

    It stays silent whenever something it would rest on is not known: a manager this
    launch does not start (a simulator's plugin), a parameter file it cannot read or
    chooses by an argument, an argument not known before launch.

    ## Why it matters
    The spawner asks the manager to load the controller; the manager refuses (`The
    'type' param was not defined for '...'`), the spawner exits with an error, and
    the robot comes up without that controller: no `/joint_states`, no command topic.
    On a real robot this is often noticed only when it does not move.

    ## Example
    ```yaml
    controller_manager:
      ros__parameters:
        joint_state_broadcaster:
          type: joint_state_broadcaster/JointStateBroadcaster
    ```
    ```python
    Node(package='controller_manager', executable='spawner',
         arguments=['joint_states_broadcaster'])  # the manager defines joint_state_broadcaster
    ```

    ## Fix
    Spawn the controller under the name the manager's parameters give it, or define it
    there (`<name>: {type: package/Class}` under `controller_manager: ros__parameters:`),
    or give the spawner `--param-file` with its type.
    """

    code = "LV507"
    slug = "unknown-controller"
    severity = Severity.ERROR
    message = ("the spawner asks {manager} to load controller '{name}', which it does not "
               "define: {why}{hint}")

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        if not any((graph.base(n.package), graph.base(n.executable)) == SPAWNER
                   for n in graph.nodes):
            return
        from launchverify.topology.wiring import any_view

        view = any_view(graph, ctx)
        managers = {c.fqn: c for c in view.nodes if c.fqn is not None}
        for composed in view.nodes:
            spawn = composed.spawn
            if spawn is None or not spawn.undefined or spawn.manager is None:
                continue
            manager = managers.get(spawn.manager)
            related = () if manager is None else (
                Related(manager.node.origin.span, f"{spawn.manager} is launched here"),)
            yield self.finding(
                spawn.spawner.origin, related=related, manager=spawn.manager,
                name=spawn.name,
                why=(f"no parameter {spawn.name}.type, and no --param-file or "
                     "--controller-type of the spawner gives one"),
                hint=did_you_mean(spawn.name, spawn.defined))
