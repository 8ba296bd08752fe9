"""LV407 parameter-out-of-range."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity
from launchverify.topology.limits import allowed, failed_check


class ParameterOutOfRange(Rule):
    """A node receives a parameter value its declaration's validation rejects.

    ## What it does
    Reads the checks a node's code puts on its parameters (generate_parameter_library's
    `validation`: `bounds<>`, `gt<>`, `gt_eq<>`, `lt<>`, `lt_eq<>`, `one_of<>`, from the
    package's definition YAML) and reports a value the launch gives the node that fails
    one. Only values known before launch are judged (a value from an argument is judged
    under the arguments as given).

    ## Why it matters
    The generated parameter listener validates every value when the node starts and
    throws (`Invalid value set during initialization for parameter 'x': Value 2.5 not
    within bounds [0.0, 1.0]`): the node, or the controller, fails to start.

    ## Example
    ```yaml
    # definition: max_speed: {type: double, default_value: 1.0, validation: {bounds<>: [0.0, 2.0]}}
    base_controller:
      ros__parameters:
        max_speed: 3.5
    ```

    ## Fix
    Give a value the validation accepts; the definition YAML in the node's package says
    which (`ros2 param describe` on a running node shows it too).
    """

    code = "LV407"
    slug = "parameter-out-of-range"
    severity = Severity.ERROR
    every_context = True
    message = ("{node} receives {value} for parameter '{name}', which must be {allowed}: "
               "the node rejects it at start")

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        from launchverify.topology.contracts import judged
        from launchverify.topology.wiring import describe_node

        found = judged(graph, ctx)
        if found is None:
            return
        view, contracts = found
        for contract in contracts:
            if contract.unmatched is not None or not contract.received.complete:
                continue
            for declared in contract.declared:
                winner = contract.received.winner(declared.name) if declared.limits else None
                if winner is None or winner.value is None:
                    continue
                failed = failed_check(declared.limits, winner.value)
                if failed is None:
                    continue
                yield self.finding(
                    winner.span, node=describe_node(view, contract.composed.node),
                    name=declared.name, value=_shown(winner.value),
                    allowed=allowed(failed),
                    related=(Related(declared.span, f"'{declared.name}' is validated here"),))


def _shown(value: object) -> str:
    return repr(value) if isinstance(value, str) else str(value)
