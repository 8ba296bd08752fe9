"""The questions rules ask about a launch graph, answered with z3.

Rules never build z3 terms: they ask whether path conditions can hold together (and under
which arguments), whether a condition can never or must always hold (and why), whether a
condition can take a value launch rejects, and whether two names can be equal. Answers
are cached per question; a solver that gives up (timeout) counts as "cannot tell", which
never produces a finding.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Iterable

import z3

from launchverify.evaluate.values import BaseReducer
from launchverify.graph import LaunchGraph
from launchverify.ir.subst import Sub
from launchverify.ir.symbolic import Guard, PathCondition, StrEquals, Truthy
from launchverify.models.booleans import CONDITION_FALSE, CONDITION_TRUE
from launchverify.smt.domains import ArgumentDomain, Mode, argument_domains
from launchverify.smt.encode import Encoder
from launchverify.smt.search import Search, all_hold, holds
from launchverify.smt.types import Contradiction, Witness

TIMEOUT_MS = 2000


class Reasoner:
    """Answers questions about one graph (one root launch file and its arguments)."""

    def __init__(self, graph: LaunchGraph) -> None:
        self.graph = graph
        self.domains: dict[str, ArgumentDomain] = argument_domains(graph)
        self._encoders: dict[Mode, Encoder] = {}
        self._together: dict[tuple[PathCondition, ...], Witness | None] = {}
        self._names: dict[tuple[object, ...], tuple[Witness, str] | None] = {}
        self._never_cache: dict[tuple[PathCondition, Guard], Contradiction | None] = {}
        self._always: dict[tuple[PathCondition, Guard], bool] = {}
        self._invalid: dict[tuple[PathCondition, Guard], tuple[str, Witness] | None] = {}
        self.search = Search(self.domains, graph.pinned)
        self.queries = 0

    def encoder(self, mode: Mode) -> Encoder:
        """Return the z3 encoder of a mode (built when a question first needs z3)."""
        if mode not in self._encoders:
            self._encoders[mode] = Encoder(self.domains, mode, self.graph.pinned)
        return self._encoders[mode]

    # ------------------------------------------------------------------ questions

    def together(self, *paths: PathCondition) -> Witness | None:
        """Return an assignment of the switches under which every path holds, if any."""
        if paths not in self._together:
            guards = [g for p in paths for g in p]
            tried = self.search.run(Mode.SWITCHES, guards, lambda r: all_hold(r, guards))
            if tried.found is not None or tried.exhaustive:
                self._together[paths] = self._tried(tried.found)
            else:
                encoder = self.encoder(Mode.SWITCHES)
                formula = z3.And(*[encoder.path(p) for p in paths])
                self._together[paths] = self._witness(encoder, [formula])
        return self._together[paths]

    def same_name(self, first: Sub, first_path: PathCondition, second: Sub,
                  second_path: PathCondition) -> tuple[Witness, str] | None:
        """Return (assignment, name) where two names are equal and both paths hold."""
        key = (first, first_path, second, second_path)
        if key not in self._names:
            guards = (*first_path, *second_path)

            def same(reducer: BaseReducer) -> bool | None:
                paths = all_hold(reducer, guards)
                if paths is False:
                    return False
                left, right = reducer.text(first), reducer.text(second)
                if left is None or right is None or paths is None:
                    return None
                return left == right

            tried = self.search.run(Mode.SWITCHES, [*guards, first, second], same)
            if tried.found is not None and tried.reducer is not None:
                name = tried.reducer.text(first) or first.describe()
                self._names[key] = (self._tried(tried.found) or Witness(), name)
                return self._names[key]
            if tried.exhaustive:
                self._names[key] = None
                return None
            encoder = self.encoder(Mode.SWITCHES)
            left, right = encoder.name(first), encoder.name(second)
            formula = z3.And(left == right, encoder.path(first_path), encoder.path(second_path))
            found = self._model(encoder, [formula])
            self._names[key] = None if found is None else (
                self._assignment(encoder, found, [formula]),
                _text(found.eval(left, model_completion=True)))
        return self._names[key]

    def never(self, path: PathCondition, guard: Guard) -> Contradiction | None:
        """Return why ``guard`` cannot hold where ``path`` does (for any argument values).

        ``None`` when it can, or when ``path`` itself cannot hold (that is reported where
        the path became impossible).
        """
        key = (path, guard)
        opposite = _opposite(guard)
        if key not in self._never_cache and opposite in path:  # no solver needed
            self._never_cache[key] = Contradiction(
                (path[path.index(opposite)], guard)) if _satisfiable_alone(path) else None
        if key not in self._never_cache:
            facts = (*path, guard)
            tried = self.search.run(Mode.ANY, facts, lambda r: all_hold(r, facts))
            self._never_cache[key] = None if tried.found is not None else self._never(
                path, guard)
        return self._never_cache[key]

    def always(self, path: PathCondition, guard: Guard) -> bool:
        """Return whether ``guard`` holds for every argument value where ``path`` holds."""
        key = (path, guard)
        if key not in self._always and guard in path and _satisfiable_alone(path):
            self._always[key] = True  # the enclosing condition says the same
        if key not in self._always:

            def refutes(reducer: BaseReducer) -> bool | None:
                inside = all_hold(reducer, path)
                verdict = holds(reducer, guard)
                if inside is False or verdict is True:
                    return False
                return None if inside is None or verdict is None else True

            if self.search.run(Mode.ANY, (*path, guard), refutes).found is not None:
                self._always[key] = False
                return False
            encoder = self.encoder(Mode.ANY)
            possible = self._check(encoder, [encoder.path(path)]) == z3.sat
            negated = z3.Not(encoder.holds(guard))
            self._always[key] = possible and self._check(
                encoder, [encoder.path(path), negated]) == z3.unsat
        return self._always[key]

    def invalid_value(self, path: PathCondition, guard: Truthy) -> tuple[str, Witness] | None:
        """Return a value the condition can take that launch rejects, with the switches."""
        key = (path, guard)
        if key not in self._invalid:

            def invalid(reducer: BaseReducer) -> bool | None:
                inside = all_hold(reducer, path)
                if inside is False:
                    return False
                text = reducer.text(guard.expression)
                if text is None or inside is None:
                    return None
                return text.strip().lower() not in CONDITION_TRUE + CONDITION_FALSE

            tried = self.search.run(Mode.SWITCHES, (*path, guard), invalid)
            if tried.found is not None and tried.reducer is not None:
                value = tried.reducer.text(guard.expression) or ""
                self._invalid[key] = (value, self._tried(tried.found) or Witness())
                return self._invalid[key]
            if tried.exhaustive:
                self._invalid[key] = None
                return None
            encoder = self.encoder(Mode.SWITCHES)
            value = encoder.string(guard.expression)
            found = None
            formulas = [encoder.path(path), encoder.raises(guard)]
            if all(_is_argument(v) for v in _variables(value)):  # unknowns: cannot tell
                found = self._model(encoder, formulas)
            self._invalid[key] = None if found is None else (
                _text(found.eval(value, model_completion=True)),
                self._assignment(encoder, found, formulas))
        return self._invalid[key]

    # ------------------------------------------------------------------ machinery

    def _never(self, path: PathCondition, guard: Guard) -> Contradiction | None:
        encoder = self.encoder(Mode.ANY)
        if self._check(encoder, [encoder.path(path)]) != z3.sat:
            return None
        solver = self._solver()
        facts = (*path, guard)
        for index, fact in enumerate(facts):
            solver.assert_and_track(encoder.holds(fact), f"g{index}")
        constraints = encoder.domain_constraints()
        for index, (_, formula) in enumerate(constraints):
            solver.assert_and_track(formula, f"d{index}")
        self.queries += 1
        if solver.check() != z3.unsat:
            return None
        if isinstance(guard, Truthy) and self._check(
                encoder, [encoder.path(path), z3.Not(encoder.raises(guard))]) != z3.sat:
            return None  # never a boolean at all: launch raises (LV002/LV207 say so)
        core = {str(c) for c in solver.unsat_core()}
        guards = tuple(f for i, f in enumerate(facts) if f"g{i}" in core)
        domains = tuple(d for i, (d, _) in enumerate(constraints) if f"d{i}" in core)
        return Contradiction(guards, domains)

    def _solver(self) -> z3.Solver:
        solver = z3.Solver()
        solver.set("timeout", TIMEOUT_MS)
        return solver

    def _check(self, encoder: Encoder, formulas: Iterable[z3.BoolRef]) -> z3.CheckSatResult:
        solver = self._solver()
        formulas = list(formulas)
        solver.add(*formulas)
        solver.add(*[f for _, f in encoder.domain_constraints()])
        self.queries += 1
        return solver.check()

    def _model(self, encoder: Encoder, formulas: list[z3.BoolRef]) -> z3.ModelRef | None:
        solver = self._solver()
        solver.add(*formulas)
        solver.add(*[f for _, f in encoder.domain_constraints()])
        self.queries += 1
        if solver.check() != z3.sat:
            return None
        model: z3.ModelRef = solver.model()
        return model

    def _tried(self, assignment: dict[str, str] | None) -> Witness | None:
        """Return the witness of an assignment found by search (changed values only)."""
        if assignment is None:
            return None
        return Witness({name: value for name, value in assignment.items()
                        if self.domains[name].defaults != {value}})

    def _witness(self, encoder: Encoder, formulas: list[z3.BoolRef]) -> Witness | None:
        model = self._model(encoder, formulas)
        return None if model is None else self._assignment(encoder, model, formulas)

    def _assignment(self, encoder: Encoder, model: z3.ModelRef,
                    formulas: list[z3.BoolRef]) -> Witness:
        """Return the arguments a question depends on that the model gives a new value."""
        names = {v.decl().name().partition(":")[2] for f in formulas for v in _variables(f)
                 if _is_argument(v)}
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


def _is_argument(variable: z3.ExprRef) -> bool:
    name: str = variable.decl().name()
    return name.startswith(("arg:", "given:"))


def _text(value: z3.ExprRef) -> str:
    return str(value.as_string()) if z3.is_string_value(value) else str(value)


def _opposite(guard: Guard) -> Guard | None:
    """Return the guard that cannot hold together with ``guard`` (if/unless of one value)."""
    if isinstance(guard, (Truthy, StrEquals)):
        return dataclasses.replace(guard, negate=not guard.negate)
    return None


def _satisfiable_alone(path: PathCondition) -> bool:
    """Return whether a path has no guard together with its opposite (a cheap check)."""
    return all(_opposite(g) not in path for g in path)
