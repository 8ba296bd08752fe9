"""LV405 unknown-parameter."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator
from typing import TYPE_CHECKING

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Fix, Related, Rule, RuleContext, Severity, rename
from launchverify.span import Span
from launchverify.topology.model import soft_open

if TYPE_CHECKING:
    from launchverify.parameters import Contribution
    from launchverify.topology.contracts import Contract
    from launchverify.topology.wiring import WiringView
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
    when it declares a name built entirely at run time, when it uses a library known to
    declare parameters on it, or when its class derives from a node class whose code is
    not in the workspace. A node whose `NodeOptions` (or rclpy `Node` arguments) accept
    undeclared parameters, or that loads plugins, is judged for misspellings only: a
    name one edit from a name it or a plugin known to derive from what it loads declares
    (nav2's servers are judged with the plugins navigation2 ships; a key under a plugin's
    name, `FollowPath.desired_linear_vell`, against the plugin its `plugin` key names),
    while another name may be a plugin's own. Names built at run time keep their literal
    parts (`plugin_name + ".max_vel"` covers `FollowPath.max_vel`). A released package
    without sources here is judged by the model shipped with launchverify, extracted from
    the release of the distribution checked for (`--distro` or `ROS_DISTRO`: humble,
    jazzy, rolling); for any other distribution, or none, by what every release
    declares, and then only a name that misspells a declared one is reported (a name one
    release takes is no mistake). A name another release declares and the checked one
    does not (controller_server's `progress_checker_plugin`, humble's, is jazzy's
    `progress_checker_plugins`) is a warning that says which release declares it, with no
    fix; nor is a rename offered when the value's type is not the meant name's. Values
    given to every node (`/**` blocks, `SetParameter`) are meant for whichever nodes use
    them and are not judged, nor rcl's own parameters (`use_sim_time`, `qos_overrides.*`).

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
        from launchverify.topology.contracts import judged
        from launchverify.topology.wiring import describe_node

        found = judged(graph, ctx)
        if found is None:
            return
        view, contracts = found
        reported: set[tuple[object, ...]] = set()
        takers = _takers(view, contracts)
        for contract in contracts:
            if contract.open is not None and not soft_open(contract.open):
                continue
            known = frozenset(contract.concrete_names())  # remembered by the suggestions
            for name, given in contract.received.values.items():
                if contract.accepts(name):
                    continue
                for contribution in given:
                    span = contribution.span
                    where = _source(contribution, name)
                    if contribution.shared or where in reported:
                        continue
                    reported.add(where)  # one written value, reported once
                    if takers.get(_source(contribution, name), set()) - {id(contract)}:
                        continue  # one value given to several nodes: another one takes it
                    other = _other_releases(contract, name)
                    typo = None if other else (
                        sole_spelling(name, known) or contract.plugin_meant(name))
                    if typo is None and not other and contract.typos_only:
                        continue  # another release, or a plugin, may declare it
                    if other:
                        hint = f" (the {' and '.join(other)} release declares it)"
                    elif typo is None or typo in known:
                        hint = did_you_mean(name, known)
                    else:
                        hint = did_you_mean(name, frozenset({typo}))
                    finding = self.finding(
                        span, node=describe_node(view, contract.composed.node), name=name,
                        hint=hint,
                        what=f"with its default for '{typo}'" if typo else "without it",
                        related=(Related(contract.composed.node.origin.span,
                                         "the node is launched here"),),
                        fix=None if typo is None or not _same_kind(contract, typo, contribution)
                        else _rename_key(span, name, typo))
                    if typo is not None:
                        finding = dataclasses.replace(finding, severity=Severity.ERROR)
                    yield finding


def _other_releases(contract: Contract, name: str) -> tuple[str, ...]:
    """Return the other releases that declare a name the checked distribution's does not."""
    interface = contract.composed.interface
    if interface is None or interface.model is None or interface.distro is None:
        return ()
    from launchverify.topology.shipped import releases_declaring

    return tuple(d for d in releases_declaring(interface, name) if d != interface.distro)


def _same_kind(contract: Contract, meant: str, given: Contribution) -> bool:
    """Return whether renaming a key keeps a value the meant name's type takes.

    ``progress_checker_plugin: "x"`` renamed to the string array
    ``progress_checker_plugins`` would make the node throw: no fix is safe then.
    """
    declared = contract.static_type(meant)
    if declared is None or declared.type is None or given.kind == "unknown":
        return True
    return given.kind == declared.type or (declared.type, given.kind) == ("double", "integer")


def _takers(view: WiringView, contracts: list[Contract]) -> dict[tuple[object, ...], set[int]]:
    """Return, per place a value is written, the nodes it reaches that may take it.

    A dict or file given to several nodes (rtabmap's ``parameters`` list, passed to
    odometry, sync and SLAM alike) is meant for whichever of them declares each name: a
    name one of them takes, or one reaching a node whose declarations are not all known,
    is no mistake of the others.
    """
    from launchverify.parameters import effective_parameters
    from launchverify.topology.compose import named_record

    judged = {id(c.composed.node): c for c in contracts}
    reached: dict[tuple[object, ...], set[int]] = {}
    for composed in view.nodes:
        contract = judged.get(id(composed.node))
        received = contract.received if contract is not None else effective_parameters(
            view.graph, named_record(view.graph, composed))
        for name, given in received.values.items():
            takes = contract is None or contract.open is not None or contract.accepts(name)
            for contribution in given:
                taken = reached.setdefault(_source(contribution, name), set())
                if takes:  # (a contract by itself, another node by its record)
                    taken.add(id(contract) if contract is not None else id(composed))
    return reached


def _source(contribution: Contribution, name: str) -> tuple[object, ...]:
    """Return what identifies one written value across the nodes it is given to.

    A file's value by its place; an inline value by its file, name and value (a dict
    kept in a variable is written once, but each node's ``parameters=[...]`` names it at
    its own place).
    """
    span = contribution.span
    if contribution.layer == "file":
        return (span.file, span.line, span.column, name)
    return (span.file, name, repr(contribution.value))


def _rename_key(span: Span, name: str, meant: str) -> Fix | None:
    """Return the fix renaming a key: a file's key is the name's last part."""
    old, new = name.rpartition(".")[2], meant.rpartition(".")[2]
    if name.rpartition(".")[0] != meant.rpartition(".")[0]:
        return None
    return rename(span, old, new, unique=True)
