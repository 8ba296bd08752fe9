"""LV408 missing-required-parameter."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity
from launchverify.topology.limits import allowed, failed_check
from launchverify.topology.model import Parameter


class MissingRequiredParameter(Rule):
    """A node declares a typed parameter without a default, and the launch never sets it.

    ## What it does
    Finds parameters the node's code requires: declared with rclcpp's template form and
    no default (`declare_parameter<std::string>("port")`, nav2's
    `declare_or_get_parameter<T>(name)`), or defined without `default_value` in a
    generate_parameter_library YAML, outside any `try`. It reports one that none of the
    node's parameter sources sets, `/**` blocks and `SetParameter` included. Only nodes
    whose parameters are all known are judged: every parameter file read, the node's name
    known when a file is keyed by it, and no `-p` or `--params-file` on its own command
    line. A parameter declared with a type alone (`rclcpp::PARAMETER_STRING`,
    `Parameter.Type.STRING`) is declared unset; whether that fails depends on how the code
    reads it (`get_parameter(name, value)` just returns `false`), so it is not reported.
    A parameter whose default its own validation rejects is required too
    (diff_drive_controller's `wheel_separation`: default 0.0, must be greater than 0.0).

    ## Why it matters
    rclcpp's `declare_parameter<T>(name)` throws
    `UninitializedStaticallyTypedParameterException` (`Statically typed parameter 'x'
    must be initialized`) at start (humble to rolling); a generated parameter listener
    throws for a definition without a default; nav2's helper throws
    `InvalidParameterValueException`; a default that fails validation throws `Invalid value
    set during initialization`. The node dies before doing anything.

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
    message = ("{node} requires parameter '{name}' ({kind}, {why}), "
               "and the launch never sets it: the node throws at start")

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        from launchverify.topology.contracts import judged
        from launchverify.topology.wiring import describe_node

        found = judged(graph, ctx)
        if found is None:
            return
        view, contracts = found
        for contract in contracts:
            if not contract.values_known:
                continue
            required = {p.name: p for p in contract.declared
                        if _required(p) is not None and "*" not in p.name}
            for name, declared in sorted(required.items()):
                if contract.received.values.get(name) or any(
                        _required(p) is None for p in contract.declarations(name)):
                    continue
                finding = self.finding(
                    contract.composed.node.origin,
                    node=describe_node(view, contract.composed.node), name=name,
                    kind=declared.type or "typed", why=_required(declared),
                    related=(Related(declared.span, f"'{name}' is declared here"),))
                yield finding


def _required(declared: Parameter) -> str | None:
    """Return why a declaration needs a value from the launch, ``None`` when it does not.

    Declared without a default, or with a default its own validation rejects: the
    generated listener (and rclcpp, for a descriptor's range) checks the initial value
    and throws (diff_drive_controller's ``wheel_separation`` defaults to 0.0 and must be
    greater than 0.0).
    """
    if declared.required:
        return "declared without a default"
    if declared.default is None or not declared.limits:
        return None
    failed = failed_check(declared.limits, declared.default)
    if failed is None:
        return None
    return f"its default {declared.default!r} is not {allowed(failed)}"
