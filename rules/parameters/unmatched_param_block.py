"""LV402 unmatched-param-block."""

from __future__ import annotations

import dataclasses
import fnmatch
import functools
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import NamedTuple

from launchverify.graph import LaunchGraph, NodeRecord
from launchverify.models.node_names import BUILTIN_NAMES, InnerNode, inner_nodes
from launchverify.models.rewritten_yaml import under_root
from launchverify.models.ros_names import node_key_matches
from launchverify.parameters import file_readers
from launchverify.rule import Finding, GatheringRule, Related, RuleContext, Severity
from launchverify.span import Span
from launchverify.suggest import closest, sole_typo
from launchverify.topology.shipped import shipped_node_names
from launchverify.workspace.package_contents import name_literals, unnamed_node_names
from launchverify.workspace.packages import PackageIndex


@dataclass(frozen=True)
class Receiver:
    """A node that loads a parameter file: its name, or the names it may have.

    A node started without ``name=`` is called what its code calls it: ``names`` holds the
    names its package's code gives nodes (``None`` when the package is not in the
    workspace: any name).
    """

    node: NodeRecord
    fqn: str | None
    namespace: str = "/"
    names: frozenset[str] | None = None
    inner: frozenset[str] = frozenset()  # names the package's code may give inner nodes
    inner_nodes: tuple[InnerNode, ...] = ()  # what models/inner_nodes.py knows it creates

    @property
    def component(self) -> bool:
        """Return whether launch_ros filters the file for it (a loaded component)."""
        return self.node.composable

    def label(self) -> str:
        """Return how the node is named in messages."""
        if self.fqn is not None:
            return self.fqn
        return f"{self.namespace.rstrip('/')}/<unnamed {self.node.executable_label()}>"

    def matches(self, key: str) -> bool:
        """Return whether a block's node key can apply to this node."""
        last = key.rpartition("/")[2]
        if not self.component and (last in self.inner or self.inner_match(key, last)):
            return True  # a node the process creates inside gets the process's files
        if self.fqn is not None:
            if self.component:
                return key == "/**" or key.strip("/") == self.fqn.strip("/")
            return node_key_matches(key, self.fqn)
        wildcard = last in ("*", "**")
        if self.names is not None and not wildcard and last not in self.names:
            return False
        # any name the code may give it: the key's own last token stands for it
        name = "x" if wildcard else last
        return node_key_matches(key, self.namespace.rstrip("/") + "/" + name)


    def inner_match(self, key: str, last: str) -> bool:
        """Return whether a key names a node the process is known to create inside."""
        own = self.fqn.rpartition("/")[2] if self.fqn is not None else None
        return any(
            fnmatch.fnmatchcase(last, inner.pattern(own))
            and node_key_matches(key, _join(self.inner_namespace(inner), last))
            for inner in self.inner_nodes
        )

    def inner_namespace(self, inner: InnerNode) -> str:
        """Return the namespace an inner node runs in."""
        return _join(self.namespace, inner.namespace)

    def namespaces(self) -> set[str]:
        """Return the namespaces this node and the nodes it creates run in."""
        return {self.namespace.rstrip("/") or "/"} | {
            self.inner_namespace(inner) for inner in self.inner_nodes}

    def inner_names(self) -> dict[str, str]:
        """Return the inner nodes with a literal name: name -> fully qualified name."""
        return {inner.name: _join(self.inner_namespace(inner), inner.name)
                for inner in self.inner_nodes if not any(c in inner.name for c in "*{")}


@dataclass(frozen=True)
class _Loader:
    """What the verdict needs of a node that loads a file (kept between checks: small)."""

    fqn: str | None
    namespaces: frozenset[str]  # where it and the nodes it creates run
    inner_names: tuple[tuple[str, str], ...]  # its inner nodes with a literal name, and fqn
    span: Span  # where it is started

    @classmethod
    def of(cls, receiver: Receiver) -> _Loader:
        """Return what the verdict needs of a receiver."""
        return cls(receiver.fqn, frozenset(receiver.namespaces()),
                   tuple(receiver.inner_names().items()), receiver.node.origin.span)


def _join(*parts: str) -> str:
    """Join namespace parts and a name into one absolute name."""
    return "/" + "/".join(token for part in parts for token in part.split("/") if token)


class _Block(NamedTuple):
    """A block of a parameter file, as the verdict needs it."""

    key: str
    span: Span


@dataclass
class _FileUse:
    """What the graphs of a check say about one parameter file."""

    blocks: tuple[_Block, ...]  # the file's blocks, in order
    undecided: bool = False
    matched: set[int] = field(default_factory=set)
    receivers: dict[str, _Loader] = field(default_factory=dict)  # by label


# what one graph tells: the node names it starts, and the uses of each parameter file
_Gathered = tuple[set[str], dict[Path, _FileUse]]


