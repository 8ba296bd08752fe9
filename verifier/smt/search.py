"""Try argument values with the concrete evaluator before asking z3.

Most questions are settled by a handful of assignments: a condition that can be true
usually is with its default or with the other boolean value. ``Search`` enumerates the
values of the arguments a question depends on (their domain when it is finite, else a few
telling candidates) and evaluates with ``BaseReducer``, exactly as the base view does. It
answers "found", or "none exists" when the enumeration covered every value; otherwise the
reasoner asks z3. Nothing here imports z3.

Its answers must be z3's, so what z3 cannot model is treated as z3 treats it
(``smt/encode.py``): a free value, named after its text, outside names (a guard without
a model is a boolean tried both ways, a value without a model read as a whole condition
is tried as true and as false; a configuration read unset, an environment variable the
user did not give and, over the switches, an argument without default take a few telling
values when the first search settles nothing); a fixed sentinel inside names
(``NameReducer``). ``tests/test_reasoner_search.py`` checks that the two agree.
"""

from __future__ import annotations

import dataclasses
import itertools
import math
import re
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from typing import Any

from launchverify.evaluate.values import BaseReducer
from launchverify.ir import subst as s
from launchverify.ir.symbolic import (
    Arg,
    EnvInput,
    Guard,
    NsPrefix,
    Opaque,
    Select,
    StrEquals,
    Truthy,
    Unknown,
    Unset,
)
from launchverify.models.booleans import CONDITION_FALSE, CONDITION_TRUE
from launchverify.smt.domains import ArgumentDomain, Mode

_QUOTES = re.compile("['\"]")
_VALUE = re.compile(r"[\w./:-]*\w[\w./:-]*")
_NUMBER = re.compile(r"(?<![\w.])\d{1,9}(?![\w.])")
MAX_ASSIGNMENTS = 256
MAX_CANDIDATES = 10
MAX_SCANNED_TEXT = 120  # longer literals are prose or code, not values to try
MAX_WORD = 48  # ``' == 'obstacle_cruise_planner'`` suggests the planner's name


@dataclass(frozen=True)
class Outcome:
    """What a search found: an assignment, or whether it covered every value."""

    found: dict[str, str] | None
    reducer: SearchReducer | None  # set to ``found`` until the next search
    exhaustive: bool


