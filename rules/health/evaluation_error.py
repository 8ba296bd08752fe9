"""LV002 evaluation-error."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph, ProblemRecord
from launchverify.problems import ProblemKind
from launchverify.rule import Finding, Rule, RuleContext, Severity
from launchverify.smt import reasoner_for
from launchverify.smt.types import Witness


class EvaluationError(Rule):
    """Evaluating the launch fails at run time, after the file loaded.

    ## What it does
    Reports what makes ros2 launch raise while it executes actions: a condition whose value
    is not `true`/`false`/`1`/`0`, an argument value outside its `choices`, `$(eval ...)`
    expressions Python rejects, boolean substitutions on non-booleans, a `for` loop length
    that is not an integer, and a `$(param)` with no `set_parameter` in scope (in files
    reached through includes: a file checked on its own may get it from its includer).
    Values that depend on arguments are checked with the default arguments too. Launch
    evaluates an include's arguments and a node's fields only when the action's condition
    holds: a failure under a condition false with the default arguments is reported with
    arguments that make it true (`when: sensor:=oakd`), and not at all when none do. A
    failure that a rule names is that rule's: a condition launch rejects is LV207, a
    process that event handlers run again is LV501.

    ## Why it matters
    launch logs `Caught exception in launch` and shuts everything down; on a robot this
    happens after the first nodes already started.

    ## Example
    ```xml
    <arg name="mode" default="fast">
      <choice value="slow"/><choice value="safe"/>
    </arg>
    <node pkg="demo_nodes_cpp" exec="talker" if="$(var mode)"/>
    ```

    ## Fix
    Make values match what launch expects: booleans in conditions (`$(equals $(var mode)
    fast)`), a declared choice, valid Python.
    """

    code = "LV002"
    slug = "evaluation-error"
    severity = Severity.ERROR
    message = "{text}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        for record in graph.problems:
            if record.problem.contextual and not graph.launchable_alone():
                continue  # what an includer of this root provides is unknown here
            if record.problem.rule is not None:
                continue  # a rule names this failure, and reports it
            if record.problem.kind is ProblemKind.EVALUATION:
                yield self.finding(record.origin, text=record.problem.message)
            elif record.problem.kind is ProblemKind.CONDITIONAL and record.value is not None:
                found = reasoner_for(graph).fails(record.path, record.value)
                if found is not None:
                    yield self.finding(record.origin, witness=found[1].values, text=found[0])
            elif record.problem.kind is ProblemKind.CONDITIONAL:
                witness = conditional_witness(graph, record)
                if witness is not None:
                    yield self.finding(record.origin, witness=witness.values,
                                       text=record.problem.message)


def conditional_witness(graph: LaunchGraph, record: ProblemRecord) -> Witness | None:
    """Return arguments under which a ``CONDITIONAL`` failure's path holds, if any are found.

    Its path does not hold with the arguments as given: without such arguments there is
    no fact that launch ever evaluates what failed.
    """
    witness = reasoner_for(graph).reachable(record.path)
    return witness if witness is not None and witness.values else None


def never_evaluated(graph: LaunchGraph, record: ProblemRecord) -> bool:
    """Return whether a ``CONDITIONAL`` failure's path holds under no argument values."""
    return reasoner_for(graph).unreachable(record.path)