class UnmatchedParamBlock(GatheringRule):
    """A parameter file block whose node key matches none of the nodes that load the file.

    ## What it does
    For every parameter file that nodes load, matches each block's node key against the
    fully qualified names of those nodes, as ROS 2 does: a leading `/` is implied, `/**`
    stands for any number of namespace tokens and `*` for one, and the whole name must
    match (`controller:` does not match `/robot1/controller`). Components loaded into a
    container only see `/**` and their exact name (launch_ros filters the file itself).
    Nodes that a process creates inside itself get its files too: nav2's costmaps
    (`local_costmap/local_costmap`), behaviour-tree client nodes, a ros2_control manager's
    controllers (one per `<name>.type` it lists), and names found in the package's own
    sources when they are in the workspace.

    A block that matches no node in any launch of the check is a warning when it is a
    likely slip: its name is close to a loading node that has no block of its own in the
    file (the message names it); an error when it misspells exactly one such node (one or
    two edits, not only digits apart: `amlc` for `amcl`), which is almost always a typo.
    One parameter file often serves a whole stack, so a
    block for a node that runs elsewhere is no finding: a node another launch of the check
    starts, a package's well-known node (nav2's servers, from the shipped models), or a
    helper node created inside a node whose block is in the file (older nav2's
    `amcl_rclcpp_node`, `local_costmap_client`). Any other block is stale, an info; so is
    a block in a namespace where none of the loading nodes runs (more likely for an inner
    node launchverify does not know than a slip). No rename is ever suggested onto a node
    that already has its block. Files that reach something launchverify cannot see into
    (an include outside the workspace, a node whose name is unknown) are not judged, nor
    files a node reads through nav2's `RewrittenYaml` with a `root_key` (every block moves
    under it).

    ## Why it matters
    ROS ignores the block without a word: the node starts with its default parameters,
    and nobody notices until the robot behaves oddly. The usual cause is a misspelt node
    name or a namespace the block does not account for.

    ## Example
    ```yaml
    amlc:                 # the node is called amcl
      ros__parameters:
        max_particles: 2000
    ```

    ## Fix
    Use the node's name (with its namespace, or `/**/amcl`), or a wildcard block `/**:`.
    """

    code = "LV402"
    slug = "unmatched-param-block"
    severity = Severity.WARNING
    message = "parameter block {key!r} matches none of the nodes that load {file}{hint}"

    def gather(self, graph: LaunchGraph, ctx: RuleContext) -> _Gathered:
        started = {fqn.rpartition("/")[2] for node in graph.nodes
                   if (fqn := graph.base(node.fqn)) is not None}
        uses: dict[Path, _FileUse] = {}
        for path, param_file in graph.param_files.items():
            use = uses[path] = _FileUse(tuple(_Block(b.key, b.span) for b in param_file.blocks))
            receivers = receivers_of(graph, path, ctx.packages)
            if receivers is None:
                use.undecided = True
                continue
            for receiver in receivers:
                if receiver.label() not in use.receivers:
                    use.receivers[receiver.label()] = _Loader.of(receiver)
                for index, block in enumerate(param_file.blocks):
                    if receiver.matches(block.key):
                        use.matched.add(index)
        return started, uses

    def conclude(self, gathered: list[object], ctx: RuleContext) -> Iterator[Finding]:
        started: set[str] = set()  # node names any launch starts
        uses: dict[Path, _FileUse] = {}
        for part in gathered:
            assert isinstance(part, tuple)
            starts: set[str] = part[0]
            graph_uses: dict[Path, _FileUse] = part[1]
            started |= starts
            for path, each in graph_uses.items():
                use = uses.setdefault(path, _FileUse(each.blocks))
                use.undecided |= each.undecided
                use.matched |= each.matched
                for label, receiver in each.receivers.items():
                    use.receivers.setdefault(label, receiver)
        for path, use in uses.items():
            if use.undecided or not use.receivers:
                continue
            names = {r.fqn.rpartition("/")[2]: r.fqn for r in use.receivers.values()
                     if r.fqn is not None}
            for receiver in use.receivers.values():
                names.update(receiver.inner_names)
            # nodes this file already has a block of their own for
            blocked = {block.key.rpartition("/")[2]
                       for index, block in enumerate(use.blocks)
                       if index in use.matched} - {"*", "**"}
            shown = sorted(use.receivers)
            listed = ", ".join(shown[:6]) + (", ..." if len(shown) > 6 else "")
            loaded_by = Related(use.receivers[shown[0]].span, f"loaded by {listed}")
            for index, block in enumerate(use.blocks):
                if index not in use.matched:
                    finding = self._unmatched(block, path, use, names, blocked, started,
                                              loaded_by)
                    if finding is not None:
                        yield finding

    def _unmatched(self, block: _Block, path: Path, use: _FileUse, names: dict[str, str],
                   blocked: set[str], started: set[str],
                   loaded_by: Related) -> Finding | None:
        """Report a block for no node: a warning for a likely slip, else an info or nothing.

        A slip is a name close to a loading node that has no block of its own here. A
        helper node created inside a node whose block is here, or a package's well-known
        node, is no finding: one file serves a whole stack. Any other block is an info.
        """
        name = block.key.rpartition("/")[2]
        if any(name.startswith(node + "_") for node in blocked):
            return None
        namespace = _foreign_namespace(block.key, use.receivers.values())
        hint = _closest(block.key, {n: fqn for n, fqn in names.items() if n not in blocked})
        if namespace is not None:  # more likely a node we do not model than a slip
            hint = f" (none of them runs in {namespace}: a node one of them creates inside?)"
        elif not hint and name in well_known_node_names():
            return None
        elif not hint and name in started:  # a shared file: the block is for another launch
            hint = f" ({name} is a node these launches do not start with it)"
        elif not hint:
            hint = " (no node of that name is known to run: a stale block?)"
        finding = self.finding(block.span, related=(loaded_by,), key=block.key,
                               file=path.name, hint=hint)
        if not hint.startswith(" (did you mean"):
            finding = dataclasses.replace(finding, severity=Severity.INFO)
        elif sole_typo(name, [n for n in names if n not in blocked]) is not None:
            finding = dataclasses.replace(finding, severity=Severity.ERROR)  # `amlc`
        return finding


