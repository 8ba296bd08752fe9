"""What the rules say about each graph, and how the graphs' verdicts become the findings.

A check evaluates many roots, and one file may be reached by several of them. The rules
judge each graph on its own (``Verdicts``); the merge then keeps a finding of a rule
marked ``every_context`` only when every graph reaching its file made it, puts polling
rules' answers to their poll and gathering rules' contributions to their verdict. The
merge needs only the verdicts, not the graphs: an incremental check keeps the verdicts
of the roots an edit did not reach and merges them with the new ones.
"""

from __future__ import annotations

from collections import defaultdict
from collections.abc import Callable, Hashable, Iterable, Iterator
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING

from launchverify.rule import Finding, Poll, Rule, RuleContext

if TYPE_CHECKING:
    from launchverify.parallel.fanout import PerGraph, RuleRun

Isolate = Callable[[Rule, Callable[[], Iterable[Finding]], Path | None], Iterator[Finding]]


@dataclass
class Verdicts:
    """What every rule said about one root's graph, before the graphs are put together."""

    root: Path
    files: frozenset[Path]  # the files the graph reached: a unanimous finding needs them all
    findings: dict[str, list[Finding]] = field(default_factory=dict)  # by rule code
    answers: dict[str, list[tuple[Hashable, Finding | None]]] = field(default_factory=dict)
    gathered: dict[str, object] = field(default_factory=dict)
    # rules asking every context: the places this graph settled, and those it relied on
    settled: dict[str, tuple[frozenset[object], frozenset[object]]] = field(
        default_factory=dict)
    # what its rules asked of other roots' interfaces (``interfaces.Consulted``)
    consulted: frozenset[tuple[str, ...]] = frozenset()


def verdicts_of(run: RuleRun, found: PerGraph) -> list[Verdicts]:
    """Return each graph's verdicts from a run of the rules (``fanout.rule_findings``)."""
    out = [Verdicts(graph.root, frozenset(graph.files)) for graph in run.graphs]
    codes = [rule.code for rule in run.rules]
    for (r, g), findings in found.items():
        out[g].findings[codes[r]] = findings
    for (r, g), answers in run.answers.items():
        out[g].answers[codes[r]] = answers
    for (r, g), gathered in run.gathered.items():
        out[g].gathered[codes[r]] = gathered
    for (r, g), (settled, relied) in run.settled.items():
        out[g].settled[codes[r]] = (frozenset(settled), frozenset(relied))
    for (_, g), consulted in run.consulted.items():
        out[g].consulted |= consulted
    return out


def order(rule: type[Rule], among: list[int], size: Callable[[int], int]) -> list[int]:
    """Return graphs in the order a rule visits them (``size``: a graph's file count).

    Small graphs first for rules asking for every context: a file evaluated as its own
    root settles most questions its includers would otherwise ask again. The merge
    visits verdicts in the order the rules visited their graphs.
    """
    if getattr(rule, "every_context", False):
        return sorted(among, key=size)
    return among


def merge(verdicts: list[Verdicts], rules: list[type[Rule]], ctx: RuleContext,
          instance: Callable[[int], Rule], isolate: Isolate,
          contexts: frozenset[Path] = frozenset(),
          own: Callable[[Finding], bool] = lambda finding: True) -> list[Finding]:
    """Return the check's findings from every graph's verdicts, in the check's order.

    ``instance(r)``: the rule object whose ``finish`` concludes (for a rule with a
    ``finish`` of its own, the one that judged every graph). ``contexts``: roots
    evaluated as the checked files' includers (``findings/scope.py``): they agree or
    deny everywhere, but what they alone find counts only where ``own`` says the check
    speaks (the paths' files).
    """
    from launchverify.parallel.fanout import gathers, polled

    merged: dict[tuple[object, ...], Finding] = {}
    votes: dict[tuple[object, ...], set[int]] = defaultdict(set)  # graphs that agree
    reach: dict[Path, int] = defaultdict(int)
    for verdict in verdicts:
        for path in verdict.files:
            reach[path] += 1
    context = {g for g, verdict in enumerate(verdicts) if verdict.root in contexts}
    unanimous = {rule.code for rule in rules if getattr(rule, "every_context", False)}
    first = verdicts[0].root if verdicts else None
    for r, rule_class in enumerate(rules):
        code = rule_class.code
        visits = order(rule_class, list(range(len(verdicts))),
                       lambda i: len(verdicts[i].files))
        for g in visits:
            for finding in verdicts[g].findings.get(code, ()):
                key = finding.key()
                votes[key].add(g)
                if g in context and not own(finding):
                    continue  # an includer's say elsewhere: it votes, it does not claim
                known = merged.get(key)
                if known is None or len(finding.chain) < len(known.chain):
                    merged[key] = finding
        rule = instance(r)
        if polled(rule_class):  # the answers its checks gathered, wherever they ran
            poll = Poll(ctx, code)
            asked = {question for g in visits if g not in context
                     for question, _ in verdicts[g].answers.get(code, ())}
            for g in visits:
                for question, answer in verdicts[g].answers.get(code, ()):
                    if (g in context and question not in asked and answer is not None
                            and not own(answer)):
                        continue  # a question only an includer asks, not the check's
                    poll.answer(question, answer)
        elif gathers(rule_class):
            ctx.memo_for(code)["gathered"] = [verdicts[g].gathered[code] for g in visits
                                              if code in verdicts[g].gathered]
        for finding in isolate(rule, partial(rule.finish, ctx), first):
            merged.setdefault(finding.key(), finding)
    kept = [
        f for key, f in merged.items()
        if f.code not in unanimous or len(votes[key]) >= reach[f.span.file]
    ]
    return sorted(kept, key=Finding.sort_key)
