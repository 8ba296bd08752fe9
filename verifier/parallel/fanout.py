"""The rules of a check, shared out between processes.

A rule judges one graph at a time, so the graphs of a check can be split between forked
processes: they were built before the fork, and a child reads them without copying. The
work is cut into pieces (``pieces``), which every process takes one after another until
none is left; each child returns what its rules found in each graph, and the check merges
those lists in the order a single process visits them, so the findings do not depend on
how many processes ran or which took what. A rule asking for every context is one piece
(``pieces`` says why); rules that gather across graphs (those with a ``finish``) run in
the checking process, over every graph, while the children start on the rest. Rules that
gather by poll (``PollingRule``) are shared out like the others: each graph's answers
come back with its findings, and the checking process puts them to the poll in the
order one process would (their views of a graph, the wiring or the lifecycle bring-up,
were built twice: once for them here, once in the child that had the graph's other rules).

Forking needs a POSIX system and no other thread in the process (the language server
checks from a thread): otherwise, and for checks too small to gain from it, everything
runs here.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable, Iterable, Iterator
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, TypeGuard, TypeVar

from launchverify.findings.verdicts import order
from launchverify.graph import LaunchGraph
from launchverify.ir.symbolic import PathCondition
from launchverify.parallel.forked import can_fork
from launchverify.rule import Finding, GatheringRule, PollingRule, Rule, RuleContext
from launchverify.smt import budget_notes, share_solver_time
from launchverify.workspace import reading

if TYPE_CHECKING:
    from concurrent.futures import Future

# Below this much work (records over all graphs) forking costs more than it saves
# (measured: ros2_control_demos, 511, took 0.046 s alone and 0.081 s shared out).
MIN_WORK = 2000

# (rule index, graph index) -> the findings of that rule in that graph, in its order
PerGraph = dict[tuple[int, int], list[Finding]]
# (rule index, graph index) -> a polling rule's answers in that graph, in its order
Answers = dict[tuple[int, int], list[tuple[Hashable, Finding | None]]]
# (rule index, graph index) -> what a gathering rule took from that graph
Gathered = dict[tuple[int, int], object]
# (rule index, graph index) -> the places that graph settled, and those it relied on
SettledLog = dict[tuple[int, int], tuple[set[object], set[object]]]
# (rule index, graph index) -> what it asked of other roots' interfaces (``Consulted``)
ConsultedLog = dict[tuple[int, int], set[tuple[str, ...]]]
Isolate = Callable[[Rule, Callable[[], Iterable[Finding]], Path | None], Iterator[Finding]]
Dead = Callable[[LaunchGraph, PathCondition], bool]
T = TypeVar("T")


@dataclass
class RuleRun:
    """What running the rules needs, shared with the children by forking."""

    graphs: list[LaunchGraph]
    rules: list[type[Rule]]
    ctx: RuleContext
    isolate: Isolate  # a rule's failure becomes a finding (engine._isolated)
    dead: Dead  # a finding's place can run under no arguments (engine.dead)
    instances: dict[int, Rule] = field(default_factory=dict)  # one per rule and process
    answers: Answers = field(default_factory=dict)  # polling rules', gathered in this process
    gathered: Gathered = field(default_factory=dict)  # gathering rules', in this process
    settled: SettledLog = field(default_factory=dict)  # rules asking every context
    consulted: ConsultedLog = field(default_factory=dict)

    def instance(self, index: int) -> Rule:
        """Return this process's instance of a rule (its ``check`` and ``finish`` share it)."""
        if index not in self.instances:
            self.instances[index] = self.rules[index]()
        return self.instances[index]

    def order(self, rule: type[Rule], among: list[int]) -> list[int]:
        """Return the graphs a rule visits, in the order one process visits them."""
        return order(rule, among, lambda i: len(self.graphs[i].files))

    def run(self, rule_indices: list[int], graph_indices: list[int]) -> PerGraph:
        """Run some rules on some graphs, here."""
        out: PerGraph = {}
        for r in rule_indices:
            rule = self.instance(r)
            places = (self.ctx.settled_for(rule.code)
                      if getattr(rule, "every_context", False) else None)
            for g in self.order(self.rules[r], graph_indices):
                graph = self.graphs[g]
                check = partial(rule.check, graph, self.ctx)
                if _polls(rule):
                    check = partial(_answering, rule, graph, self.ctx,
                                    self.answers.setdefault((r, g), []))
                elif _gathers(rule):
                    check = partial(_gathering, rule, graph, self.ctx, self.gathered, (r, g))
                if places is not None:
                    places.log = self.settled[(r, g)] = (set(), set())
                self.ctx.interfaces.log = self.consulted[(r, g)] = set()
                out[(r, g)] = [
                    finding for finding in self.isolate(rule, check, graph.root)
                    if not (finding.path and self.dead(graph, finding.path))]
                out[(r, g)] += budget_notes(graph)  # once its solver time ran out
                self.ctx.interfaces.log = None
                if places is not None:
                    places.log = None
        return out

