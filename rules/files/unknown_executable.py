"""LV304 unknown-executable."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Rule, RuleContext, Severity, rename
from launchverify.suggest import closest, typos
from launchverify.workspace.package_executables import executables


class UnknownExecutable(Rule):
    """A node's executable is not one its package provides.

    ## What it does
    For nodes of packages launchverify can see, compares the executable with what the
    package installs into `lib/<package>/`: the files there when the package is
    installed, or else what its build files say it installs (ament_python console
    scripts; for ament_cmake, `add_executable` targets installed to
    `lib/${PROJECT_NAME}`, installed programs, `ament_auto_add_executable`,
    `rclcpp_components_register_node(... EXECUTABLE ...)`, followed through variables,
    functions and loops). Packages whose build files it cannot follow entirely, and
    released packages that are not installed, are not judged.

    ## Why it matters
    `ros2 launch` fails only when it reaches the node: `executable 'talkr' not found on
    the libexec directory`, after the nodes before it already started.

    ## Example
    ```xml
    <node pkg="demo_nodes_cpp" exec="talkr"/>
    ```

    ## Fix
    Use the executable's installed name (`ros2 pkg executables <package>` lists them).

    Autofix: renames the executable to the one the message suggests, where it is written
    as plain text; safe when that is its only close name (one or two edits away), unsafe
    otherwise.
    """

    code = "LV304"
    slug = "unknown-executable"
    severity = Severity.ERROR
    message = "package {package!r} has no executable {executable!r}{hint}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        if ctx.packages is None:
            return
        for node in graph.nodes:
            if node.kind not in ("node", "lifecycle_node", "node_container"):
                continue
            package_name, executable = graph.base(node.package), graph.base(node.executable)
            if not package_name or not executable:
                continue
            package = ctx.packages.find(package_name)
            if package is None:
                continue
            provided = executables(package)
            if provided is None or not provided.complete or executable in provided.names:
                continue
            meant = closest(executable, provided.names, cutoff=0.6)
            close = [meant] if meant is not None else []
            hint = f" (did you mean {close[0]!r}?)" if close else (
                f"; it installs {', '.join(sorted(provided.names)[:6])}"
                if provided.names else "")
            fix = None if not close else rename(
                node.executable_written, executable, close[0],
                unique=typos(executable, provided.names) == close)
            yield self.finding(node.origin, package=package_name, executable=executable,
                               hint=hint, fix=fix)
