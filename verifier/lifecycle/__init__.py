"""The lifecycle bring-up of a launch: its transition system and what a search finds.

``analyse(graph)`` builds the system (``system.py``; nav2 managers in ``managers.py``),
searches it (``explore.py``) and keeps the result on the graph, so that the lifecycle
rules and ``launchverify graph`` share one search.
"""

from __future__ import annotations

from dataclasses import dataclass

from launchverify.graph import LaunchGraph
from launchverify.lifecycle.explore import Exploration, Where, explore
from launchverify.lifecycle.system import System, build_system
from launchverify.models import distros

__all__ = ["Analysis", "Where", "analyse", "bringup"]


@dataclass
class Analysis:
    """A graph's lifecycle system and the search of it."""

    system: System
    exploration: Exploration


def analyse(graph: LaunchGraph) -> Analysis:
    """Return the lifecycle analysis of a graph (computed once per distribution checked).

    The distribution matters: before rolling, lifecycle events carry no transition label,
    so a handler filtering on one never fires (``labels.py``).
    """
    cache = graph.derived.setdefault("lifecycle", {})
    found = cache.get(distros.current())
    if isinstance(found, Analysis):
        return found
    system = build_system(graph)
    analysis = Analysis(system, explore(system) if not system.empty else Exploration())
    cache[distros.current()] = analysis
    return analysis


def bringup(graph: LaunchGraph) -> Analysis | None:
    """Return the lifecycle analysis of a graph, or ``None`` when it has no bring-up."""
    if not graph.nodes:
        return None
    analysis = analyse(graph)
    return None if analysis.system.empty else analysis
