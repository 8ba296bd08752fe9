"""LV303 unknown-package."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.models.known_packages import is_released, released_packages
from launchverify.rule import Finding, Rule, RuleContext, Severity
from launchverify.suggest import typo_of


class UnknownPackage(Rule):
    """A package named in the launch exists nowhere.

    ## What it does
    Looks up every package a launch file names (`pkg=`, `$(find-pkg-share)`,
    `$(find-pkg-prefix)`, `$(exec-in-pkg)`) in the workspace and, when ROS 2 is installed,
    in `AMENT_PREFIX_PATH`. Without an installation, a package missing from the workspace
    may still be installed on the robot; it is reported only when it is not a released
    ROS 2 package and is one or two edits away from a package that exists: a typo.

    ## Why it matters
    ros2 launch stops with `PackageNotFoundError` when it reaches the reference.

    ## Example
    ```xml
    <node pkg="demo_node_cpp" exec="talker"/>
    ```

    ## Fix
    Correct the package name, or add the package to the workspace or the system.
    """

    code = "LV303"
    slug = "unknown-package"
    severity = Severity.ERROR
    message = "package {name!r} is {where}{hint}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        installed = ctx.packages is not None and ctx.packages.has_install
        local = ctx.packages.names() if ctx.packages is not None else []
        seen: set[object] = set()
        for ref in graph.packages:
            key = (ref.name, ref.origin.span)
            if ref.found or key in seen:
                continue
            seen.add(key)
            typo = typo_of(ref.name, frozenset(local)) or typo_of(ref.name, released_packages())
            if installed:
                where = "neither in the workspace nor installed"
            elif is_released(ref.name) or typo is None:
                continue  # may be installed on the robot; only a near miss is a sure typo
            else:
                where = "not in the workspace and not a released ROS 2 package"
            hint = f" (did you mean {typo!r}?)" if typo else ""
            yield self.finding(ref.origin, name=ref.name, where=where, hint=hint)
