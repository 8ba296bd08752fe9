"""LV405 unknown-parameter."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Fix, Related, Rule, RuleContext, Severity, rename
from launchverify.span import Span
from launchverify.suggest import did_you_mean, sole_spelling


class UnknownParameter(Rule):
    """A parameter given to a node whose code declares no such name.

    ## What it does
    Reads the parameters each launched node's code declares (`declare_parameter` in C++
    and Python, `declare_parameters`, nav2's `declare_parameter_if_not_declared`, read
    from the workspace's sources without building) and compares them with what the
    launch gives the node: its own parameter file blocks and inline values. A name the
    code never declares is reported at its key, with the declared name it probably
    misspells. It is an error when exactly one declared name is that close (one or two
    edits, or the same words shortened: `max_vel_x` for `max_velocity_x`; a safe fix
    renames the key), a warning otherwise.

    Only what is known is judged. A node is skipped when its sources were not all read,
    when its `NodeOptions` (or rclpy `Node` arguments) accept undeclared parameters, when
    it declares a name built entirely at run time, when it loads plugins (they declare
    names of their own), when it uses a library known to declare parameters on it
    (nav2_util), or when its class derives from a node class whose code is not in the
    workspace. Names built at run time keep their literal parts (`plugin_name +
    ".max_vel"` covers `FollowPath.max_vel`). For a released package known from the model
    shipped with launchverify (extracted from one release), only a name that misspells a
    declared one is reported: another release may declare more. Values given to every
    node (`/**` blocks, `SetParameter`) are meant for whichever nodes use them and are not
    judged, nor rcl's own parameters (`use_sim_time`, `qos_overrides.*`).

    ## Why it matters
    rclcpp and rclpy silently ignore an override for a parameter the node never
    declares. The node starts, logs nothing, and runs with its default: the robot drives
    at the default speed while the file says otherwise.

    ## Example
    ```yaml
    controller:
      ros__parameters:
        max_vel_x: 0.5      # the node declares max_velocity_x
    ```

    ## Fix
    Use the name the node declares (`ros2 param list` on the running node, or its
    documentation), or declare the parameter in the node's code.
    """

    code = "LV405"
    slug = "unknown-parameter"
    severity = Severity.WARNING
    every_context = True  # an includer's namespace decides which block a node reads
    message = ("{node} declares no parameter '{name}'{hint}: it is ignored, and the node "
               "runs {what}")

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        from launchverify.topology.contracts import contracts
        from launchverify.topology.wiring import any_view, describe_node, knows_code

        if not knows_code(graph, ctx):
            return
        view = any_view(graph, ctx)
        reported: set[tuple[object, ...]] = set()
        for contract in contracts(view):
            if contract.open is not None:
                continue
            known = contract.concrete_names()
            interface = contract.composed.interface
            modelled = interface is not None and interface.model is not None
            for name, given in contract.received.values.items():
                if contract.accepts(name):
                    continue
                for contribution in given:
                    span = contribution.span
                    where = (span.file, span.line, span.column, name)
                    if contribution.shared or where in reported:
                        continue
                    reported.add(where)
                    typo = sole_spelling(name, known)
                    if typo is None and modelled:
                        continue  # another release of the package may declare it
                    finding = self.finding(
                        span, node=describe_node(view, contract.composed.node), name=name,
                        hint=did_you_mean(name, known),
                        what=f"with its default for '{typo}'" if typo else "without it",
                        related=(Related(contract.composed.node.origin.span,
                                         "the node is launched here"),),
                        fix=None if typo is None else _rename_key(span, name, typo))
                    if typo is not None:
                        finding = dataclasses.replace(finding, severity=Severity.ERROR)
                    yield finding


def _rename_key(span: Span, name: str, meant: str) -> Fix | None:
    """Return the fix renaming a key: a file's key is the name's last part."""
    old, new = name.rpartition(".")[2], meant.rpartition(".")[2]
    if name.rpartition(".")[0] != meant.rpartition(".")[0]:
        return None
    return rename(span, old, new, unique=True)