class Search:
    """Enumerates small argument domains for one graph."""

    def __init__(self, domains: dict[str, ArgumentDomain], pinned: dict[str, str], *,
                 out_of_time: Callable[[], bool] | None = None) -> None:
        self.domains = domains
        self.pinned = pinned
        # the root's solver budget is spent: a search stops, having proved nothing
        self.out_of_time = out_of_time or (lambda: False)
        self._reducer = SearchReducer(dict(pinned))  # reused: its pinned values change
        self.names = NameReducer(self._reducer.pinned)  # names, under the same assignment
        self._memo: dict[int, _Inputs] = {}  # per item, by identity (``_keep``)
        self._keep: list[object] = []

    def run(self, mode: Mode, items: Iterable[Guard | s.Sub],
            predicate: Callable[[SearchReducer], bool | None], *,
            guess_unset: bool = True) -> Outcome:
        """Look for an assignment where ``predicate`` is true.

        ``guess_unset``: whether configurations read unset may be given values (z3 does
        as much for whether conditions hold, but judges no value that reads one).

        Over the switches, the enumeration covers each switch's values; every other
        argument keeps its default, or has none and stays symbolic. A verdict the
        predicate reaches despite a symbolic argument holds for every value of it (the
        reducer gives a text only when the value does not depend on what it could not
        reduce), so the search is exhaustive as long as no verdict was "cannot tell".
        """
        read = _Inputs.union(self._inputs(item) for item in items)
        choices = self.candidates(sorted(read.names), mode, read.literals)
        choices += [(OPAQUE_KEY + d, ("true", "false")) for d in sorted(read.opaque)]
        choices += [(FREE_KEY + label, CLASSES) for label in sorted(read.whole - read.nested)
                    if self._free(label, mode)]
        complete = mode is Mode.SWITCHES or (
            all(self.finite(name) for name in read.names)
            and all("env:" + name in self.pinned for name, _ in read.env))
        outcome = self._try(mode, choices, predicate, complete)
        if outcome.found is None and not outcome.exhaustive:
            # What z3 takes as any string (a configuration unset where it is read, an
            # environment variable, an argument without default over the switches):
            # trying the literals it meets may find what can happen, never prove that
            # nothing can.
            guesses = self.free_candidates(read, mode, guess_unset)
            if guesses:
                tried = self._try(mode, choices + guesses, predicate, complete=False)
                if tried.found is not None:
                    return tried
        return outcome

    def _try(self, mode: Mode, choices: list[tuple[str, tuple[str, ...]]],
             predicate: Callable[[SearchReducer], bool | None], complete: bool) -> Outcome:
        """Try the assignments of ``choices``; ``complete``: they cover every value."""
        whole = math.prod(len(values) for _, values in choices) <= MAX_ASSIGNMENTS
        if not whole and mode is Mode.SWITCHES:
            return Outcome(None, None, exhaustive=False)  # z3 says whether one exists
        exhaustive = whole and complete
        assignments = _product(choices) if whole else itertools.islice(
            _nearest_first(choices), MAX_ASSIGNMENTS)
        reducer = self._reducer
        for assignment in assignments:
            if self.out_of_time():
                return Outcome(None, None, exhaustive=False)
            reducer.pinned = self.names.pinned = {**self.pinned, **assignment}
            verdict = predicate(reducer)
            if verdict is True:
                return Outcome(assignment, reducer, exhaustive)
            if verdict is None:
                exhaustive = False
        return Outcome(None, None, exhaustive)

    def _free(self, label: str, mode: Mode) -> bool:
        """Return whether z3 takes a value read as a whole condition as a free string.

        Values without a model always are; an argument without default is only over
        the switches, when it is no switch and keeps no pinned value (``Encoder._arg``).
        """
        if not label.startswith(ARG_LABEL):
            return True
        domain = self.domains.get(label[len(ARG_LABEL):])
        return mode is Mode.SWITCHES and (domain is None or (
            not domain.switch and domain.pinned is None))

    def finite(self, name: str) -> bool:
        """Return whether the enumeration covers every value ``ros2 launch`` accepts."""
        domain = self.domains.get(name)
        return domain is not None and domain.values(Mode.ANY) is not None

    def candidates(self, names: list[str], mode: Mode,
                   literals: frozenset[str]) -> list[tuple[str, tuple[str, ...]]]:
        """Return the values to try per argument."""
        out: list[tuple[str, tuple[str, ...]]] = []
        for name in names:
            domain = self.domains.get(name)
            if domain is None or domain.pinned is not None:
                continue
            values = domain.values(mode)
            if values is None:
                if mode is Mode.SWITCHES:
                    continue  # keeps its default: the reducer uses it
                extra = sorted(literals - domain.defaults)
                values = (*sorted(domain.defaults), "true", "false", *extra)
                values = tuple(dict.fromkeys(values))[:MAX_CANDIDATES]
            out.append((name, values))
        return out

    def free_candidates(self, read: _Inputs, mode: Mode, guess_unset: bool
                        ) -> list[tuple[str, tuple[str, ...]]]:
        """Return values to try for what z3 takes as a free string inside a value.

        Those are configurations unset where they are read (launch raises on reading one;
        only with ``guess_unset``), environment variables the user did not give (any of
        them over any value, those without default over the switches: ``Encoder._env``)
        and, over the switches, arguments without default that are no switch and keep no
        pinned value (``Encoder._arg``). The literals they are compared with are the
        values worth trying; a value read as a whole condition is already tried as true
        and as false (``run``).
        """
        values = tuple(dict.fromkeys(("true", "false", *sorted(read.literals))))[
            :MAX_CANDIDATES]
        keys = [UNSET_KEY + name for name in sorted(read.unset)] if guess_unset else []
        keys += [FREE_KEY + ENV_LABEL + name for name, has_default in sorted(read.env)
                 if "env:" + name not in self.pinned
                 and (mode is Mode.ANY or not has_default)]
        if mode is Mode.SWITCHES:
            keys += [FREE_KEY + label for label in sorted(read.nested)
                     if label.startswith(ARG_LABEL) and self._free(label, mode)]
        return [(key, values) for key in dict.fromkeys(keys)]

    def argument_names(self, item: object) -> frozenset[str]:
        """Return the launch arguments a guard or value reads (``frozenset()`` for others)."""
        if isinstance(item, (Guard, s.Sub)):
            return self._inputs(item).names
        return frozenset()

    def _inputs(self, item: Guard | s.Sub) -> _Inputs:
        """Return what ``run`` varies for an item (``_inputs_of``), remembered per item."""
        key = id(item)
        known = self._memo.get(key)
        if known is None:
            known = self._memo[key] = _inputs_of(item)
            self._keep.append(item)
        return known


