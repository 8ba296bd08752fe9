"""LV406 parameter-type-mismatch."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Fix, Related, Rule, RuleContext, Severity, rename
from launchverify.span import Span


class ParameterTypeMismatch(Rule):
    """A node receives a parameter value whose type is not the one its code declares.

    ## What it does
    Reads each launched node's parameter declarations from the workspace's sources and
    the static type each one gets: the template argument (`declare_parameter<double>`),
    a `rclcpp::ParameterType` or `Parameter.Type`, else the default's type (`0.5` is a
    double, `1` an integer, `"x"` a string). It compares that type with the value the
    node finally receives from the launch (the last of its parameter sources, as rcl
    merges them) and reports a value of another type. A parameter declared with
    `dynamic_typing`, declared with different types in different places, or whose type
    the sources do not show is not judged; nor is a node whose parameter files are keyed
    by a name the launch does not give, nor one that declares parameters from its
    overrides (`automatically_declare_parameters_from_overrides`).

    ## Why it matters
    Both rclcpp and rclpy refuse the override when the node declares the parameter:
    `InvalidParameterTypeException` (`parameter 'max_vel' has invalid type: Wrong
    parameter type, parameter {max_vel} is of type {double}, setting it to {integer} is
    not allowed`). The node dies at start, often among dozens of others in the log. The
    usual cause is an integer where a double is declared: `1` for `1.0`.

    ## Example
    ```yaml
    controller:
      ros__parameters:
        max_vel: 1        # declared as declare_parameter("max_vel", 0.5): a double
    ```

    ## Fix
    Write the value with the declared type: `1.0` for a double (the safe fix adds the
    `.0`), quotes removed or added for strings, `true`/`false` for booleans.
    """

    code = "LV406"
    slug = "parameter-type-mismatch"
    severity = Severity.ERROR
    every_context = True
    message = ("{node} declares parameter '{name}' as {declared}, but receives {given} "
               "({value}): the node refuses it and fails at start")

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        from launchverify.topology.contracts import judged
        from launchverify.topology.wiring import describe_node

        found = judged(graph, ctx)
        if found is None:
            return
        view, contracts = found
        for contract in contracts:
            interface = contract.composed.interface
            if contract.unmatched is not None or not contract.received.complete or (
                    interface is not None and interface.parameters_undeclared):
                continue  # overrides declared from the command line come first, any type
            for name in sorted({p.name for p in contract.declared if "*" not in p.name}):
                declared = contract.static_type(name)
                winner = contract.received.winner(name)
                if declared is None or declared.type is None or winner is None or \
                        winner.kind in ("unknown", declared.type):
                    continue
                yield self.finding(
                    winner.span, node=describe_node(view, contract.composed.node), name=name,
                    declared=_article(declared.type), given=_article(winner.kind),
                    value=_shown(winner.value),
                    related=(Related(declared.span, f"'{name}' is declared here"),
                             Related(contract.composed.node.origin.span,
                                     "the node is launched here")),
                    fix=_as_double(winner.value_span, winner.value)
                    if (declared.type, winner.kind) == ("double", "integer") else None)


def _as_double(written: Span | None, value: object) -> Fix | None:
    """Return the safe fix that writes an integer as a double (``1`` -> ``1.0``)."""
    if written is None or not isinstance(value, int):
        return None
    return rename(written, str(value), f"{value}.0", unique=True)


def _article(kind: str) -> str:
    return f"an {kind}" if kind[0] in "aeiou" else f"a {kind}"


def _shown(value: object) -> str:
    text = repr(value) if isinstance(value, str) else str(value).lower() \
        if isinstance(value, bool) else str(value)
    return text if len(text) <= 40 else text[:39] + "\u2026"
