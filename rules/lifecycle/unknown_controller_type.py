"""LV509 unknown-controller-type."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import replace

from launchverify.graph import LaunchGraph
from launchverify.models import distros
from launchverify.models.ros2_control import SPAWNER
from launchverify.rule import (
    Applicability,
    Finding,
    Related,
    Rule,
    RuleContext,
    Severity,
    rename,
)
from launchverify.span import Span


class UnknownControllerType(Rule):
    """A ros2_control controller's type is one no plugin description exports.

    ## What it does
    Takes each spawned controller's type as the spawner and the manager decide it
    (`--controller-type`, a `type` in the spawner's `--param-file`, the manager's
    `<controller>.type` parameter) and looks for a plugin description that exports it:
    the shipped models of the released controllers (ros2_controllers, for the checked
    distribution, or for every release when none is given), the plugin descriptions a
    workspace package's `CMakeLists.txt` exports with
    `pluginlib_export_plugin_description_file(controller_interface ...)`, and those the
    ament index of an install prefix lists. A type that left ros2_controllers (Foxy's
    `joint_state_controller/JointStateController`, the gripper and joint-group
    specializations) is reported with what replaces it; a misspelt one with the closest
    type that exists.

    It stays silent unless nothing exporting the type is a fact: a type whose package
    is a vendor's (neither in the workspace nor modelled), a workspace package whose CMake
    files it cannot follow entirely, a type given by a launch argument, are not known.

    ## Why it matters
    The manager cannot load the controller (`Loader for controller 'joint_state_broadcaster'
    (type 'joint_state_controller/JointStateController') not found`), the spawner exits
    with an error, and the robot comes up without it: no `/joint_states`, no command
    topic. Old tutorials and copied configurations keep the names of older releases.

    ## Example
    ```yaml
    controller_manager:
      ros__parameters:
        joint_state_broadcaster:
          type: joint_state_controller/JointStateController  # Foxy's name
        diff_drive:
          type: diff_drive_controller/DiffDriveControler
    ```

    ## Fix
    Use the type the message names. Autofix: replaces the type where it is written as
    plain text: safe for a rename that needs nothing else and for a misspelling with a
    single close type, unsafe when the replacement behaves differently or the
    misspelling has several candidates; a replacement that needs another parameter
    (`interface_name` of `forward_command_controller/ForwardCommandController`) is not
    offered.
    """

    code = "LV509"
    slug = "unknown-controller-type"
    severity = Severity.ERROR
    message = ("controller '{name}' has type '{kind}', which no plugin description "
               "exports: {why}{hint}")

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        if not any((graph.base(n.package), graph.base(n.executable)) == SPAWNER
                   for n in graph.nodes):
            return
        from launchverify.topology.controller_types import controller_types
        from launchverify.topology.wiring import any_view

        view = any_view(graph, ctx)
        for composed in view.nodes:
            spawn = composed.spawn
            if spawn is None or spawn.kind is None or spawn.type_at is None:
                continue
            known = controller_types(ctx.memo_for(self.code), ctx.packages, distros.current())
            missing = known.missing(spawn.kind)
            if missing is None:
                continue
            hint = "" if missing.meant is None or missing.named else (
                f" (did you mean {missing.meant!r}?)")
            fix = None if missing.meant is None or missing.fix is None else rename(
                spawn.type_at if spawn.type_exact else None, spawn.kind, missing.meant,
                unique=missing.fix is Applicability.SAFE)
            origin = spawn.spawner.origin
            if _inside(spawn.type_at, origin.span):  # the spawner's --controller-type
                yield self.finding(replace(origin, span=spawn.type_at, call=origin.span),
                                   fix=fix, name=spawn.name, kind=spawn.kind,
                                   why=missing.why, hint=hint)
            else:  # a parameter file, the manager's parameters
                yield self.finding(spawn.type_at, related=(
                    Related(origin.span, f"the spawner of {spawn.name}"),), fix=fix,
                    name=spawn.name, kind=spawn.kind, why=missing.why, hint=hint)


def _inside(at: Span, call: Span) -> bool:
    """Return whether ``at`` lies on the lines of ``call``."""
    return at.file == call.file and call.line <= at.line <= (call.end_line or call.line)
