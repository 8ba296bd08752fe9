"""The arguments each checked launch file declares and reads, and the files it mirrors.

Launch files come in families that share one interface: a stand-in beside the file it
replaces (``dummy_scenario_selector_parking.launch.xml`` beside
``scenario_selector.launch.xml``), or one implementation per package of an interface that
an includer picks by name (``$(find-pkg-share $(var sensor_model)_launch)/launch/
sensing.launch.xml``). Such a file declares its family's arguments so that either can be
launched or included the same way, whether or not it uses each of them.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from launchverify.graph import LaunchGraph
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

    def __init__(self, graphs: Iterable[LaunchGraph] = ()) -> None:
        self._graphs = {graph.root: graph for graph in graphs}
        self._of: dict[Path, Interface] = {}
        self._by_folder: dict[Path, list[Path]] = {}
        self._by_name: dict[str, list[Path]] = {}
        for path in sorted(self._graphs):
            self._by_folder.setdefault(path.parent, []).append(path)
            self._by_name.setdefault(path.name, []).append(path)

    def of(self, root: Path) -> Interface | None:
        """Return the interface of a checked root (``None`` for another file)."""
        known = self._of.get(root)
        if known is None and (graph := self._graphs.get(root)) is not None:
            known = self._of[root] = Interface(
                {a.name: a.origin.span for a in graph.arguments
                 if a.origin.span.file == graph.root},
                frozenset(graph.read_names() | graph.mentioned_names()),
            )
        return known

    def mirrored(self, file: Path, name: str) -> Span | None:
        """Return where a file of ``file``'s family declares ``name`` and uses it, if any.

        The family: launch files in the same folder, or of the same file name elsewhere
        (one per package), whose declared arguments ``file`` mostly shares.
        """
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