# In ``pinned``, beside the arguments: the value tried for a configuration unset where it
# is read, whether a guard without a model holds, and the value of a condition that is a
# value without a model (z3 takes each as free, by name).
UNSET_KEY = "unset:"
OPAQUE_KEY = "opaque:"
FREE_KEY = "free:"
# A value without a model that is only ever read as a whole condition matters only as
# true or false: one of each settles whether guards hold (a value that is neither makes
# every guard reading it fail, as one of the two already does).
CLASSES = ("true", "false")
# What ``Encoder`` models; any other value is a free string to z3, named after its text.
_ENCODED = frozenset({
    s.Text, s.Concat, Arg, EnvInput, Select, NsPrefix, s.PythonExpr, s.EqualsSub,
    s.NotEqualsSub, s.NotSub, s.AndSub, s.OrSub, s.AnySub, s.AllSub, s.IfElse, s.AsBool,
    s.PathJoin, s.StringJoin})


@dataclass(frozen=True)
class _Inputs:
    """What a question's item reads that a search may vary."""

    names: frozenset[str]  # launch arguments
    literals: frozenset[str]  # short texts worth trying as their values
    unset: frozenset[str]  # configurations read unset
    opaque: frozenset[str]  # guards without a model
    whole: frozenset[str]  # values without a model read as a whole condition...
    nested: frozenset[str]  # ...and those read inside another value
    env: frozenset[tuple[str, bool]]  # environment variables, whether each has a default

    @staticmethod
    def union(parts: Iterable[_Inputs]) -> _Inputs:
        """Return what several items read together."""
        fields = [field.name for field in dataclasses.fields(_Inputs)]
        merged: dict[str, set[Any]] = {name: set() for name in fields}
        for part in parts:
            for name in fields:
                merged[name] |= getattr(part, name)
        return _Inputs(**{name: frozenset(values) for name, values in merged.items()})


def free_label(sub: s.Sub) -> str | None:
    """Return the name z3 gives a value it does not model (``None``: it models it)."""
    if type(sub) in _ENCODED:
        return None
    return f"<{sub.reason}>" if isinstance(sub, Unknown) else sub.describe()


ARG_LABEL = "arg "  # an argument without default, named as z3 names it when it is free
ENV_LABEL = "env "  # an environment variable the user did not give (``free_candidates``)


def condition_label(sub: s.Sub) -> str | None:
    """Return ``free_label``, or the name of an argument without default (maybe free)."""
    if isinstance(sub, Arg) and sub.default is None:
        return ARG_LABEL + sub.name
    return free_label(sub)


class SearchReducer(BaseReducer):
    """``BaseReducer``, where what z3 takes as free (see the module doc) is given values.

    A condition's value that is not a boolean makes it fail, as z3's encoding has it
    (``BaseReducer`` cannot tell, since launch would raise there: LV207 says so).
    """

    def __init__(self, pinned: dict[str, str]) -> None:
        super().__init__(pinned)
        self._dispatch[Unset] = self._unset

    def _unset(self, sub: s.Sub) -> s.Sub:
        assert isinstance(sub, Unset)
        value = self.pinned.get(UNSET_KEY + sub.name)
        return sub if value is None else s.Text(value)

    def guard(self, guard: Guard) -> bool | None:
        if isinstance(guard, Opaque):
            value = self.pinned.get(OPAQUE_KEY + guard.description)
            return None if value is None else value == "true"
        if isinstance(guard, Truthy) and (text := self.condition_text(guard)) is not None:
            return text.strip().lower() in (CONDITION_FALSE if guard.negate else CONDITION_TRUE)
        return super().guard(guard)

    def arg(self, sub: Arg) -> s.Sub:
        if sub.default is None and sub.name not in self.pinned:  # the value tried, if any
            value = self.pinned.get(FREE_KEY + ARG_LABEL + sub.name)
            if value is not None:
                return s.Text(value)
        return super().arg(sub)

    def env_input(self, sub: EnvInput) -> s.Sub:
        if "env:" + sub.name not in self.pinned:  # not given by the user: the value tried
            value = self.pinned.get(FREE_KEY + ENV_LABEL + sub.name)
            if value is not None:
                return s.Text(value)
        return super().env_input(sub)

    def condition_text(self, guard: Truthy) -> str | None:
        """Return a condition's text: the value tried for it when it has no model."""
        label = condition_label(guard.expression)
        if label is not None:
            value = self.pinned.get(FREE_KEY + label)
            if value is not None:
                return value
        return self.text(guard.expression)


class NameReducer(SearchReducer):
    """The base view of a ROS name, where z3 would see a fixed unknown: a fixed text.

    Inside a name, ``Encoder.name`` turns what it cannot model (an unknown, an argument
    that has no default and keeps none, an unset environment variable) into a sentinel,
    a constant equal only to itself. Reducing them to the same sentinels lets the search
    settle the name comparisons z3 would (most names of real trees hold an unknown: the
    share folder of a package outside the workspace, a command's output). Outside names,
    the same values are free (``SearchReducer``).
    """

    def reduce(self, sub: s.Sub) -> s.Sub:
        label = free_label(sub)
        if label is not None:
            return s.Text(SENTINEL.format(label))
        return super().reduce(sub)

    def condition_text(self, guard: Truthy) -> str | None:
        return self.text(guard.expression)  # a value without a model: its sentinel

    def arg(self, sub: Arg) -> s.Sub:
        if sub.name not in self.pinned and sub.default is None:
            return s.Text(SENTINEL.format(f"arg {sub.name}"))
        return super().arg(sub)

    def env_input(self, sub: EnvInput) -> s.Sub:
        if "env:" + sub.name not in self.pinned and sub.default is None:
            return s.Text(SENTINEL.format(f"env {sub.name}"))
        return super().env_input(sub)


