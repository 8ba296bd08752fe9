"""LV101 duplicate-node-name."""

from __future__ import annotations

import dataclasses
from collections import defaultdict
from collections.abc import Iterator
from typing import TYPE_CHECKING

from launchverify.dds.discovery import meet
from launchverify.evaluate.values import ns_prefix
from launchverify.events import meeting_origin
from launchverify.graph import LaunchGraph, NodeRecord
from launchverify.ir import subst as s
from launchverify.ir.symbolic import Arg, Select, depends_on_unknowns, rests_on_unknowns
from launchverify.rule import Finding, Related, Rule, RuleContext, Severity
from launchverify.smt import Witness, reasoner_for

if TYPE_CHECKING:  # composition is imported only when two unnamed nodes may collide
    from launchverify.topology.compose import CodeName

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

    A node the launch does not name (no `name=`) runs under the name its code gives it:
    `rclcpp::Node("talker")`, `super().__init__('talker')`, a component's constructor.
    Two such nodes are compared under those names where they are facts: the package's
    sources in the workspace, or the interface model shipped for a released package
    (`robot_state_publisher` is `/robot_state_publisher`), give one literal name; package
    and executable (or plugin) do not depend on arguments; no remap rule renames or moves
    the node (`-r __node:=` in `arguments` or `ros_arguments`, `remappings` or `SetRemap`
    of `__node` or `__ns`, or one not known before launch); and its namespace holds
    nothing launchverify cannot know. The finding then says that the code names both and
    points at where it does (a model extracted without that place names the sources it
    was extracted from). An executable whose code creates several nodes, or computes its
    node's name, is not compared; nor is a node without `name=` with one the launch names.
    Interfaces are read for this only when two unnamed nodes of known code may share a
    namespace.

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

    ```xml
    <node pkg="robot_state_publisher" exec="robot_state_publisher"/>
    <node pkg="robot_state_publisher" exec="robot_state_publisher"/>
    ```
    (neither is named: both run as `/robot_state_publisher`, the name its code gives)

    ## Fix
    Rename one node (`name=`), push it into its own namespace (`<group>` with
    `<push_ros_namespace>`), or make the conditions exclusive.
    """

    code = "LV101"
    slug = "duplicate-node-name"
    severity = Severity.ERROR
    message = "node name {fqn} is already used by the node at {other}"

    def check(self, graph: LaunchGraph, ctx: RuleContext) -> Iterator[Finding]:
        switches = {n for n, d in reasoner_for(graph).domains.items() if d.switch}
        named = [(node, node.fqn) for node in graph.nodes if node.fqn is not None]
        for node, other, fqn, witness in duplicates(graph, named, switches):
            yield self._report(graph, node, other, fqn, witness)
        coded = code_named(graph, ctx, switches)  # compared with each other only
        given = {id(node): code for node, _, code in coded}
        for node, other, fqn, witness in duplicates(
                graph, [(node, name) for node, name, _ in coded], switches):
            finding = self._report(graph, node, other, fqn, witness)
            yield _from_code(finding, given[id(other)], given[id(node)])

    def _report(self, graph: LaunchGraph, node: NodeRecord, other: NodeRecord, fqn: str,
                witness: Witness) -> Finding:
        """Return the finding on ``node``, whose name ``other`` (started first) has."""
        other_at, related = _first_start(other, node)
        finding = self.finding(node.origin, related=(related,),
                               witness=witness.values or None, fqn=fqn, other=other_at)
        if meet(graph, other, node) is None:  # only if the caller's domain is 0
            finding = dataclasses.replace(finding, severity=Severity.WARNING,
                                          message=finding.message + CALLER_DOMAIN)
        return finding


Named = tuple[NodeRecord, s.Sub]  # a node and its fully qualified name


def duplicates(graph: LaunchGraph, nodes: list[Named], switches: set[str]
               ) -> Iterator[tuple[NodeRecord, NodeRecord, str, Witness]]:
    """Yield ``(node, other, name, witness)`` for each node an earlier one's name can take.

    Candidates are found by name (the text no switch changes, else the last segment); a
    node whose name is not known is compared with every earlier one.
    """
    fixed_by_text: dict[str, list[Named]] = defaultdict(list)
    variable_by_name: dict[str, list[Named]] = defaultdict(list)
    all_by_name: dict[str, list[Named]] = defaultdict(list)
    seen: list[Named] = []
    position: dict[int, int] = {}  # launch order of the nodes seen
    for entry in nodes:
        node, fqn = entry
        if any(rests_on_unknowns(g) for g in node.origin.path):
            continue
        fixed = fixed_name(graph, fqn, switches)
        key = name_key(graph, node.name, fqn)
        if key == "*":
            candidates = [(n, False) for n in seen]
        elif fixed is not None:
            candidates = [(n, True) for n in fixed_by_text[fixed]]
            candidates += [(n, False) for n in variable_by_name[key]]
            candidates += [(n, False) for n in all_by_name["*"]]
        else:
            candidates = [(n, False) for n in (*all_by_name[key], *all_by_name["*"])]
        candidates.sort(key=lambda candidate: position[id(candidate[0][0])])
        found = first_collision(graph, entry, candidates)
        if found is not None:
            yield (node, *found)
        position[id(node)] = len(seen)
        seen.append(entry)
        all_by_name[key].append(entry)
        if fixed is not None:
            fixed_by_text[fixed].append(entry)
        else:
            variable_by_name[key].append(entry)


def code_named(graph: LaunchGraph, ctx: RuleContext,
               switches: set[str]) -> list[tuple[NodeRecord, s.Sub, CodeName]]:
    """Return the nodes the launch does not name, named as their code names them.

    Cheap unless it matters: interfaces are read only when two such nodes of packages
    whose code is known (sources here, or a shipped model) may share a namespace, and
    only theirs (two in different namespaces cannot collide, whatever their code). A
    node whose namespace holds what launchverify cannot know is left out.
    """
    from launchverify.topology.wiring import has_code

    unnamed = []
    for node in graph.nodes:
        if node.name is not None or any(rests_on_unknowns(g) for g in node.origin.path) or (
                node.namespace is not None and depends_on_unknowns(node.namespace)):
            continue
        package = _fixed_text(graph, node.package, switches)
        if package is not None and _fixed_text(graph, node.executable, switches) is not None \
                and has_code(ctx, package):
            unnamed.append(node)
    spaces = [_namespace_key(graph, node, switches) for node in unnamed]
    if len(unnamed) < 2 or ("*" not in spaces and len(set(spaces)) == len(spaces)):
        return []  # no two can share a namespace: nothing to read
    from launchverify.topology.compose import code_name
    from launchverify.topology.wiring import interfaces_of

    source = interfaces_of(ctx)
    found = []
    for node in unnamed:
        code = code_name(graph, source, node)
        if code is not None:
            namespace = node.namespace if node.namespace is not None else s.Text("/")
            fqn = ns_prefix(namespace, s.Text(code.name))
            assert fqn is not None
            found.append((node, fqn, code))
    return found


def _fixed_text(graph: LaunchGraph, value: s.Sub | None, switches: set[str]) -> str | None:
    """Return a value's text when no switch changes it and launchverify knows it."""
    if value is None or _varies(value, switches) or depends_on_unknowns(value):
        return None
    return graph.base(value)