def polled(rule: type[Rule]) -> bool:
    """Return whether a rule gathers by ``PollingRule``'s own poll (its check not changed)."""
    return issubclass(rule, PollingRule) and rule.check is PollingRule.check


def gathers(rule: type[Rule]) -> bool:
    """Return whether a rule gathers by ``GatheringRule``'s own means (check not changed)."""
    return issubclass(rule, GatheringRule) and rule.check is GatheringRule.check


def graph_wise(rule: type[Rule]) -> bool:
    """Return whether a rule's findings come from what it says of each graph on its own.

    What it says of one graph may then be computed anywhere (another process, an earlier
    check) and put together with the others'. A ``finish`` of its own needs every graph
    in the process that ran its ``check``.
    """
    return rule.finish is Rule.finish or polled(rule) or gathers(rule)


def _polls(rule: Rule) -> TypeGuard[PollingRule]:
    return polled(type(rule))


def _gathers(rule: Rule) -> TypeGuard[GatheringRule]:
    return gathers(type(rule))


def _gathering(rule: GatheringRule, graph: LaunchGraph, ctx: RuleContext, into: Gathered,
               key: tuple[int, int]) -> Iterator[Finding]:
    """``GatheringRule.check`` keeping what it gathers for the merge (a child's go back)."""
    into[key] = rule.gather(graph, ctx)
    yield from ()


def _answering(rule: PollingRule, graph: LaunchGraph, ctx: RuleContext,
               answers: list[tuple[Hashable, Finding | None]]) -> Iterator[Finding]:
    """``PollingRule.check`` keeping the answers for ``RuleRun.poll`` (a child's go back)."""
    for answer in rule.answers(graph, ctx):  # (one by one: those before a failure count)
        answers.append(answer)
    yield from rule.direct(graph, ctx)


@dataclass(frozen=True)
class Piece:
    """A piece of the work: rules to run on every graph, and rules to run on some graphs."""

    whole: tuple[int, ...] = ()  # rules asking every context: on every graph, here
    split: tuple[int, ...] = ()  # the other rules...
    graphs: tuple[int, ...] = ()  # ...on these graphs

    def run(self, run: RuleRun) -> PerGraph:
        """Compute this part's findings in the running process."""
        out = run.run(list(self.whole), list(range(len(run.graphs))))
        out.update(run.run(list(self.split), list(self.graphs)))
        return out

    def done(self, found: PerGraph, graphs: list[int]) -> bool:
        """Return whether ``found`` holds this part's findings (``graphs``: every graph)."""
        return (all((r, g) in found for r in self.whole for g in graphs)
                and all((r, g) in found for r in self.split for g in self.graphs))


_SHARED: dict[str, object] = {}  # what a forked child works on (set before the fork)
LOCK_SECONDS = 5.0  # a process killed holding the counter's lock must not stop the others


class NextPiece:
    """The next piece to take, shared by the processes of one check (forked with them).

    Each process takes pieces until none is left, so none waits while another works:
    the cost of a rule varies from tree to tree (navigation2's lifecycle rules, which only
    the checking process can run, took as long as half of all the others).
    """

    def __init__(self, pieces: int) -> None:
        import multiprocessing

        self.pieces = pieces
        self._next = multiprocessing.get_context("fork").Value("i", 0)

    def take(self) -> int | None:
        """Return the index of a piece nobody has taken, or ``None`` when none is left."""
        lock = self._next.get_lock()
        if not lock.acquire(timeout=LOCK_SECONDS):
            return None  # what is left is run by the checking process, at the end
        try:
            index = self._next.value
            self._next.value = index + 1
        finally:
            lock.release()
        return index if index < self.pieces else None


def _drain(run: RuleRun, pieces: list[Piece], counter: NextPiece) -> PerGraph:
    """Run pieces, here, as long as some are left."""
    out: PerGraph = {}
    while (index := counter.take()) is not None:
        out.update(pieces[index].run(run))
    return out


Collected = tuple[PerGraph, Answers, Gathered, SettledLog, ConsultedLog, dict[int, int],
                  set[str]]