SENTINEL = "\x01{}\x01"  # as ``Encoder._sentinel`` writes one


def inputs_of(item: Guard | s.Sub) -> tuple[frozenset[str], frozenset[str]]:
    """Return the argument names and short literals an expression or guard holds.

    Each shared part is visited once; a ``Select``'s guards count, as its encoding reads
    them.
    """
    found = _inputs_of(item)
    return found.names, found.literals


def _inputs_of(item: Guard | s.Sub) -> _Inputs:
    """Return everything a search may vary for an item (each shared part visited once)."""
    names: set[str] = set()
    literals: set[str] = set()
    unset: set[str] = set()
    opaque: set[str] = set()
    whole: set[str] = set()
    nested: set[str] = set()
    env: set[tuple[str, bool]] = set()
    seen: set[int] = set()
    stack: list[object] = [item]
    while stack:
        current = stack.pop()
        if id(current) in seen:
            continue
        seen.add(id(current))
        if isinstance(current, Truthy):
            label = condition_label(current.expression)
            if label is None:
                stack.append(current.expression)
            else:
                whole.add(label)
                if isinstance(current.expression, Arg):
                    names.add(current.expression.name)
        elif isinstance(current, StrEquals):
            stack.extend(x for x in (current.left, current.right) if x is not None)
        elif isinstance(current, s.Sub):
            if (label := condition_label(current)) is not None:
                nested.add(label)
            if isinstance(current, Arg):
                names.add(current.name)
            elif isinstance(current, Unset):
                unset.add(current.name)
            elif isinstance(current, EnvInput):
                env.add((current.name, current.default is not None))
            elif isinstance(current, s.Text) and len(current.text) <= MAX_SCANNED_TEXT:
                literals.update(_words(current.text))
            elif isinstance(current, Select):
                stack.extend(current.guards)
            stack.extend(current.children())
        elif isinstance(current, Opaque):
            opaque.add(current.description)
    return _Inputs(frozenset(names), frozenset(literals), frozenset(unset), frozenset(opaque),
                   frozenset(whole), frozenset(nested), frozenset(env))


def all_hold(reducer: SearchReducer, guards: Iterable[Guard]) -> bool | None:
    """Return whether every guard holds (``False`` as soon as one surely does not)."""
    result: bool | None = True
    for guard in guards:
        verdict = reducer.guard(guard)
        if verdict is False:
            return False
        if verdict is None:
            result = None
    return result


def _words(text: str) -> Iterator[str]:
    """Yield a literal and the values it suggests trying.

    Those are the quoted words inside it (``r2`` in ``' == 'r2'``) and its numbers with
    their successors (``40`` and ``41`` in ``' >= 40'``).
    """
    if len(text) <= MAX_WORD and not any(c.isspace() for c in text):
        yield text
    # A literal between substitutions may start inside quotes or outside them
    # (``' == 'r2'`` closes one first): every quoted-off piece that looks like a value.
    for piece in _QUOTES.split(text):
        if len(piece) <= MAX_WORD and _VALUE.fullmatch(piece):
            yield piece
    for number in _NUMBER.findall(text):
        yield number
        yield str(int(number) + 1)
        yield str(max(int(number) - 1, 0))


def _nearest_first(choices: list[tuple[str, tuple[str, ...]]]) -> Iterator[dict[str, str]]:
    """Yield every assignment, those changing fewer arguments from their first value first.

    Where the whole product is too long to try, a condition that can hold usually does
    with one or two arguments changed: those are tried before the budget runs out.
    """
    names = [name for name, _ in choices]
    first = {name: values[0] for name, values in choices}
    for count in range(len(choices) + 1):
        for changed in itertools.combinations(range(len(choices)), count):
            others = [choices[i][1][1:] for i in changed]
            for values in itertools.product(*others):
                assignment = dict(first)
                assignment.update((names[i], v) for i, v in zip(changed, values, strict=True))
                yield assignment


def _product(choices: list[tuple[str, tuple[str, ...]]]) -> Iterator[dict[str, str]]:
    names = [name for name, _ in choices]
    for values in itertools.product(*[values for _, values in choices]):
        yield dict(zip(names, values, strict=True))