def _namespace_key(graph: LaunchGraph, node: NodeRecord, switches: set[str]) -> str:
    """Return a node's namespace as text (``/`` when the launch gives none), ``*``: may vary."""
    if node.namespace is None:
        return "/"
    return _fixed_text(graph, node.namespace, switches) or "*"


def _from_code(finding: Finding, first: CodeName, second: CodeName) -> Finding:
    """Say that the launch names neither node, and where their code gives the name."""
    codes = [second] if _place(first) == _place(second) else [second, first]
    places = " and ".join(_place(code) for code in codes)
    related = tuple(Related(code.at, f"the code names the node {code.name} here")
                    for code in codes if code.at is not None)
    return dataclasses.replace(
        finding, related=(*finding.related, *related),
        message=(f"{finding.message}; the launch names neither node, so each runs under "
                 f"the name its code gives it ({places})"))


def _place(code: CodeName) -> str:
    """Return where the code gives the name: its line, else what it was read from."""
    if code.at is None:
        return code.origin
    return f"{code.at.short()} in {code.origin}"


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


def first_collision(graph: LaunchGraph, entry: Named, earlier: list[tuple[Named, bool]]
                    ) -> tuple[NodeRecord, str, Witness] | None:
    """Return the first earlier node this one can collide with (name, switches)."""
    for other, same_fixed_name in earlier:
        found = collision(graph, other, entry, same_fixed_name)
        if found is not None:
            return (other[0], *found)
    return None