@functools.cache
def well_known_node_names() -> frozenset[str]:
    """Return the names packages' code gives their nodes (shipped models, well-known)."""
    return shipped_node_names() | frozenset(BUILTIN_NAMES.values())


def receivers_of(graph: LaunchGraph, path: Path,
                 packages: PackageIndex | None) -> list[Receiver] | None:
    """Return the nodes that load a parameter file; ``None`` if that cannot be known.

    Unknown when a node loading it has a name or namespace launchverify does not know,
    or when the file's path is passed to something it cannot see into (an include it
    could not evaluate, a process command line, an opaque Python construct).
    """
    receivers: list[Receiver] = []
    spellings: set[str] = {str(path)}
    seen: set[int] = set()
    for node, param in file_readers(graph).get(path, []):
        if under_root(param.file):
            return None  # its keys move under a root key (RewrittenYaml): not this file's
        if param.file is not None and (text := graph.base(param.file)) is not None:
            spellings.add(text)
        if id(node) in seen:
            continue
        seen.add(id(node))
        receiver = _receiver(graph, node, packages)
        if receiver is None:
            return None
        receivers.append(receiver)
    if graph.opaque_files or graph.stopped_early:
        return None
    for include in graph.includes:
        if include.status != "loaded" and any(
            _mentions(graph.base(value), spellings) for _, value, _ in include.arguments
        ):
            return None
    for process in graph.processes:
        if any(text is not None and _mentions(text, spellings)
               for text in (graph.base(part) for part in process.cmd)):
            return None
    return receivers


def _receiver(graph: LaunchGraph, node: NodeRecord,
              packages: PackageIndex | None) -> Receiver | None:
    package_name = graph.base(node.package)
    package = packages.find(package_name) if packages and package_name else None
    inner = (name_literals(package) if package is not None else None) or frozenset()
    created = inner_nodes(package_name, graph.base(node.executable), _loaded_names(graph, node))
    fqn = graph.base(node.fqn)
    if fqn is not None:
        return Receiver(node, fqn, fqn.rpartition("/")[0] or "/", inner=inner,
                        inner_nodes=created)
    unnamed = unnamed_node_names(graph, node, packages)
    if unnamed is None:
        return None  # a name or namespace we cannot compute
    return Receiver(node, None, unnamed[0], unnamed[1], inner, created)


def _loaded_names(graph: LaunchGraph, node: NodeRecord) -> list[tuple[str, str]]:
    """Return (block's node name, parameter) of every file a node loads (controllers)."""
    files = [graph.param_files.get(param.source) for param in node.parameters
             if param.source is not None]
    return [(block.key.rpartition("/")[2], name) for loaded in files if loaded is not None
            for block in loaded.blocks for name in block.parameters]


def _foreign_namespace(key: str, receivers: Iterable[_Loader]) -> str | None:
    """Return a key's namespace when it is literal and no receiver runs in it."""
    prefix = key.rpartition("/")[0] or "/"
    if "*" in prefix or prefix == "/":
        return None
    known = {namespace for receiver in receivers for namespace in receiver.namespaces}
    if any(namespace == prefix or namespace.startswith(prefix + "/") for namespace in known):
        return None
    return prefix


def _mentions(text: str | None, spellings: set[str]) -> bool:
    return text is None or any(spelling in text for spelling in spellings)


def _closest(key: str, names: dict[str, str]) -> str:
    """Return " (did you mean '/robot1/listener'?)" for the node a block was likely for."""
    prefix, _, last = key.rpartition("/")
    found = last if last in names else closest(last, names)
    if found is None:
        return ""
    # a wildcard key keeps its wildcard: '/**/colision_monitor' -> '/**/collision_monitor'
    suggestion = f"{prefix}/{found}" if "*" in prefix else names[found]
    if suggestion == key:  # the wildcard cannot reach it (a component): name it in full
        suggestion = names[found]
    return f" (did you mean {suggestion!r}?)"
