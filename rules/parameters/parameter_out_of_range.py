"""LV407 parameter-out-of-range."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity

_WORDS = {"bounds": "within [{0}, {1}]", "gt": "greater than {0}", "gt_eq": "at least {0}",
          "lt": "less than {0}", "lt_eq": "at most {0}", "one_of": "one of {0}"}


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
                failed = next((limit for limit in declared.limits
                               if violates(limit, winner.value)), None)
                if failed is None:
                    continue
                check, arguments = failed
                yield self.finding(
                    winner.span, node=describe_node(view, contract.composed.node),
                    name=declared.name, value=_shown(winner.value),
                    allowed=_WORDS[check].format(*arguments, "", ""),
                    related=(Related(declared.span, f"'{declared.name}' is validated here"),))


def violates(limit: tuple[str, tuple[object, ...]], value: object) -> bool:
    """Return whether a value surely fails a check (``False`` when it cannot be told).

    Examples:
        >>> violates(("bounds", (0.0, 1.0)), 2.5), violates(("bounds", (0.0, 1.0)), 0.5)
        (True, False)
        >>> violates(("one_of", (["a", "b"],)), "c"), violates(("gt", (0,)), [1])
        (True, False)
    """
    check, arguments = limit
    if check == "one_of":
        choices = arguments[0] if arguments else None
        return isinstance(choices, list) and isinstance(value, (str, int, float)) and \
            value not in choices
    number = _number(value)
    limits = [_number(a) for a in arguments]
    if number is None or not limits or any(x is None for x in limits):
        return False
    if check == "bounds" and len(limits) == 2:
        low, high = limits
        return not (low <= number <= high)  # type: ignore[operator]
    bound = limits[0]
    assert bound is not None
    return {"gt": number <= bound, "gt_eq": number < bound, "lt": number >= bound,
            "lt_eq": number > bound}.get(check, False)


def _number(value: object) -> float | None:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return None
    return float(value)


def _shown(value: object) -> str:
    return repr(value) if isinstance(value, str) else str(value)
