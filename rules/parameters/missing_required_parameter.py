"""LV408 missing-required-parameter."""

from __future__ import annotations

import dataclasses
from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity


class MissingRequiredParameter(Rule):
    """A node declares a typed parameter without a default, and the launch never sets it.

    ## What it does
    Finds parameters the node's code declares with a type but no default
    (`declare_parameter<std::string>("robot_description")`,
    `declare_parameter("port", rclcpp::PARAMETER_INTEGER)`,
    `declare_parameter('port', Parameter.Type.INTEGER)`) that none of the node's parameter
    sources sets, `/**` blocks and `SetParameter` included. Only nodes whose parameters
    are all known are judged: every parameter file read, the node's name known when a
    file is keyed by it, and no `-p` or `--params-file` on its own command line.

    It is an error for rclcpp's template form, which throws at the declaration, and a
    warning for the typed forms, which throw when the node reads the parameter.

    ## Why it matters
    rclcpp's `declare_parameter<T>(name)` throws
    `UninitializedStaticallyTypedParameterException` (`Statically typed parameter 'x'
    must be initialized`) at start (humble to rolling). The other typed forms declare the
    parameter without a value, and `get_parameter` then throws
    `ParameterUninitializedException` (rclcpp and rclpy alike).

    ## Example
    ```python
    Node(package='my_driver', executable='driver')  # declares "port" with no default
    ```

    ## Fix
    Give the node the parameter (`parameters=[{'port': 4001}]`, or in its parameter
    file under the node's name).
    """

    code = "LV408"
    slug = "missing-required-parameter"
    severity = Severity.ERROR
    every_context = True
    message = ("{node} requires parameter '{name}' ({kind}, declared without a default), "
               "and the launch never sets it: {consequence}")

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        from launchverify.topology.contracts import contracts
        from launchverify.topology.wiring import describe_node, reads_sources, workspace_view

        if not reads_sources(graph, ctx):
            return
        view = workspace_view(graph, ctx)
        for contract in contracts(view):
            if not contract.values_known:
                continue
            required = {p.name: p for p in contract.declared
                        if p.required and "*" not in p.name}
            for name, declared in sorted(required.items()):
                if contract.received.values.get(name) or any(
                        not p.required for p in contract.declarations(name)):
                    continue
                finding = self.finding(
                    contract.composed.node.origin,
                    node=describe_node(view, contract.composed.node), name=name,
                    kind=declared.type or "typed",
                    consequence="the node throws at start" if declared.strict else
                    "the node throws when it reads it",
                    related=(Related(declared.span, f"'{name}' is declared here"),))
                if not declared.strict:
                    finding = dataclasses.replace(finding, severity=Severity.WARNING)
                yield finding
