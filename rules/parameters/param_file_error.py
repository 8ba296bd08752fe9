"""LV401 param-file-error."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

from launchverify.graph import LaunchGraph
from launchverify.models.rewritten_yaml import rewrite_of
from launchverify.parameters import file_readers
from launchverify.rule import Finding, Rule, RuleContext, Severity


class ParamFileError(Rule):
    """A parameter file a node loads is broken or does not say what it seems to.

    ## What it does
    Reads every parameter file that nodes of the launch load (`<param from=...>`,
    `parameters=[path]`, `ParameterFile`, `RewrittenYaml`, `SetParametersFromFile`) the way
    rcl's parameter parser does, and reports: YAML syntax errors; values before
    `ros__parameters` or `ros__parameters` without a node name (rcl rejects the file);
    lists mixing types such as `[0.05, 0]` (rcl: "Sequence should be of same type") and
    lists of lists; parameters without a value; node keys with no `ros__parameters`
    under them (ignored); duplicate keys (the last value wins; a node key or mapping
    written twice is merged by rcl but replaced by launch_ros). Files that only components
    loaded into a container read are read by launch_ros with `yaml.safe_load`, not rcl:
    for them only what YAML itself gets wrong is reported, and a file without any
    `ros__parameters` is one flat set of parameters, as launch_ros takes it. A file every
    node reads through nav2's `RewrittenYaml` reaches rcl as PyYAML writes it again: a key
    without a value (written `null` then) is no error there.

    ## Why it matters
    rcl refuses the whole file and the node does not start (`Couldn't parse params file`),
    or the node silently runs with other values than the file seems to give. Python's
    `yaml.safe_load` accepts all of these, so a quick check in a script does not catch them.

    ## Example
    ```yaml
    ekf_filter_node:
      ros__parameters:
        process_noise_covariance: [0.05, 0, 0]   # 0 is an integer
    ```

    ## Fix
    Write every number of a list the same way (`0.0`), put parameters under
    `<node>: ros__parameters:`, remove the duplicate key.
    """

    code = "LV401"
    slug = "param-file-error"
    severity = Severity.ERROR
    message = "{text}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        for path, param_file in graph.param_files.items():
            for problem in param_file.problems_for(reader_of(graph, path)):
                yield self.finding(problem.span, text=problem.message)


def reader_of(graph: LaunchGraph, path: Path) -> str:
    """Return what reads a file: rcl, launch_ros (components only), or nav2's rewrite.

    ``RewrittenYaml`` loads the file with ``yaml.safe_load`` and writes it out again for
    rcl: what only rcl refuses in the text as written (a key without a value, which the
    rewrite writes as ``null``) never reaches rcl when every node reads it that way.
    """
    if only_components(graph, path):
        return "launch_ros"
    readers = file_readers(graph).get(path, [])
    if readers and all(rewrite_of(param.file) is not None for _, param in readers):
        return "rewritten"
    return "rcl"


def only_components(graph: LaunchGraph, path: Path) -> bool:
    """Return whether only loaded components read a file (launch_ros reads it, not rcl)."""
    kinds = {node.kind for node, _ in file_readers(graph).get(path, [])}
    return bool(kinds) and kinds <= {"composable_node", "composable_lifecycle_node"}
