"""The questions rules ask about a launch graph.

Rules never build z3 terms: they ask whether path conditions can hold together (and under
which arguments), whether a condition can never or must always hold (and why), whether a
condition can take a value launch rejects, and whether two names can be equal. Each
question is first tried with the concrete evaluator over the arguments' values
(``search``); z3 (``solver``) is imported and asked only when that settles nothing.
Answers are cached per question. All the questions about one root share a budget of
solver time (``budget.py``): a question z3 gives up on, or one asked once the budget is
spent, is answered "cannot tell", which each question turns into the answer that claims
nothing (no witness, no contradiction, not always).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Iterable
from typing import TYPE_CHECKING, TypeVar, cast

from launchverify.graph import LaunchGraph
from launchverify.ir.subst import Opaque as s_Opaque
from launchverify.ir.subst import Sub, walk
from launchverify.ir.symbolic import (
    Arg,
    EnvInput,
    Guard,
    Opaque,
    PathCondition,
    StrEquals,
    Truthy,
    Unknown,
)
from launchverify.models.booleans import CONDITION_FALSE, CONDITION_TRUE
from launchverify.smt.budget import BudgetSpent, CannotTell, SolverBudget
from launchverify.smt.domains import ArgumentDomain, Mode, argument_domains
from launchverify.smt.search import (
    FREE_KEY,
    OPAQUE_KEY,
    UNSET_KEY,
    Search,
    SearchReducer,
    all_hold,
)
from launchverify.smt.types import Contradiction, Witness

if TYPE_CHECKING:
    from launchverify.smt.solver import Z3Backend


Answer = TypeVar("Answer")  # what one kind of question is answered with


class Reasoner:
    """Answers questions about one graph (one root launch file and its arguments)."""

    def __init__(self, graph: LaunchGraph, budget: SolverBudget | None = None) -> None:
        self.graph = graph
        self.domains: dict[str, ArgumentDomain] = argument_domains(graph)
        self.budget = budget or SolverBudget()  # the root's solver time, for all questions
        self.search = Search(self.domains, graph.inputs(), out_of_time=self.budget.spent)
        self._backend: Z3Backend | None = None
        self._inputs = tuple(sorted(graph.inputs().items()))
        self._domain_keys: dict[str, tuple[object, ...]] = {}
        self._answers: dict[tuple[object, ...], object] = {}  # by question (a fast path)
        # contradictions name the guards' places, which differ between roots
        self._never: dict[tuple[PathCondition, Guard], Contradiction | None] = {}

    @property
    def z3(self) -> Z3Backend:
        """Return the z3 backend (importing z3 the first time)."""
        if self._backend is None:
            from launchverify.smt.solver import Z3Backend

            self._backend = Z3Backend(self.domains, self.graph.inputs(), self.budget)
        return self._backend

    @property
    def queries(self) -> int:
        """Return how many times z3 was asked."""
        return 0 if self._backend is None else self._backend.queries

    # ------------------------------------------------------------------ questions

    def together(self, *paths: PathCondition) -> Witness | None:
        """Return an assignment of the switches under which every path holds, if any.

        Asked as one path of the guards of all, each once: a handler and its target in
        one scope share their guards, and the question is then the one already answered.
        ``None`` also when it cannot tell: a finding needs a witness.
        """
        found = self._together(paths)
        return None if found is CANNOT_TELL else cast("Witness | None", found)

    def apart(self, *paths: PathCondition) -> bool:
        """Return whether the paths surely never hold together (``False``: they may)."""
        return self._together(paths) is None

    def _together(self, paths: tuple[PathCondition, ...]) -> Witness | _CannotTell | None:
        merged = tuple(dict.fromkeys(g for p in paths for g in p))

        def answer() -> Witness | None:
            guards = list(merged)
            tried = self.search.run(Mode.SWITCHES, guards, lambda r: all_hold(r, guards))
            if tried.found is not None or tried.exhaustive:
                return self._tried(tried.found)
            return self.z3.together((merged,))

        return self._answer("together", merged, merged, answer)

    def reachable(self, path: PathCondition) -> Witness | None:
        """Return argument values, any the user may give, under which a path holds.

        For the claim that launch fails where a path holds (launch evaluates an action's
        fields only under its condition): the switches first (``together``), then every
        value (``Mode.ANY``), so that a free-text argument takes what the condition
        compares it to (``sensor:=oakd``), as whoever picks that sensor gives it; only
        arguments of the root's interface (``domains``). ``None`` when none is found.
        """
        found = self.together(path)
        if found is not None or not path:
            return found
        guards = list(dict.fromkeys(path))

        def answer() -> Witness | None:
            tried = self.search.run(Mode.ANY, guards, lambda r: all_hold(r, guards))
            found = self._tried(tried.found)
            if found is None or any(not self.domains[name].exposed for name in found.values):
                return None  # an included file's own knob is not the root user's to turn
            return found

        result = self._answer("reachable", tuple(guards), guards, answer)
        return None if result is CANNOT_TELL else cast("Witness | None", result)

    def fails(self, path: PathCondition, value: Sub) -> tuple[str, Witness] | None:
        """Return how evaluating ``value`` raises where ``path`` holds, and the arguments.

        Only the arguments are varied, and a failure must show with them and the defaults
        (``_facts``): a value the search guesses for an environment variable, or for a
        free-text argument to break the expression (``name:='``), is no fact. The switches
        are tried first; then the arguments under which the path holds (``reachable``).
        ``None`` when nothing tried raised.
        """
        guards = list(dict.fromkeys(path))
        failure: list[str] = []

        def raises(reducer: SearchReducer) -> bool | None:
            found = self._failure(guards, value, _facts(reducer.pinned))
            if found:
                failure[:] = [found]
            return True if found else None

        def answer() -> tuple[str, Witness] | None:
            tried = self.search.run(Mode.SWITCHES, [*guards, value], raises)
            found = self._tried(tried.found)
            if found is not None and found.values and failure:
                return failure[0], found
            reached = self.reachable(path)
            if reached is None or not reached.values:
                return None
            message = self._failure(guards, value, {**self.graph.inputs(), **reached.values})
            return None if message is None else (message, reached)

        result = self._answer("fails", (tuple(guards), value), [*guards, value], answer)
        return None if result is CANNOT_TELL else cast("tuple[str, Witness] | None", result)

    @staticmethod
    def _failure(guards: list[Guard], value: Sub, pinned: dict[str, str]) -> str | None:
        """Return what evaluating ``value`` raises with ``pinned`` where the path holds."""
        probe = _RaisingReducer(pinned)
        if all_hold(probe, guards) is not True:
            return None
        probe.failures.clear()  # the guards' own are their conditions' (judged there)
        probe.reduce(value)
        return probe.failures[0] if probe.failures else None

    def unreachable(self, path: PathCondition) -> bool:
        """Return whether a path holds under no value the user can give the arguments.

        Asked over the switches (``together``), and trusted only for guards whose every
        input is a switch, has choices or is pinned: a free-text argument, an environment
        variable or an unknown might make a guard hold. So the path is unreachable when
        those guards together cannot hold (one of them, say ``$(and False $(var x))``).
        """
        if not path or self.together(path) is not None:
            return False
        decided = tuple(guard for guard in path if self._switched(guard))
        return bool(decided) and self.together(decided) is None

    def _switched(self, guard: Guard) -> bool:
        """Return whether a guard reads only switches, arguments with choices, pinned ones."""
        if isinstance(guard, Opaque):
            return False
        expressions = ((guard.expression,) if isinstance(guard, Truthy) else
                       (guard.left, *(() if guard.right is None else (guard.right,)))
                       if isinstance(guard, StrEquals) else ())
        for part in (p for expression in expressions for p in walk(expression)):
            if isinstance(part, Arg):
                domain = self.domains.get(part.name)
                if domain is None or not (domain.switch or domain.pinned is not None
                                          or domain.choices is not None):
                    return False
            elif isinstance(part, (EnvInput, Unknown, s_Opaque)):
                return False
        return True

    def same_name(self, first: Sub, first_path: PathCondition, second: Sub,
                  second_path: PathCondition) -> tuple[Witness, str] | None:
        """Return (assignment, name) where two names are equal and both paths hold.

        ``None`` when they cannot be, or when it cannot tell.
        """
        guards = (*first_path, *second_path)

        def same(reducer: SearchReducer) -> bool | None:
            left, right = self.search.names.text(first), self.search.names.text(second)
            if left is not None and right is not None and left != right:
                return False  # whether the paths hold or not
            paths = all_hold(reducer, guards)
            if paths is False:
                return False
            if left is None or right is None or paths is None:
                return None
            return True

        def answer() -> tuple[Witness, str] | None:
            tried = self.search.run(Mode.SWITCHES, [*guards, first, second], same)
            if tried.found is not None and tried.reducer is not None:
                name = self.search.names.text(first) or first.describe()
                return self._tried(tried.found) or Witness(), name
            if tried.exhaustive:
                return None
            return self.z3.same_name(first, first_path, second, second_path)

        found = self._answer("same name", (first, first_path, second, second_path),
                             (*guards, first, second), answer)
        return None if found is CANNOT_TELL else cast("tuple[Witness, str] | None", found)

    def never(self, path: PathCondition, guard: Guard) -> Contradiction | None:
        """Return why ``guard`` cannot hold where ``path`` does (for any argument values).

        ``None`` when it can, or when ``path`` itself cannot hold (that is reported where
        the path became impossible), or when it cannot tell.
        """
        key = (path, guard)
        if key in self._never:
            return self._never[key]
        opposite = _opposite(guard)
        found: Contradiction | None = None
        if opposite in path:  # no solver needed
            found = Contradiction((path[path.index(opposite)], guard)) if _satisfiable_alone(
                path) else None
        elif not self.budget.spent():
            facts = (*path, guard)
            try:
                with self.budget.question():
                    tried = self.search.run(Mode.ANY, facts, lambda r: all_hold(r, facts))
                    found = None if tried.found is not None else self.z3.never(path, guard)
            except CannotTell:
                found = None
        self._never[key] = found
        return found

    def always(self, path: PathCondition, guard: Guard) -> bool:
        """Return whether ``guard`` holds for every argument value where ``path`` holds."""

        def answer() -> bool:
            if guard in path and _satisfiable_alone(path):
                return True  # the enclosing condition says the same
            held = False  # some value tried makes the path hold

            def refutes(reducer: SearchReducer) -> bool | None:
                nonlocal held
                inside = all_hold(reducer, path)
                held = held or inside is True
                verdict = reducer.guard(guard)
                if inside is False or verdict is True:
                    return False
                return None if inside is None or verdict is None else True

            tried = self.search.run(Mode.ANY, (*path, guard), refutes)
            if tried.found is not None:
                return False
            if tried.exhaustive:  # every value tried: it holds wherever the path can
                return held
            return self.z3.always(path, guard)

        return self._answer("always", (path, guard), (*path, guard), answer) is True

    def invalid_value(self, path: PathCondition, guard: Truthy) -> tuple[str, Witness] | None:
        """Return a value the condition can take that launch rejects, with the switches."""

        def invalid(reducer: SearchReducer) -> bool | None:
            text = reducer.text(guard.expression)
            if text is not None and text.strip().lower() in CONDITION_TRUE + CONDITION_FALSE:
                return False  # a boolean, whether the path holds or not
            inside = all_hold(reducer, path)
            if inside is False:
                return False
            if text is None or inside is None:
                return None
            return True

        def answer() -> tuple[str, Witness] | None:
            tried = self.search.run(Mode.SWITCHES, (*path, guard), invalid, guess_unset=False)
            if tried.found is not None and tried.reducer is not None:
                value = tried.reducer.text(guard.expression) or ""
                return value, self._tried(tried.found) or Witness()
            if tried.exhaustive:
                return None
            return self.z3.invalid_value(path, guard)

        found = self._answer("invalid value", (path, guard), (*path, guard), answer)
        return None if found is CANNOT_TELL else cast("tuple[str, Witness] | None", found)

    def _answer(self, kind: str, question: tuple[object, ...], items: Iterable[object],
                compute: Callable[[], Answer]) -> Answer | _CannotTell:
        """Return a question's answer: this reasoner's, another's (same key), or computed.

        ``CANNOT_TELL`` when z3 gave up (remembered for every reasoner, as an answer) or
        the budget is spent (remembered here only: another root has time of its own).
        (``kind`` names what ``compute`` answers, so an answer found under a key is of
        the type ``compute`` returns.)
        """
        local = (kind, question)
        if local in self._answers:
            return cast("Answer", self._answers[local])
        key = self._shared_key(kind, question, items)
        found = _ANSWERS.get(key, _UNKNOWN)
        if found is _UNKNOWN:
            try:
                self.budget.require()
                with self.budget.question():
                    found = compute()
            except BudgetSpent:
                found = CANNOT_TELL
            except CannotTell:
                found = CANNOT_TELL
                _remember(key, found)
            else:
                _remember(key, found)
        self._answers[local] = found
        return cast("Answer", found)

    def _shared_key(self, kind: str, question: tuple[object, ...],
                    items: Iterable[object]) -> tuple[object, ...]:
        """Return the key of a question's answer, shared by every reasoner of the process.

        An answer depends on the question and on what is known of the arguments it
        reads (their domains) and of the inputs the user fixed, nothing else: roots of
        one workspace reaching the same included files ask the same questions about the
        same arguments, whatever else each declares (autoware_launch: 4,703 questions,
        3,014 distinct). Answers naming places in files (contradictions) stay with each
        reasoner (``never``).
        """
        names: set[str] = set()
        for item in items:
            names |= self.search.argument_names(item)
        known = self._domain_keys
        domains = tuple(known.get(name) or known.setdefault(
            name, _domain_key(name, self.domains.get(name))) for name in sorted(names))
        return (kind, question, domains, self._inputs)

    def _tried(self, assignment: dict[str, str] | None) -> Witness | None:
        """Return the witness of an assignment found by search (changed values only)."""
        if assignment is None:
            return None
        return Witness({name: value for name, value in assignment.items()
                        if name in self.domains and self.domains[name].defaults != {value}})


def _facts(pinned: dict[str, str]) -> dict[str, str]:
    """Return a search's assignment without what it guessed for values without a model."""
    return {key: value for key, value in pinned.items()
            if not key.startswith((FREE_KEY, OPAQUE_KEY, UNSET_KEY))}


class _RaisingReducer(SearchReducer):
    """A search's reducer that keeps what launch would raise on (``fails``)."""

    def __init__(self, pinned: dict[str, str]) -> None:
        super().__init__(pinned)
        self.failures: list[str] = []

    def fail(self, message: str, rule: str | None = None) -> None:
        self.failures.append(message)


class _CannotTell:
    """The answer to a question z3 gave up on, or that the budget left unasked."""

    def __repr__(self) -> str:
        return "CANNOT_TELL"


CANNOT_TELL = _CannotTell()
_ANSWERS: dict[tuple[object, ...], object] = {}
_UNKNOWN = object()  # no answer yet (an answer may be None)
MAX_ANSWERS = 200_000  # answers remembered in one process (a long-lived server)


def _remember(key: tuple[object, ...], answer: object) -> None:
    """Keep an answer for every reasoner of the process (forgetting all past the bound)."""
    if len(_ANSWERS) >= MAX_ANSWERS:
        _ANSWERS.clear()
    _ANSWERS[key] = answer


def _domain_key(name: str, domain: ArgumentDomain | None) -> tuple[object, ...]:
    """Return what an answer may depend on of one argument's domain."""
    if domain is None:
        return (name,)
    return (name, domain.pinned, domain.choices, tuple(sorted(domain.defaults)),
            domain.symbolic_default, domain.required, domain.exposed)


def _opposite(guard: Guard) -> Guard | None:
    """Return the guard that cannot hold together with ``guard`` (if/unless of one value)."""
    if isinstance(guard, (Truthy, StrEquals)):
        return dataclasses.replace(guard, negate=not guard.negate)
    return None


def _satisfiable_alone(path: PathCondition) -> bool:
    """Return whether a path has no guard together with its opposite (a cheap check)."""
    return all(_opposite(g) not in path for g in path)
