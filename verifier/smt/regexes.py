"""The value sets of launch's truth rules, as z3 regular expressions and sets.

Kept apart from the encoder so that each rule of ``models.booleans`` has one z3 spelling:
the condition rule (strip, lower-case, ``true``/``1``/``false``/``0``), the typed rule of
boolean substitutions (YAML booleans plus ``1``/``0``), ``EqualsSubstitution``'s boolean
and number comparison, and nav2's ``LaunchConfigAsBool``.
"""

from __future__ import annotations

from functools import cache

import z3

_WHITESPACE = " \t\n\r\x0b\x0c"
# Characters a string ``float()`` accepts can be made of (digits, sign, point, exponent,
# underscores, surrounding blanks, inf/infinity/nan).
_NUMBER_CHARS = " +-._eEiInNfFtTyYaA"

TYPED_TRUE = ("1", "yes", "Yes", "YES", "true", "True", "TRUE", "on", "On", "ON")
TYPED_FALSE = ("0", "no", "No", "NO", "false", "False", "FALSE", "off", "Off", "OFF")


def _chars(chars: str) -> z3.ReRef:
    return z3.Union(*[z3.Re(c) for c in chars]) if len(chars) > 1 else z3.Re(chars)


def caseless(word: str) -> z3.ReRef:
    """Return the regular expression of ``word`` in any case."""
    pieces = [_chars(c.lower() + c.upper()) if c.isalpha() else z3.Re(c) for c in word]
    return z3.Concat(*pieces) if len(pieces) > 1 else pieces[0]


@cache
def _condition(true: bool) -> z3.ReRef:
    blanks = z3.Star(_chars(_WHITESPACE))
    word = z3.Union(caseless("true" if true else "false"), z3.Re("1" if true else "0"))
    return z3.Concat(blanks, word, blanks)


def condition_true(value: z3.SeqRef) -> z3.BoolRef:
    """The condition rule says true (``if`` holds)."""
    return z3.InRe(value, _condition(True))


def condition_false(value: z3.SeqRef) -> z3.BoolRef:
    """The condition rule says false (``unless`` holds)."""
    return z3.InRe(value, _condition(False))


def one_of(value: z3.SeqRef, words: tuple[str, ...] | list[str]) -> z3.BoolRef:
    """The value is one of these exact strings."""
    return z3.Or(*[value == z3.StringVal(w) for w in words]) if words else z3.BoolVal(False)


@cache
def _boolish() -> z3.ReRef:
    return z3.Union(caseless("true"), caseless("false"), z3.Re("1"), z3.Re("0"))


@cache
def _boolish_true() -> z3.ReRef:
    return z3.Union(caseless("true"), z3.Re("1"))


def boolish(value: z3.SeqRef) -> z3.BoolRef:
    """``EqualsSubstitution`` compares the value as a boolean (no strip)."""
    return z3.InRe(value, _boolish())


def boolish_true(value: z3.SeqRef) -> z3.BoolRef:
    """As a boolean in ``EqualsSubstitution``, the value is true."""
    return z3.InRe(value, _boolish_true())


@cache
def _number_chars() -> z3.ReRef:
    return z3.Plus(z3.Union(z3.Range("0", "9"), _chars(_NUMBER_CHARS)))


def maybe_number(value: z3.SeqRef) -> z3.BoolRef:
    """The value might parse as a float (false means it surely does not)."""
    return z3.InRe(value, _number_chars())


@cache
def _as_bool_true() -> z3.ReRef:
    blanks = z3.Star(_chars(_WHITESPACE))
    words = z3.Union(caseless("true"), z3.Re("1"), caseless("yes"), caseless("on"))
    return z3.Concat(blanks, words, blanks)


def as_bool_true(value: z3.SeqRef) -> z3.BoolRef:
    """nav2's ``LaunchConfigAsBool`` gives ``True``."""
    return z3.InRe(value, _as_bool_true())


@cache
def digits() -> z3.ReRef:
    """One or more decimal digits."""
    return z3.Plus(z3.Range("0", "9"))