def _child() -> Collected:
    """Run pieces in a forked child; return what ``rule_findings`` merges.

    Their findings, the polling and gathering rules' answers, the places settled, and how
    many z3 queries it asked per graph.
    """
    run = _SHARED["run"]
    pieces = _SHARED["pieces"]
    counter = _SHARED["counter"]
    assert isinstance(run, RuleRun) and isinstance(pieces, list)
    assert isinstance(counter, NextPiece)
    before = _queries(run.graphs)  # reasoners the parent made before the fork come along
    reads: set[str] = set()  # what the rules read here, for the parent's record
    with reading.recording(reads if reading.recording_on() else None):
        found = _drain(run, pieces, counter)
    after = _queries(run.graphs)
    queries = {g: n - before.get(g, 0) for g, n in after.items() if n != before.get(g, 0)}
    return (found, _taken(run.answers, found), _taken(run.gathered, found),
            _taken(run.settled, found), _taken(run.consulted, found), queries, reads)


def _taken(log: dict[tuple[int, int], T], found: PerGraph) -> dict[tuple[int, int], T]:
    """Return what a log holds of the pieces this process took (its findings' keys)."""
    return {key: log[key] for key in found if key in log}


def _queries(graphs: list[LaunchGraph]) -> dict[int, int]:
    """Return the z3 queries each graph's reasoner in this process has asked."""
    return {g: reasoner.queries for g, graph in enumerate(graphs)
            if (reasoner := getattr(graph, "_reasoner", None)) is not None}


def rule_findings(run: RuleRun, jobs: int) -> PerGraph:
    """Return every rule's findings in every graph, computed by up to ``jobs`` processes.

    Which process computes which piece varies from run to run; the findings do not (a
    piece's findings depend on the piece alone). z3's query count may: a reasoner warmed
    by one piece saves the next piece of its graph a question only in the same process.
    """
    everything = list(range(len(run.graphs)))
    if jobs < 2 or len(run.graphs) < 2 or not can_fork() or _work(run.graphs) < MIN_WORK:
        return run.run(list(range(len(run.rules))), everything)
    shared = pieces(run, exclude=gathering(run.rules))
    import multiprocessing  # here: a small check never pays for importing them
    from concurrent.futures import ProcessPoolExecutor

    try:
        counter = NextPiece(len(shared))
        pool = ProcessPoolExecutor(max_workers=jobs - 1,
                                   mp_context=multiprocessing.get_context("fork"))
    except OSError:  # no semaphores here (a container without /dev/shm): one process
        return run.run(list(range(len(run.rules))), everything)
    share_solver_time(run.graphs)  # a root's solver budget is one, whoever asks
    _SHARED.update(run=run, pieces=shared, counter=counter)
    out: PerGraph = {}
    try:
        with pool:
            futures = [pool.submit(_child) for _ in range(jobs - 1)]
            out.update(run.run(gathering(run.rules), everything))  # here: ``finish`` needs them
            out.update(_drain(run, shared, counter))
            for future in futures:
                collected = _collected(future)
                if collected is None:
                    continue
                found, answers, gathered, settled, consulted, queries, reads = collected
                reading.note_reads(reads)
                out.update(found)
                run.answers.update(answers)
                run.gathered.update(gathered)
                run.settled.update(settled)
                run.consulted.update(consulted)
                for g, count in queries.items():
                    run.graphs[g].queries_elsewhere += count
    finally:
        _SHARED.clear()
    for piece in shared:  # taken by a child that failed: done here
        if not piece.done(out, everything):
            out.update(piece.run(run))
    return out


def _collected(future: Future[Collected]) -> Collected | None:
    """Return a child's findings; ``None`` when it failed (its pieces are then run here)."""
    try:
        return future.result()
    except Exception:  # a child killed, or a finding that does not pickle
        return None


def gathering(rules: list[type[Rule]]) -> list[int]:
    """Return the rules that must see every graph in one process (a ``finish`` of their own)."""
    return [r for r, rule in enumerate(rules) if not graph_wise(rule)]


def pieces(run: RuleRun, exclude: Iterable[int] = ()) -> list[Piece]:
    """Split the rules' work into pieces, the largest first (deterministic).

    A rule asking for every context is one piece: the graphs it has seen settle places
    for the others (``RuleContext.settled``), so split, it would ask more in total. The
    other rules make one piece per graph (a graph's reasoner then answers them all).
    """
    skipped = set(exclude)
    whole = [r for r, rule in enumerate(run.rules)
             if r not in skipped and getattr(rule, "every_context", False)]
    split = tuple(r for r in range(len(run.rules)) if r not in skipped and r not in whole)
    total = _work(run.graphs)
    sized = [(total, Piece(whole=(r,))) for r in whole]
    if split:
        sized += [(len(split) * _work([graph]), Piece(split=split, graphs=(g,)))
                  for g, graph in enumerate(run.graphs)]
    return [piece for _, piece in sorted(sized, key=lambda item: -item[0])]


def _work(graphs: list[LaunchGraph]) -> int:
    """Return a rough measure of what the rules will do in these graphs."""
    return sum(len(g.nodes) + len(g.conditions) + len(g.includes) + len(g.reads) + 1
               for g in graphs)
