"""LV002 evaluation-error."""

from __future__ import annotations

from collections.abc import Iterator

from launchverify.graph import LaunchGraph
from launchverify.problems import ProblemKind
from launchverify.rule import Finding, Rule, RuleContext, Severity


class EvaluationError(Rule):
    """Evaluating the launch fails at run time, after the file loaded.

    ## What it does
    Reports what makes ros2 launch raise while it executes actions: a condition whose value
    is not `true`/`false`/`1`/`0`, an argument value outside its `choices`, `$(eval ...)`
    expressions Python rejects, boolean substitutions on non-booleans, a `for` loop length
    that is not an integer, and a `$(param)` with no `set_parameter` in scope (in files
    reached through includes: a file checked on its own may get it from its includer).
    Values that depend on arguments are checked with the default arguments too. A failure
    that a rule names is that rule's: a condition launch rejects is LV207, a process that
    event handlers run again is LV501.

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
