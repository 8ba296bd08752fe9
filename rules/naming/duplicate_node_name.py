"""LV101 duplicate-node-name."""

from __future__ import annotations

import dataclasses
from collections import defaultdict
from collections.abc import Iterator

from launchverify.dds.discovery import meet
from launchverify.events import meeting_origin
from launchverify.graph import LaunchGraph, NodeRecord
from launchverify.ir import subst as s
from launchverify.ir.symbolic import Arg, Select, depends_on_unknowns, rests_on_unknowns
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity
from launchverify.smt import Witness, reasoner_for

CALLER_DOMAIN = (" if the caller's ROS_DOMAIN_ID is unset or 0 (the launch sets one node's "
                 "domain and leaves the other's to the environment it is started in)")


class DuplicateNodeName(Rule):
    """Two nodes that can run together can have the same fully qualified name.

    ## What it does
    Resolves every node's namespace (pushed namespaces, `namespace=`, absolute names) and
    name as ROS 2 does, and reports a node whose fully qualified name can equal another
    node's while both run. It checks every combination of the launch's *switches*
    (arguments with `choices`, or with a boolean default such as `use_sim:=true`), with
    the other arguments at their defaults or at the values given on the command line; the
    finding names the argument values that make the collision happen. Nodes under
    conditions that exclude each other (`if`/`unless` of one argument, different
    `LaunchConfigurationEquals` values) are not duplicates. A node launched without a
    namespace is in `/`. A file included twice into one namespace starts each of its
    nodes twice: the finding then names the include that started the first copy. A node
    an event handler starts is named in the scope launch has when the event comes: the
    group the handler is registered in has popped its pushed namespace by then, so two
    robots' handlers starting one name both start it in `/` (unless the handler's own
    entities push a namespace or give one).

    Arguments that are not switches (a `namespace` or `robot_name` argument) are not
    varied: they name one robot per launch, and letting them take any value would make
    every namespaced node collide with every other one. What the launch cannot know (an
    argument without default, an environment variable) only makes two names equal when
    they use it in the same place. Nodes under conditions launchverify cannot model are
    not compared, nor are nodes under conditions on what launchverify cannot know (a
    value of code it does not see, an environment variable): the user's arguments do
    not decide whether they run.

    Nodes in different DDS domains never see each other (`ROS_DOMAIN_ID` set per group,
    per node or per container), nor do two processes one of which turns discovery off
    (`ROS_AUTOMATIC_DISCOVERY_RANGE=OFF`, from iron on): they are no duplicates. A node
    whose domain the launch leaves to the environment it is started in is taken to be
    in the default domain 0, and a collision that rests on that is a warning.

    Two nodes that never run at the same time are not duplicates either: a node started
    by an `OnProcessExit` handler of the other one's process (or later in a chain of
    exits), or by an `OnExecutionComplete` handler of it, starts once the other has ended.
    When that process has `respawn` on, launch starts it again after the handler fired,
    so the pair is still reported (with the `respawn` argument as part of the witness when
    an argument sets it). Starting on the other's `OnProcessStart`, in a timer, or on the
    exit of an unrelated process is no such guarantee.

    ## Why it matters
    ROS 2 starts both. Parameter services, lifecycle transitions, `ros2 node` tools and
    logging then reach either node at random; launch itself only prints a warning.

    ## Example
    ```xml
    <arg name="use_sim" default="false"/>
    <node pkg="demo_nodes_cpp" exec="talker" name="talker"/>
    <node pkg="demo_nodes_py" exec="talker" name="talker" if="$(var use_sim)"/>
    ```
    (with `use_sim:=true`, two nodes are called `/talker`)

    ## Fix
    Rename one node, push it into its own namespace (`<group>` with
    `<push_ros_namespace>`), or make the conditions exclusive.
    """

    code = "LV101"
    slug = "duplicate-node-name"
    severity = Severity.ERROR
    message = "node name {fqn} is already used by the node at {other}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        switches = {n for n, d in reasoner_for(graph).domains.items() if d.switch}
        fixed_by_text: dict[str, list[NodeRecord]] = defaultdict(list)
        variable_by_name: dict[str, list[NodeRecord]] = defaultdict(list)
        all_by_name: dict[str, list[NodeRecord]] = defaultdict(list)
        seen: list[NodeRecord] = []
        position: dict[int, int] = {}  # launch order of the nodes seen
        for node in graph.nodes:
            if node.fqn is None or any(rests_on_unknowns(g) for g in node.origin.path):
                continue
            fixed = fixed_name(graph, node, switches)
            key = name_key(graph, node)
            if key == "*":
                candidates = [(n, False) for n in seen]
            elif fixed is not None:
                candidates = [(n, True) for n in fixed_by_text[fixed]]
                candidates += [(n, False) for n in variable_by_name[key]]
                candidates += [(n, False) for n in all_by_name["*"]]
            else:
                candidates = [(n, False) for n in (*all_by_name[key], *all_by_name["*"])]
            candidates.sort(key=lambda candidate: position[id(candidate[0])])
            found = first_collision(graph, node, candidates)
            if found is not None:
                other, fqn, witness = found
                other_at, related = _first_start(other, node)
                finding = self.finding(
                    node.origin,
                    related=(related,),
                    witness=witness.values or None,
                    fqn=fqn,
                    other=other_at,
                )
                if meet(graph, other, node) is None:  # only if the caller's domain is 0
                    finding = dataclasses.replace(
                        finding, severity=Severity.WARNING,
                        message=finding.message + CALLER_DOMAIN)
                yield finding
            position[id(node)] = len(seen)
            seen.append(node)
            all_by_name[key].append(node)
            if fixed is not None:
                fixed_by_text[fixed].append(node)
            else:
                variable_by_name[key].append(node)


