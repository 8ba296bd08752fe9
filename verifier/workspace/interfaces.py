"""The arguments each checked launch file declares and reads, and the files it mirrors.

Launch files come in families that share one interface: a stand-in beside the file it
replaces (``dummy_scenario_selector_parking.launch.xml`` beside
``scenario_selector.launch.xml``), or one implementation per package of an interface that
an includer picks by name (``$(find-pkg-share $(var sensor_model)_launch)/launch/
sensing.launch.xml``). Such a file declares its family's arguments so that either can be
launched or included the same way, whether or not it uses each of them.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path

from launchverify.graph import LaunchGraph
from launchverify.ir import subst as s
from launchverify.span import Span

# A file mirrors another when they share at least this many declared arguments, and these
# are at least this share of what the file declares (a family, not a common name or two
# like use_sim_time).
MIRROR_SHARED = 3
MIRROR_SHARE = 0.75


@dataclass(frozen=True, slots=True)
class Interface:
    """What one launch file, evaluated as a root, declares itself and reads anywhere."""

    declared: dict[str, Span]  # each argument's declaration
    used: frozenset[str]


class Interfaces:
    """The interfaces of a check's roots, found by folder and by file name.

    Each is worked out when a rule first asks about its family (a large tree's roots
    read tens of thousands of configurations; few roots are ever asked about).
    """

    def __init__(self, graphs: Iterable[LaunchGraph] = (),
                 kept: Mapping[Path, tuple[Interface, Picked]] | None = None,
                 order: Iterable[Path] = ()) -> None:
        """Know the roots of a check by their graphs, or by what was kept of them.

        ``kept``: roots without a graph here, by the interface and picks they had;
        ``order``: the check's roots in its order (by default the graphs', then ``kept``).
        """
        self._graphs = {graph.root: graph for graph in graphs}
        self._kept = dict(kept or {})
        self._order = [root for root in order if root in self._graphs or root in self._kept] \
            or [*self._graphs, *self._kept]
        self._of: dict[Path, Interface] = {root: i for root, (i, _) in self._kept.items()}
        self._by_folder: dict[Path, list[Path]] = {}
        self._by_name: dict[str, list[Path]] = {}
        self._picked: dict[tuple[str, str], Span] | None = None
        # what a rule asked while judging one graph (set around it: ``Consulted``)
        self.log: set[Consulted] | None = None
        for path in sorted([*self._graphs, *self._kept]):
            self._by_folder.setdefault(path.parent, []).append(path)
            self._by_name.setdefault(path.name, []).append(path)

    def of(self, root: Path) -> Interface | None:
        """Return the interface of a checked root (``None`` for another file)."""
        known = self._of.get(root)
        if known is None and (graph := self._graphs.get(root)) is not None:
            known = self._of[root] = interface_of(graph)
        return known

    def mirrored(self, file: Path, name: str) -> Span | None:
        """Return where a file of ``file``'s family declares ``name`` and uses it, if any.

        The family: launch files in the same folder, or of the same file name elsewhere
        (one per package), whose declared arguments ``file`` mostly shares.
        """
        if self.log is not None:
            self.log.add(("family", str(file.parent), file.name))
        own = self.of(file)
        if own is None:
            return None
        family = dict.fromkeys([*self._by_folder.get(file.parent, []),
                                *self._by_name.get(file.name, [])])
        for other in sorted(family):
            interface = self.of(other)
            if interface is None or other == file or name not in interface.declared \
                    or name not in interface.used:
                continue
            shared = len(own.declared.keys() & interface.declared.keys())
            if shared >= MIRROR_SHARED and shared >= MIRROR_SHARE * len(own.declared):
                return interface.declared[name]
        return None

    def picked_by_name(self, file: Path, name: str) -> Span | None:
        """Return where an includer picking ``file`` by an argument's value passes ``name``.

        Such an includer (``$(var sensor_model)_launch/.../sensing.launch.xml``) picks
        one file of that name among packages, and every one of them declares what the
        includer passes, whether or not it uses it.
        """
        if self.log is not None:
            self.log.add(("picked", file.name))
        if self._picked is None:
            self._picked = {}
            for root in self._order:
                graph = self._graphs.get(root)
                for pick, span in (picks_of(graph) if graph is not None
                                   else self._kept[root][1]):
                    self._picked.setdefault(pick, span)
        return self._picked.get((file.name, name))


# An includer's picks: (the file name it picks by an argument, an argument it passes)
Picked = tuple[tuple[tuple[str, str], Span], ...]
# What a rule consulted: ("family", folder, file name) of ``mirrored``, ("picked", file
# name) of ``picked_by_name``: a root of that family, or picking that name, concerns it.
Consulted = tuple[str, ...]


def concerns(consulted: Consulted, root: Path, picked: set[str]) -> bool:
    """Return whether a change of ``root`` may change what a rule consulted.

    ``picked``: the file names whose picks by ``root`` changed.
    """
    if consulted[0] == "family":
        return str(root.parent) == consulted[1] or root.name == consulted[2]
    return consulted[1] in picked


def interface_of(graph: LaunchGraph) -> Interface:
    """Return what a root declares itself and reads anywhere (worked out once a graph)."""
    derived = graph.derived.setdefault("interface", {})
    known = derived.get(None)
    if not isinstance(known, Interface):
        known = derived[None] = Interface(
            {a.name: a.origin.span for a in graph.arguments if a.origin.span.file == graph.root},
            frozenset(graph.read_names() | graph.mentioned_names()))
    return known


def picks_of(graph: LaunchGraph) -> Picked:
    """Return what a graph's includes that pick a file by an argument's value pass it."""
    out = []
    for include in graph.includes:
        picked = _picked_name(include.action.path)
        if picked is None:
            continue
        for argument in include.action.arguments:
            if isinstance(argument.name, s.Text):
                out.append(((picked, argument.name.text), argument.span))
    return tuple(out)


def _picked_name(location: s.Sub) -> str | None:
    """Return the file name an include's location ends with, if an argument picks its folder.

    (``$(var pkg)/launch/x.launch.xml``, or a ``PathJoinSubstitution`` of the same.)
    """
    parts = location.parts if isinstance(location, (s.Concat, s.PathJoin)) else (location,)
    tail = parts[-1]
    if not isinstance(tail, s.Text):
        return None
    name = tail.text.rsplit("/", 1)[-1]
    joined = isinstance(location, s.PathJoin) or "/" in tail.text
    if not joined or not name or not any(
            isinstance(sub, s.LaunchConfig) for part in parts[:-1] for sub in s.walk(part)):
        return None
    return name
