"""The rules of a check, shared out between processes.

A rule judges one graph at a time, so the graphs of a check can be split between forked
processes: they were built before the fork, and a child reads them without copying. Each
child returns what its rules found in each of its graphs; the check then merges those
lists in the order a single process visits them, so the findings do not depend on how
many processes ran. A rule asking for every context runs whole in one process (``plan``
says why); rules that gather across graphs (those with a ``finish``) run in the
checking process, over every graph, as before.

Forking needs a POSIX system and no other thread in the process (the language server
checks from a thread): otherwise, and for checks too small to gain from it, everything
runs here.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING

from launchverify.forked import can_fork
from launchverify.graph import LaunchGraph
from launchverify.ir.symbolic import PathCondition
from launchverify.rule import Finding, Rule, RuleContext

if TYPE_CHECKING:
    from concurrent.futures import Future

# Below this much work (records over all graphs) forking costs more than it saves
# (measured: ros2_control_demos, 511, took 0.046 s alone and 0.081 s shared out).
MIN_WORK = 2000

# (rule index, graph index) -> the findings of that rule in that graph, in its order
PerGraph = dict[tuple[int, int], list[Finding]]
Isolate = Callable[[Rule, Callable[[], Iterable[Finding]], Path | None], Iterator[Finding]]
Dead = Callable[[LaunchGraph, PathCondition], bool]


@dataclass
class RuleRun:
    """What running the rules needs, shared with the children by forking."""

    graphs: list[LaunchGraph]
    rules: list[type[Rule]]
    ctx: RuleContext
    isolate: Isolate  # a rule's failure becomes a finding (engine._isolated)
    dead: Dead  # a finding's place can run under no arguments (engine.dead)
    instances: dict[int, Rule] = field(default_factory=dict)  # one per rule and process

    def instance(self, index: int) -> Rule:
        """Return this process's instance of a rule (its ``check`` and ``finish`` share it)."""
        if index not in self.instances:
            self.instances[index] = self.rules[index]()
        return self.instances[index]

    def order(self, rule: type[Rule], among: list[int]) -> list[int]:
        """Return the graphs a rule visits, in the order one process visits them.

        Small graphs first for rules asking for every context: a file evaluated as its
        own root settles most questions its includers would otherwise ask again.
        """
        if getattr(rule, "every_context", False):
            return sorted(among, key=lambda i: len(self.graphs[i].files))
        return among

    def run(self, rule_indices: list[int], graph_indices: list[int]) -> PerGraph:
        """Run some rules on some graphs, here."""
        out: PerGraph = {}
        for r in rule_indices:
            rule = self.instance(r)
            for g in self.order(self.rules[r], graph_indices):
                graph = self.graphs[g]
                out[(r, g)] = [
                    finding for finding in self.isolate(
                        rule, partial(rule.check, graph, self.ctx), graph.root)
                    if not (finding.path and self.dead(graph, finding.path))]
        return out


@dataclass(frozen=True)
class Share:
    """One process's part: rules to run on every graph, and rules to run on some graphs."""

    whole: tuple[int, ...] = ()  # rules asking every context: on every graph, here
    split: tuple[int, ...] = ()  # the other rules...
    graphs: tuple[int, ...] = ()  # ...on these graphs

    def run(self, run: RuleRun) -> PerGraph:
        """Compute this part's findings in the running process."""
        out = run.run(list(self.whole), list(range(len(run.graphs))))
        out.update(run.run(list(self.split), list(self.graphs)))
        return out


_SHARED: dict[str, RuleRun] = {}  # what a forked child works on (set before the fork)


def _child(share: Share) -> tuple[PerGraph, dict[int, int]]:
    """Run a share in a forked child; also say how many z3 queries it asked per graph."""
    run = _SHARED["run"]
    before = _queries(run.graphs)  # reasoners the parent made before the fork come along
    found = share.run(run)
    after = _queries(run.graphs)
    return found, {g: n - before.get(g, 0) for g, n in after.items() if n != before.get(g, 0)}


def _queries(graphs: list[LaunchGraph]) -> dict[int, int]:
    """Return the z3 queries each graph's reasoner in this process has asked."""
    return {g: reasoner.queries for g, graph in enumerate(graphs)
            if (reasoner := getattr(graph, "_reasoner", None)) is not None}


def rule_findings(run: RuleRun, jobs: int) -> PerGraph:
    """Return every rule's findings in every graph, computed by up to ``jobs`` processes."""
    everything = list(range(len(run.graphs)))
    if jobs < 2 or len(run.graphs) < 2 or not can_fork() or _work(run.graphs) < MIN_WORK:
        return run.run(list(range(len(run.rules))), everything)
    gathering = [r for r, rule in enumerate(run.rules) if rule.finish is not Rule.finish]
    shares = plan(run, jobs, exclude=gathering)
    import multiprocessing  # here: a small check never pays for importing them
    from concurrent.futures import ProcessPoolExecutor

    _SHARED["run"] = run
    out: PerGraph = {}
    try:
        with ProcessPoolExecutor(max_workers=max(1, len(shares) - 1),
                                 mp_context=multiprocessing.get_context("fork")) as pool:
            futures = [(share, pool.submit(_child, share)) for share in shares[1:]]
            out.update(run.run(gathering, everything))  # meanwhile, here
            out.update(shares[0].run(run))
            for share, future in futures:
                collected = _collected(future)
                if collected is None:
                    out.update(share.run(run))
                    continue
                found, queries = collected
                out.update(found)
                for g, count in queries.items():
                    run.graphs[g].queries_elsewhere += count
    finally:
        _SHARED.clear()
    return out


def _collected(future: Future[tuple[PerGraph, dict[int, int]]]
               ) -> tuple[PerGraph, dict[int, int]] | None:
    """Return a child's findings; ``None`` when it failed (its share is then run here)."""
    try:
        return future.result()
    except Exception:  # a child killed, or a finding that does not pickle
        return None


def plan(run: RuleRun, jobs: int, exclude: Iterable[int] = ()) -> list[Share]:
    """Split the rules' work into at most ``jobs`` shares of about equal size.

    A rule asking for every context stays whole: the graphs it has seen settle places
    for the others (``RuleContext.settled``), so split, it would ask more in total. The
    other rules are split by graph. The largest piece first, each to the share with the
    least work so far (deterministic: the same check gives the same shares).
    """
    skipped = set(exclude)
    whole = [r for r, rule in enumerate(run.rules)
             if r not in skipped and getattr(rule, "every_context", False)]
    split = [r for r in range(len(run.rules)) if r not in skipped and r not in whole]
    total = _work(run.graphs)
    pieces: list[tuple[int, str, int]] = [(total, "rule", r) for r in whole]
    pieces += [(len(split) * _work([g]), "graph", i) for i, g in enumerate(run.graphs)]
    loads = [0] * jobs
    parts: list[tuple[list[int], list[int]]] = [([], []) for _ in range(jobs)]
    for cost, kind, index in sorted(pieces, key=lambda p: (-p[0], p[1], p[2])):
        lightest = loads.index(min(loads))
        parts[lightest][0 if kind == "rule" else 1].append(index)
        loads[lightest] += cost
    return [Share(tuple(sorted(rules)), tuple(split) if graphs else (), tuple(sorted(graphs)))
            for rules, graphs in parts if rules or graphs]


def _work(graphs: list[LaunchGraph]) -> int:
    """Return a rough measure of what the rules will do in these graphs."""
    return sum(len(g.nodes) + len(g.conditions) + len(g.includes) + len(g.reads) + 1
               for g in graphs)