def collision(graph: LaunchGraph, first_entry: Named, second_entry: Named,
              same_fixed_name: bool) -> tuple[str, Witness] | None:
    """Return (name, witness) when two nodes can run together under one name.

    Together means at the same time: the event structure may keep them apart
    (``overlap_guards``). ``same_fixed_name``: both names are the same whatever the
    switches, so only the path conditions matter.
    """
    (first, first_fqn), (second, second_fqn) = first_entry, second_entry
    first_origin = meeting_origin(graph, first, second)
    if first_origin is None:
        return None  # one starts only once the other has ended for good
    if not meet(graph, first, second, assume_default=True):
        return None  # DDS keeps them apart (domains, discovery off), or may
    if not _same_unknowns(graph, first_fqn, second_fqn):
        return None
    first_text, second_text = graph.base(first_fqn), graph.base(second_fqn)
    if (first_text is not None and first_text == second_text
            and graph.runs(first_origin) and graph.runs(second.origin)):
        return first_text, Witness()  # under the arguments as given: no solver needed
    reasoner = reasoner_for(graph)
    if same_fixed_name:
        witness = reasoner.together(first_origin.path, second.origin.path)
        shown = first_text if first_text is not None else first_fqn.describe()
        return None if witness is None else (shown, witness)
    found = reasoner.same_name(first_fqn, first_origin.path, second_fqn, second.origin.path)
    if found is None:
        return None
    witness, name = found
    return (name if "\x01" not in name else second_fqn.describe()), witness


def _same_unknowns(graph: LaunchGraph, first: s.Sub, second: s.Sub) -> bool:
    """Return whether two names hold what launchverify cannot know only in the same way.

    ``$(env NS '')/a`` reads as ``/a`` while the variable is unset, which the robot's
    environment decides: equal to a plain ``/a`` only by that assumption. The same
    unknown in the same place, under the arguments as given, is equal whatever it is.
    """
    if not (depends_on_unknowns(first) or depends_on_unknowns(second)):
        return True
    return graph.as_facts(first).describe() == graph.as_facts(second).describe()


def fixed_name(graph: LaunchGraph, fqn: s.Sub, switches: set[str]) -> str | None:
    """Return a key for a name no switch changes (its text, or its expression), else None."""
    if _varies(fqn, switches):
        return None
    text = graph.base(fqn)
    return text if text is not None else "?" + fqn.describe()


def name_key(graph: LaunchGraph, name: s.Sub | None, fqn: s.Sub) -> str:
    """Return the node's own name (the last segment), or ``*`` when it is not known."""
    text = graph.base(name)
    if text is None:
        full = graph.base(fqn)
        if full is None:
            return "*"
        text = full
    return text.rstrip("/").rpartition("/")[2]


def _varies(sub: s.Sub, switches: set[str]) -> bool:
    """Return whether a value can change with the switches (or with the path taken)."""
    return any(isinstance(part, Select) or (isinstance(part, Arg) and part.name in switches)
               for part in s.walk(sub))