def _first_start(first: NodeRecord, second: NodeRecord) -> tuple[str, Related]:
    """Say where the first node started: its line, or the include that started it.

    The include is what tells them apart when both are one line of a file included twice.
    """
    at = first.origin.span.short()
    if first.origin.span != second.origin.span or not first.origin.chain \
            or first.origin.chain == second.origin.chain:
        return at, Related(first.origin.span, "first started here")
    include = first.origin.chain[-1]
    return (f"{at} (this same node, started first through the include at {include.short()})",
            Related(include, "this same node started first through this include"))


def first_collision(graph: LaunchGraph, node: NodeRecord,
                    earlier: list[tuple[NodeRecord, bool]]
                    ) -> tuple[NodeRecord, str, Witness] | None:
    """Return the first earlier node this one can collide with (name, switches)."""
    for other, same_fixed_name in earlier:
        found = collision(graph, other, node, same_fixed_name)
        if found is not None:
            return (other, *found)
    return None


def collision(graph: LaunchGraph, first: NodeRecord, second: NodeRecord,
              same_fixed_name: bool) -> tuple[str, Witness] | None:
    """Return (name, witness) when two nodes can run together under one name.

    Together means at the same time: the event structure may keep them apart
    (``overlap_guards``). ``same_fixed_name``: both names are the same whatever the
    switches, so only the path conditions matter.
    """
    assert first.fqn is not None and second.fqn is not None
    first_origin = meeting_origin(graph, first, second)
    if first_origin is None:
        return None  # one starts only once the other has ended for good
    if not meet(graph, first, second, assume_default=True):
        return None  # DDS keeps them apart (domains, discovery off), or may
    if not _same_unknowns(graph, first.fqn, second.fqn):
        return None
    first_text, second_text = graph.base(first.fqn), graph.base(second.fqn)
    if (first_text is not None and first_text == second_text
            and graph.runs(first_origin) and graph.runs(second.origin)):
        return first_text, Witness()  # under the arguments as given: no solver needed
    reasoner = reasoner_for(graph)
    if same_fixed_name:
        witness = reasoner.together(first_origin.path, second.origin.path)
        shown = first_text if first_text is not None else first.fqn.describe()
        return None if witness is None else (shown, witness)
    found = reasoner.same_name(first.fqn, first_origin.path, second.fqn, second.origin.path)
    if found is None:
        return None
    witness, name = found
    return (name if "\x01" not in name else second.fqn.describe()), witness


def _same_unknowns(graph: LaunchGraph, first: s.Sub, second: s.Sub) -> bool:
    """Return whether two names hold what launchverify cannot know only in the same way.

    ``$(env NS '')/a`` reads as ``/a`` while the variable is unset, which the robot's
    environment decides: equal to a plain ``/a`` only by that assumption. The same
    unknown in the same place, under the arguments as given, is equal whatever it is.
    """
    if not (depends_on_unknowns(first) or depends_on_unknowns(second)):
        return True
    return graph.as_facts(first).describe() == graph.as_facts(second).describe()


def fixed_name(graph: LaunchGraph, node: NodeRecord, switches: set[str]) -> str | None:
    """Return a key for a name no switch changes (its text, or its expression), else None."""
    assert node.fqn is not None
    if _varies(node.fqn, switches):
        return None
    text = graph.base(node.fqn)
    return text if text is not None else "?" + node.fqn.describe()


def name_key(graph: LaunchGraph, node: NodeRecord) -> str:
    """Return the node's own name (the last segment), or ``*`` when it is not known."""
    name = graph.base(node.name)
    if name is None:
        fqn = graph.base(node.fqn)
        if fqn is None:
            return "*"
        name = fqn
    return name.rstrip("/").rpartition("/")[2]


def _varies(sub: s.Sub, switches: set[str]) -> bool:
    """Return whether a value can change with the switches (or with the path taken)."""
    return any(isinstance(part, Select) or (isinstance(part, Arg) and part.name in switches)
               for part in s.walk(sub))
