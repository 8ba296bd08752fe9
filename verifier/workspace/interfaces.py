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
    """The interfaces of a check's roots, found by folder and by file name."""

    def __init__(self, graphs: Iterable[LaunchGraph] = ()) -> None:
        self.of: dict[Path, Interface] = {
            graph.root: Interface(
                {a.name: a.origin.span for a in graph.arguments
                 if a.origin.span.file == graph.root},
                frozenset(graph.read_names() | graph.mentioned_names()),
            )
            for graph in graphs
        }
        self._by_folder: dict[Path, list[Path]] = {}
        self._by_name: dict[str, list[Path]] = {}
        for path in sorted(self.of):
            self._by_folder.setdefault(path.parent, []).append(path)
            self._by_name.setdefault(path.name, []).append(path)

    def mirrored(self, file: Path, name: str) -> Span | None:
        """Return where a file of ``file``'s family declares ``name`` and uses it, if any.

        The family: launch files in the same folder, or of the same file name elsewhere
        (one per package), whose declared arguments ``file`` mostly shares.
        """
        own = self.of.get(file)
        if own is None:
            return None
        family = dict.fromkeys([*self._by_folder.get(file.parent, []),
                                *self._by_name.get(file.name, [])])
        for other in sorted(family):
            interface = self.of[other]
            if other == file or name not in interface.declared or name not in interface.used:
                continue
            shared = len(own.declared.keys() & interface.declared.keys())
            if shared >= MIRROR_SHARED and shared >= MIRROR_SHARE * len(own.declared):
                return interface.declared[name]
        return None
