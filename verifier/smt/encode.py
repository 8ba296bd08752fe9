"""Residual values and guards as z3 terms.

Each value of the graph (``ir.subst`` and ``ir.symbolic`` expressions) becomes a z3
string; each guard a z3 boolean. Operators follow ``evaluate.values`` exactly; where the
exact rule has no z3 spelling (``float()`` comparison, YAML parsing, an unsupported Python
expression) the result is a fresh unknown value, never a guess. An unknown is named after
what it stands for, so the same expression twice is the same value.

Launch arguments follow ``domains``: an argument occurrence is its command-line value when
given (``given:x``/``arg:x``), else its default. In ``fqn`` encoding, what is
unconstrained (an argument without default, an environment variable without default, an
unknown) becomes a sentinel string no real value can equal: two names then match only if
they match whatever that value is.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

import z3

from launchverify.ir import subst as s
from launchverify.ir.symbolic import (
    Arg,
    EnvInput,
    Guard,
    NsPrefix,
    Opaque,
    PathCondition,
    Select,
    StrEquals,
    Truthy,
    Unknown,
)
from launchverify.smt import regexes as rx
from launchverify.smt.domains import ArgumentDomain, Mode

TRUE_TEXT, FALSE_TEXT = z3.StringVal("true"), z3.StringVal("false")


class Encoder:
    """Encodes one graph's values for one ``Mode``; terms are memoised per expression."""

    def __init__(self, domains: dict[str, ArgumentDomain], mode: Mode,
                 pinned: dict[str, str] | None = None) -> None:
        self.domains = domains
        self.mode = mode
        self.pinned = pinned or {}
        self.arguments: set[str] = set()  # arguments met while encoding
        self._memo: dict[tuple[int, bool], z3.ExprRef] = {}
        self._keep: list[object] = []  # memo keys are ids: keep their objects alive
        self._fqn = False
        self._domains_memo: dict[str, list[tuple[str, z3.BoolRef]]] = {}
        self._dispatch: dict[type, Callable[[s.Sub], z3.SeqRef]] = {
            s.Text: self._text,
            s.Concat: self._concat,
            Arg: self._arg,
            EnvInput: self._env,
            Select: self._select,
            NsPrefix: self._ns_prefix,
            s.PythonExpr: self._python,
            s.EqualsSub: self._equals_text,
            s.NotEqualsSub: self._equals_text,
            s.NotSub: self._not,
            s.AndSub: self._combine,
            s.OrSub: self._combine,
            s.AnySub: self._combine,
            s.AllSub: self._combine,
            s.IfElse: self._if_else,
            s.AsBool: self._as_bool,
            s.PathJoin: self._path_join,
            s.StringJoin: self._string_join,
        }

    # ------------------------------------------------------------------ public

    def string(self, sub: s.Sub) -> z3.SeqRef:
        """Return the z3 string a value denotes."""
        key = (id(sub), self._fqn)
        term = self._memo.get(key)
        if term is None:
            handler = self._dispatch.get(type(sub))
            term = handler(sub) if handler is not None else self.unknown(sub)
            self._memo[key] = term
            self._keep.append(sub)
        return term

    def name(self, sub: s.Sub) -> z3.SeqRef:
        """Return a ROS name's term, unconstrained inputs as sentinels (see module doc)."""
        previous, self._fqn = self._fqn, True
        try:
            return self.string(sub)
        finally:
            self._fqn = previous

    def holds(self, guard: Guard) -> z3.BoolRef:
        """Return the formula of one guard."""
        if isinstance(guard, Truthy):
            value = self.string(guard.expression)
            return rx.condition_false(value) if guard.negate else rx.condition_true(value)
        if isinstance(guard, StrEquals):
            if guard.right is None:
                unset = z3.Bool(f"unset:{guard.left.describe()}")
                return z3.Not(unset) if guard.negate else unset
            equal = self.string(guard.left) == self.string(guard.right)
            return z3.Not(equal) if guard.negate else equal
        assert isinstance(guard, Opaque)
        return z3.Bool(f"opaque:{guard.description}")

    def path(self, path: PathCondition) -> z3.BoolRef:
        """Return the conjunction of a path condition."""
        return z3.And(*[self.holds(g) for g in path]) if path else z3.BoolVal(True)

    def raises(self, guard: Truthy) -> z3.BoolRef:
        """Return when a condition's value is not a boolean (launch raises)."""
        value = self.string(guard.expression)
        return z3.Not(z3.Or(rx.condition_true(value), rx.condition_false(value)))

    def domain_constraints(self, names: Iterable[str] | None = None
                           ) -> list[tuple[str, z3.BoolRef]]:
        """Return (description, formula) for these arguments (default: all met so far)."""
        out = []
        for name in sorted(self.arguments if names is None else names):
            out.extend(self._domain(name))
        return out

    def _domain(self, name: str) -> list[tuple[str, z3.BoolRef]]:
        cached = self._domains_memo.get(name)
        if cached is not None:
            return cached
        out: list[tuple[str, z3.BoolRef]] = []
        domain = self.domains.get(name)
        given, value = self.given(name), self.cli(name)
        if domain is not None and domain.pinned is not None:
            out.append((domain.describe(self.mode),
                        z3.And(given, value == z3.StringVal(domain.pinned))))
        elif domain is not None:
            values = domain.values(self.mode)
            if values is not None:
                out.append((domain.describe(self.mode),
                            z3.Implies(given, rx.one_of(value, values))))
            if domain.required:
                out.append((f"{name} has no default: it must be given", given))
            elif self.mode is Mode.SWITCHES and not domain.switch:
                out.append((f"{name} keeps its default", z3.Not(given)))
        self._domains_memo[name] = out
        return out

    def given(self, name: str) -> z3.BoolRef:
        """Whether argument ``name`` is given on the command line."""
        return z3.Bool(f"given:{name}")

    def cli(self, name: str) -> z3.SeqRef:
        """The command-line value of argument ``name`` (when given)."""
        return z3.String(f"arg:{name}")

    def unknown(self, sub: s.Sub) -> z3.SeqRef:
        """A value we cannot model: a fresh string named after it (a sentinel in names)."""
        label = sub.describe() if not isinstance(sub, Unknown) else f"<{sub.reason}>"
        return self._sentinel(label) if self._fqn else z3.String(f"unknown:{label}")

    # ------------------------------------------------------------------ inputs

    def _sentinel(self, label: str) -> z3.SeqRef:
        return z3.StringVal(f"\x01{label}\x01")

    def _arg(self, sub: s.Sub) -> z3.SeqRef:
        assert isinstance(sub, Arg)
        self.arguments.add(sub.name)
        domain = self.domains.get(sub.name)
        if domain is not None and domain.pinned is not None:
            return z3.StringVal(domain.pinned)
        fixed = self.mode is Mode.SWITCHES and (domain is None or not domain.switch)
        if sub.default is None:
            if not fixed:
                return self.cli(sub.name)
            # Unconstrained: whatever the user passes, assumed sensible (never a witness).
            return self._sentinel(f"arg {sub.name}") if self._fqn else z3.String(
                f"unknown:arg {sub.name}")
        default = self.string(sub.default)
        if fixed:
            return default
        return z3.If(self.given(sub.name), self.cli(sub.name), default)

    def _env(self, sub: s.Sub) -> z3.SeqRef:
        assert isinstance(sub, EnvInput)
        pinned = self.pinned.get("env:" + sub.name)
        if pinned is not None:
            return z3.StringVal(pinned)
        if sub.default is not None and self.mode is Mode.SWITCHES:
            return self.string(sub.default)
        if sub.default is None and self._fqn:
            return self._sentinel(f"env {sub.name}")
        value = z3.String(f"env:{sub.name}")
        if sub.default is None:
            return value
        return z3.If(z3.Bool(f"env-set:{sub.name}"), value, self.string(sub.default))

    # ------------------------------------------------------------------ structure

    def _text(self, sub: s.Sub) -> z3.SeqRef:
        assert isinstance(sub, s.Text)
        return z3.StringVal(sub.text)

    def _concat(self, sub: s.Sub) -> z3.SeqRef:
        assert isinstance(sub, s.Concat)
        parts = [self.string(p) for p in sub.parts]
        return z3.Concat(*parts) if len(parts) > 1 else parts[0]

    def _select(self, sub: s.Sub) -> z3.SeqRef:
        assert isinstance(sub, Select)
        return z3.If(self.path(sub.guards), self.string(sub.then), self.string(sub.otherwise))

    def _ns_prefix(self, sub: s.Sub) -> z3.SeqRef:
        """``make_absolute(prefix_namespace(base, ns))`` (one trailing ``/`` stripped)."""
        assert isinstance(sub, NsPrefix)
        ns = self.string(sub.ns)
        slash = z3.StringVal("/")
        if sub.base is None:
            result = ns
        else:
            base = self.string(sub.base)
            joined = z3.Concat(z3.If(base == slash, z3.StringVal(""), base), slash, ns)
            result = z3.If(z3.Or(z3.PrefixOf(slash, ns), base == z3.StringVal("")), ns, joined)
        result = z3.If(z3.And(result != slash, z3.SuffixOf(slash, result)),
                       z3.SubString(result, 0, z3.Length(result) - 1), result)
        if sub.absolute:
            result = z3.If(z3.PrefixOf(slash, result), result, z3.Concat(slash, result))
        return result

    def _path_join(self, sub: s.Sub) -> z3.SeqRef:
        """``os.path.join``: an absolute part restarts the path."""
        assert isinstance(sub, s.PathJoin)
        if not sub.parts:
            return z3.StringVal("")
        slash = z3.StringVal("/")
        result = self.string(sub.parts[0])
        for part in sub.parts[1:]:
            term = self.string(part)
            glued = z3.If(z3.Or(result == z3.StringVal(""), z3.SuffixOf(slash, result)),
                          z3.Concat(result, term), z3.Concat(result, slash, term))
            result = z3.If(z3.PrefixOf(slash, term), term, glued)
        return result

    def _string_join(self, sub: s.Sub) -> z3.SeqRef:
        assert isinstance(sub, s.StringJoin)
        if not sub.parts:
            return z3.StringVal("")
        delimiter = self.string(sub.delimiter)
        pieces: list[z3.SeqRef] = []
        for index, part in enumerate(sub.parts):
            if index:
                pieces.append(delimiter)
            pieces.append(self.string(part))
        return z3.Concat(*pieces) if len(pieces) > 1 else pieces[0]

    # ------------------------------------------------------------------ operators

    def _bool_text(self, value: z3.BoolRef, negate: bool = False) -> z3.SeqRef:
        return z3.If(value, FALSE_TEXT, TRUE_TEXT) if negate else z3.If(value, TRUE_TEXT,
                                                                          FALSE_TEXT)

    def _equals(self, left_sub: s.Sub, right_sub: s.Sub) -> z3.BoolRef:
        """``EqualsSubstitution``: as booleans, else as numbers, else as text."""
        left, right = self.string(left_sub), self.string(right_sub)
        label = f"{left_sub.describe()} == {right_sub.describe()}"
        both_bool = z3.And(rx.boolish(left), rx.boolish(right))
        both_number = z3.And(rx.maybe_number(left), rx.maybe_number(right))
        same_number = z3.If(z3.And(left == right, z3.Not(z3.Contains(left, "n")),
                                   z3.Not(z3.Contains(left, "N"))),
                            z3.BoolVal(True), z3.Bool(f"equals:{label}"))
        return z3.If(both_bool, rx.boolish_true(left) == rx.boolish_true(right),
                     z3.If(both_number, same_number, left == right))

    def _typed(self, sub: s.Sub) -> tuple[z3.BoolRef, z3.BoolRef]:
        """Return (valid, value) of the typed truth rule of boolean substitutions."""
        value = self.string(sub)
        true, false = rx.one_of(value, rx.TYPED_TRUE), rx.one_of(value, rx.TYPED_FALSE)
        return z3.Or(true, false), true

    def _not(self, sub: s.Sub) -> z3.SeqRef:
        assert isinstance(sub, s.NotSub)
        valid, value = self._typed(sub.value)
        return z3.If(valid, self._bool_text(value, negate=True), self.unknown(sub))

    def _combine(self, sub: s.Sub) -> z3.SeqRef:
        """``$(and)``, ``$(or)``, ``$(any)``, ``$(all)`` under the typed truth rule."""
        if isinstance(sub, (s.AndSub, s.OrSub)):
            operands: tuple[s.Sub, ...] = (sub.left, sub.right)
        else:
            assert isinstance(sub, (s.AnySub, s.AllSub))
            operands = sub.args
        typed = [self._typed(o) for o in operands]
        truths = [t for _, t in typed]
        result = z3.Or(*truths) if isinstance(sub, (s.OrSub, s.AnySub)) else z3.And(*truths)
        valid = z3.And(*[v for v, _ in typed])
        return z3.If(valid, self._bool_text(result), self.unknown(sub))

    def _equals_text(self, sub: s.Sub) -> z3.SeqRef:
        assert isinstance(sub, (s.EqualsSub, s.NotEqualsSub))
        return self._bool_text(self._equals(sub.left, sub.right),
                               negate=isinstance(sub, s.NotEqualsSub))

    def _as_bool(self, sub: s.Sub) -> z3.SeqRef:
        assert isinstance(sub, s.AsBool)
        return z3.If(rx.as_bool_true(self.string(sub.value)), z3.StringVal("True"),
                     z3.StringVal("False"))

    def _if_else(self, sub: s.Sub) -> z3.SeqRef:
        assert isinstance(sub, s.IfElse)
        valid, value = self._typed(sub.condition)
        chosen = z3.If(value, self.string(sub.if_value), self.string(sub.else_value))
        return z3.If(valid, chosen, self.unknown(sub))

    def _python(self, sub: s.Sub) -> z3.SeqRef:
        assert isinstance(sub, s.PythonExpr)
        from launchverify.smt.python_expression import encode_expression

        term = encode_expression(sub, self)
        return term if term is not None else self.unknown(sub)
