"""The z3 side of the reasoner: what the concrete search could not settle.

Each method answers one question of ``reasoner.Reasoner`` with the encodings of
``encode``; a solver that gives up (a timeout, an undecided theory) raises
``CannotTell``, and one asked once the root's budget is spent raises ``BudgetSpent``:
the reasoner answers "cannot tell". Importing this module imports z3, which is why the
reasoner imports it only when a question needs it.
"""

from __future__ import annotations

from collections.abc import Iterable

import z3

from launchverify.ir.subst import Sub
from launchverify.ir.symbolic import Guard, PathCondition, Truthy
from launchverify.smt.budget import BudgetSpent, CannotTell, SolverBudget
from launchverify.smt.domains import ArgumentDomain, Mode
from launchverify.smt.encode import Encoder
from launchverify.smt.search import inputs_of
from launchverify.smt.types import Contradiction, Witness

TIMEOUT_MS = 2000  # per question; the root's budget (``budget.py``) bounds them all


class Z3Backend:
    """Asks z3 about one graph's values and guards."""

    def __init__(self, domains: dict[str, ArgumentDomain], pinned: dict[str, str],
                 budget: SolverBudget | None = None) -> None:
        self.domains = domains
        self.pinned = pinned
        self.budget = budget or SolverBudget()
        self._encoders: dict[Mode, Encoder] = {}
        self.queries = 0

    def encoder(self, mode: Mode) -> Encoder:
        """Return the encoder of a mode (built on first use)."""
        if mode not in self._encoders:
            self._encoders[mode] = Encoder(self.domains, mode, self.pinned)
        return self._encoders[mode]

    # ------------------------------------------------------------------ questions

    def together(self, paths: tuple[PathCondition, ...]) -> Witness | None:
        """Return switches under which every path holds, if any."""
        encoder = self.encoder(Mode.SWITCHES)
        formula = z3.And(*[encoder.path(p) for p in paths])
        names = argument_names([g for p in paths for g in p])
        model = self._model(encoder, [formula], names)
        if model is None:
            return None
        return self._assignment(encoder, model, names)

    def same_name(self, first: Sub, first_path: PathCondition, second: Sub,
                  second_path: PathCondition) -> tuple[Witness, str] | None:
        """Return (switches, name) where two names are equal and both paths hold."""
        encoder = self.encoder(Mode.SWITCHES)
        left, right = encoder.name(first), encoder.name(second)
        formula = z3.And(left == right, encoder.path(first_path), encoder.path(second_path))
        names = argument_names([first, second, *first_path, *second_path])
        found = self._model(encoder, [formula], names)
        if found is None:
            return None
        return (self._assignment(encoder, found, names),
                _text(found.eval(left, model_completion=True)))

    def never(self, path: PathCondition, guard: Guard) -> Contradiction | None:
        """Return the unsat core when ``guard`` cannot hold where ``path`` can."""
        encoder = self.encoder(Mode.ANY)
        names = argument_names([*path, guard])
        if self._check(encoder, [encoder.path(path)], names) != z3.sat:
            return None
        solver = self._solver()
        facts = (*path, guard)
        for index, fact in enumerate(facts):
            solver.assert_and_track(encoder.holds(fact), f"g{index}")
        constraints = encoder.domain_constraints(names)
        for index, (_, formula) in enumerate(constraints):
            solver.assert_and_track(formula, f"d{index}")
        if self._run(solver) != z3.unsat:
            return None
        if isinstance(guard, Truthy) and self._check(
                encoder, [encoder.path(path), z3.Not(encoder.raises(guard))], names) != z3.sat:
            return None  # never a boolean at all: launch raises (LV002/LV207 say so)
        core = {str(c) for c in solver.unsat_core()}
        guards = tuple(f for i, f in enumerate(facts) if f"g{i}" in core)
        domains = tuple(d for i, (d, _) in enumerate(constraints) if f"d{i}" in core)
        return Contradiction(guards, domains)

    def always(self, path: PathCondition, guard: Guard) -> bool:
        """Return whether ``guard`` holds wherever ``path`` does (and ``path`` can)."""
        encoder = self.encoder(Mode.ANY)
        names = argument_names([*path, guard])
        if self._check(encoder, [encoder.path(path)], names) != z3.sat:
            return False
        negated = z3.Not(encoder.holds(guard))
        return bool(self._check(encoder, [encoder.path(path), negated], names) == z3.unsat)

    def invalid_value(self, path: PathCondition, guard: Truthy) -> tuple[str, Witness] | None:
        """Return a non-boolean value the condition takes under some switches."""
        encoder = self.encoder(Mode.SWITCHES)
        value = encoder.string(guard.expression)
        if not all(_is_argument(v) for v in _variables(value)):
            return None  # it depends on unknowns: cannot tell
        formulas = [encoder.path(path), encoder.raises(guard)]
        names = argument_names([*path, guard])
        found = self._model(encoder, formulas, names)
        if found is None:
            return None
        return (_text(found.eval(value, model_completion=True)),
                self._assignment(encoder, found, names))

    # ------------------------------------------------------------------ machinery

    def _solver(self) -> z3.Solver:
        solver = z3.Solver()
        solver.set("timeout", TIMEOUT_MS)
        return solver

    def _run(self, solver: z3.Solver) -> z3.CheckSatResult:
        """Ask z3 within the budget left: ``sat`` or ``unsat``, else ``CannotTell``.

        A question the budget cut short raises ``BudgetSpent`` (another root, with time
        of its own, may still answer it).
        """
        self.budget.require()
        limit = min(TIMEOUT_MS, max(1, int(self.budget.remaining() * 1000)))
        solver.set("timeout", limit)
        self.queries += 1
        result = solver.check()
        if result == z3.unknown:
            if limit < TIMEOUT_MS:  # cut by the root's budget, not by its own limit
                self.budget.ran_out = True
                raise BudgetSpent
            raise CannotTell
        return result

    def _check(self, encoder: Encoder, formulas: Iterable[z3.BoolRef],
               names: set[str]) -> z3.CheckSatResult:
        solver = self._solver()
        solver.add(*formulas)
        solver.add(*[f for _, f in encoder.domain_constraints(names)])
        return self._run(solver)

    def _model(self, encoder: Encoder, formulas: list[z3.BoolRef],
               names: set[str]) -> z3.ModelRef | None:
        solver = self._solver()
        solver.add(*formulas)
        solver.add(*[f for _, f in encoder.domain_constraints(names)])
        if self._run(solver) != z3.sat:
            return None
        model: z3.ModelRef = solver.model()
        return model

    def _assignment(self, encoder: Encoder, model: z3.ModelRef, names: set[str]) -> Witness:
        """Return the arguments a question depends on that the model gives a new value."""
        values: dict[str, str] = {}
        for name in sorted(names):
            domain = self.domains.get(name)
            if domain is None or domain.pinned is not None:
                continue
            if not z3.is_true(model.eval(encoder.given(name), model_completion=True)):
                continue
            value = _text(model.eval(encoder.cli(name), model_completion=True))
            if domain.defaults != {value}:
                values[name] = value
        return Witness(values)


def _variables(term: z3.ExprRef) -> list[z3.ExprRef]:
    """Return the free constants of a term (shared subterms visited once)."""
    found: dict[int, z3.ExprRef] = {}
    visited: set[int] = set()
    stack = [term]
    while stack:
        item = stack.pop()
        if item.get_id() in visited:
            continue
        visited.add(item.get_id())
        if z3.is_const(item) and item.decl().kind() == z3.Z3_OP_UNINTERPRETED:
            found[item.get_id()] = item
            continue
        stack.extend(item.children())
    return list(found.values())


def argument_names(items: Iterable[Sub | Guard]) -> set[str]:
    """Return the launch arguments expressions and guards read (what a witness may set).

    The same answer as the arguments among the free constants of their z3 encoding,
    read from launchverify's own expressions instead of a walk through z3's terms.
    """
    return {name for item in items for name in inputs_of(item)[0]}


def _is_argument(variable: z3.ExprRef) -> bool:
    name: str = variable.decl().name()
    return name.startswith(("arg:", "given:"))


def _text(value: z3.ExprRef) -> str:
    return str(value.as_string()) if z3.is_string_value(value) else str(value)
