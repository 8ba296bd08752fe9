"""LV305 duplicate-package."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Rule, RuleContext, Severity
from launchverify.workspace.paths import display_path


class DuplicatePackage(Rule):
    """A package name the launch uses is defined by two packages in the workspace.

    ## What it does
    Reports a reference to a package (`pkg=`, `$(find-pkg-share ...)`, an include) whose
    name two or more `package.xml` files of the workspace declare (folders marked
    `COLCON_IGNORE` do not count), naming every folder.

    ## Why it matters
    colcon refuses to build a workspace with duplicate package names, and until it is
    built nobody can tell which copy `ros2 launch` would use. launchverify resolves the
    name to the copy nearest to the files checked (the one sharing the most folders with
    them, as an overlay wins over an underlay; among equally near ones, the first it
    finds), so its findings may concern the other copy.

    ## Example
    ```text
    src/robot_bringup/package.xml          <name>robot_bringup</name>
    src/old/robot_bringup_v1/package.xml   <name>robot_bringup</name>
    ```

    ## Fix
    Rename one package, delete the stale copy, or mark its folder with `COLCON_IGNORE`.
    """

    code = "LV305"
    slug = "duplicate-package"
    severity = Severity.WARNING
    message = ("package '{name}' is defined {count} times in the workspace ({folders}): "
               "colcon refuses to build it; launchverify reads {first}")

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        if ctx.packages is None:
            return
        seen: set[str] = set()
        for ref in graph.packages:
            if ref.name in seen or graph.runs(ref.origin) is False:
                continue
            seen.add(ref.name)
            folders = ctx.packages.duplicates(ref.name)
            if folders:
                package = ctx.packages.find(ref.name)
                first = package.source if package is not None and package.source else folders[0]
                yield self.finding(ref.origin, name=ref.name, count=len(folders),
                                   folders=", ".join(display_path(f) for f in folders),
                                   first=display_path(first))
