"""How much one root's evaluation may expand before it stops (issue 42).

A few kilobytes of launch files can describe an exponential launch: 24 files each
including the next twice make 2**24 include instances, nested loops multiply their
lengths. Every root is bounded by what it expands, counted as it is walked; past a bound
the walk stops, the graph keeps what it had (marked cut short: no rule claims that
anything is absent from it) and the root gets an LV003 info naming the bound. The bounds
are per root: no file can spend another's.

Each bound is far above what real launch trees reach (measured on the 41-repository
corpus and ``bench/fleet.py``) and low enough that a root stopped by it costs a fraction
of a second: every file of a fan-out is a root of its own too, and each pays.
"""

from __future__ import annotations

from dataclasses import dataclass

from launchverify.span import Span

# Include instances (each file walked through an include, per root). The largest real
# root, autoware.universe's reaction_analyzer, follows 270; autoware_launch's
# logging_simulator 195; bench/fleet.py at 1,000 robots 1,000 (one include per robot).
# A root stopped here costs about 0.2 s: the 24 files of a 7 KB fan-out, each of them a
# root, check in about 3 s.
MAX_INCLUDES = 2_000

# Nodes recorded per root. Real roots reach 380 (reaction_analyzer); the 1,000-robot
# fleet 18,003. Past this, nodes come from loops or containers more than from includes.
MAX_NODES = 40_000

# Actions visited per root (groups, arguments, nodes, includes: every action executed,
# loop iterations and handlers included). Real roots visit at most 3,300
# (reaction_analyzer); the 1,000-robot fleet 30,005. Bounds nested loops, whose lengths
# multiply (each up to 256) without any include.
MAX_ACTIONS = 150_000


class BoundReached(Exception):
    """The walk of a root went past one of its bounds; ``message`` names it."""

    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message
        self.where: Span | None = None  # the action being executed when it was reached


@dataclass
class ExpansionBudget:
    """What one root's walk has expanded so far, against its bounds."""

    max_includes: int = MAX_INCLUDES
    max_nodes: int = MAX_NODES
    max_actions: int = MAX_ACTIONS
    includes: int = 0
    actions: int = 0

    def action(self, nodes: int) -> None:
        """Count one more action visited (``nodes``: recorded so far); raise past a bound."""
        self.actions += 1
        if self.actions > self.max_actions:
            raise BoundReached(f"{self.max_actions:,} actions")
        if nodes > self.max_nodes:
            raise BoundReached(f"{self.max_nodes:,} nodes")

    def include(self) -> None:
        """Count one more file walked through an include; raise past the bound."""
        self.includes += 1
        if self.includes > self.max_includes:
            raise BoundReached(f"{self.max_includes:,} include instances")
