"""Did-you-mean suggestions: the fast versions answer what the plain loops answered.

``typos``, ``closest`` and ``sole_spelling`` no longer compare every pair in Python
(issue 42: 1,500 declared names and 1,500 reads one letter off each took minutes). The
loops they replaced are kept here as the reference, and hypothesis compares the two on
names from small alphabets (so that many are near each other), with separators, case,
and characters outside ASCII.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from launchverify.suggest import (
    _bigrams,
    _is_abbreviation,
    _words,
    closest,
    did_you_mean,
    edit_distance,
    file_name_typos,
    sole_spelling,
    sole_typo,
    typos,
)

# ---- the reference: the loops before issue 42


def old_typos(name: str, candidates: Iterable[str]) -> list[str]:
    pool = frozenset(candidates)
    if name in pool:
        return []
    limit = 1 if len(name) <= 6 else 2
    grams = _bigrams(name)
    needed = len(grams) - 2 * limit
    found: list[tuple[int, str]] = []
    for candidate in sorted(pool):
        if abs(len(candidate) - len(name)) > limit or len(grams & _bigrams(candidate)) < needed:
            continue
        distance = edit_distance(name, candidate, limit)
        if distance <= limit:
            found.append((distance, candidate))
    return [candidate for _, candidate in sorted(found)]


def old_closest(name: str, candidates: Iterable[str], cutoff: float = 0.75) -> str | None:
    matches = difflib.get_close_matches(name, sorted(set(candidates)), n=1, cutoff=cutoff)
    return matches[0] if matches else None


def old_sole_spelling(name: str, candidates: Iterable[str]) -> str | None:
    pool = sorted(set(candidates))
    close = old_typos(name, pool)
    typo = close[0] if len(close) == 1 and not _numbered(name, close[0]) else None
    if typo is not None:
        return typo
    words = _words(name)
    found = [c for c in pool if c != name and _abbreviates(words, _words(c))]
    return found[0] if len(found) == 1 else None


def _numbered(first: str, second: str) -> bool:
    import re

    return re.sub(r"\d+", "", first) == re.sub(r"\d+", "", second)


def _abbreviates(words: tuple[str, ...], others: tuple[str, ...]) -> bool:
    if len(words) != len(others) or words == others:
        return False
    return all(a == b or _is_abbreviation(a, b) or _is_abbreviation(b, a)
               for a, b in zip(words, others, strict=True))


# ---- generated names

letters = st.sampled_from("aabbcdeé_-1Aü\udcff")
names = st.text(letters, max_size=9)
near = st.text(st.sampled_from("ab_"), min_size=0, max_size=7)  # many alike
pools = st.lists(names | near, max_size=25)


@settings(max_examples=600, deadline=None)
@given(names | near, pools)
def test_typos_are_those_of_the_loop(name: str, pool: list[str]) -> None:
    assert typos(name, pool) == old_typos(name, pool)
    assert typos(name, frozenset(pool)) == old_typos(name, pool)
    assert sole_typo(name, pool) == (
        found[0] if len(found := old_typos(name, pool)) == 1
        and not _numbered(name, found[0]) else None)


@st.composite
def edited(draw: st.DrawFn, name: str) -> str:
    """Return ``name`` after one or two edits: an insertion, deletion, substitution or
    swap of neighbours, anywhere (a swap in the middle changes three bigrams)."""
    text = list(name)
    for _ in range(draw(st.integers(1, 2))):
        where = draw(st.integers(0, len(text)))
        kind = draw(st.sampled_from(["insert", "delete", "substitute", "swap"]))
        if kind == "insert":
            text.insert(where, draw(letters))
        elif where < len(text) and kind == "delete":
            del text[where]
        elif where < len(text) and kind == "substitute":
            text[where] = draw(letters)
        elif where + 1 < len(text):
            text[where], text[where + 1] = text[where + 1], text[where]
    return "".join(text)


@st.composite
def near_misses(draw: st.DrawFn) -> tuple[str, list[str]]:
    """A name and a pool of names one or two edits from it, and others."""
    name = draw(st.text(st.sampled_from("abcdefghij_"), min_size=0, max_size=12))
    pool = draw(st.lists(edited(name), max_size=20)) + draw(pools)
    return name, pool


@settings(max_examples=600, deadline=None)
@given(near_misses())
def test_typos_of_edited_names_are_those_of_the_loop(case: tuple[str, list[str]]) -> None:
    name, pool = case
    assert typos(name, pool) == old_typos(name, pool)


def test_a_swap_and_a_slip_break_more_bigrams_than_two_edits_may() -> None:
    """The bigram filter is part of the answer: a swap in the middle breaks three."""
    assert old_typos("abcdefgh", ["abdcexgh"]) == typos("abcdefgh", ["abdcexgh"]) == []


@settings(max_examples=600, deadline=None)
@given(names | near, pools, st.sampled_from([0.75, 0.6, 0.0, 1.0]))
def test_closest_is_difflibs(name: str, pool: list[str], cutoff: float) -> None:
    assert closest(name, pool, cutoff) == old_closest(name, pool, cutoff)


@settings(max_examples=400, deadline=None)
@given(near_misses(), st.sampled_from([0.75, 0.6, 0.0]))
def test_closest_of_edited_names_is_difflibs(case: tuple[str, list[str]], cutoff: float
                                            ) -> None:
    """With one candidate tried first, then four, sixteen...: every batch is needed."""
    from launchverify import suggest

    name, pool = case
    first, suggest.FIRST_BATCH = suggest.FIRST_BATCH, 1
    try:
        suggest._closest.cache_clear()
        assert closest(name, pool, cutoff) == old_closest(name, pool, cutoff)
    finally:
        suggest.FIRST_BATCH = first
        suggest._closest.cache_clear()


@settings(max_examples=300, deadline=None)
@given(st.lists(st.sampled_from(["max", "vel", "velocity", "vertical", "x", "y", "acc",
                                 "accel", "v", "ma"]), min_size=1, max_size=3).map("_".join),
       st.lists(st.lists(st.sampled_from(["max", "maximum", "velocity", "vel", "x", "y",
                                          "accel", "acceleration", "vert", "vertical"]),
                         min_size=1, max_size=3).map("_".join), max_size=12))
def test_sole_spelling_is_that_of_the_loop(name: str, pool: list[str]) -> None:
    assert sole_spelling(name, pool) == old_sole_spelling(name, pool)


@settings(max_examples=300, deadline=None)
@given(names | near, pools)
def test_sole_spelling_on_any_names(name: str, pool: list[str]) -> None:
    assert sole_spelling(name, pool) == old_sole_spelling(name, pool)


def test_long_names_and_empty_pools() -> None:
    long = "a" * 300 + "b"
    pool = ["a" * 300 + "c", "a" * 299, "", "b" * 301]
    assert typos(long, pool) == old_typos(long, pool)
    assert closest(long, pool) == old_closest(long, pool)  # difflib's autojunk over 200
    assert typos("x", []) == [] and closest("x", []) is None and sole_spelling("x", []) is None
    assert closest("", [""]) == old_closest("", [""])


# ---- 1,500 x 1,500 (issue 42)

DECLARED = [f"argument_{i:04d}" for i in range(1500)]
READS = [f"argumenx_{i:04d}" for i in range(1500)]  # each one letter off one declared


def test_fifteen_hundred_near_misses_compare_few_pairs_in_python(
        monkeypatch: pytest.MonkeyPatch) -> None:
    """What a rule asks for 1,500 names one letter off 1,500 others compares a bounded
    number of pairs in Python per name, whatever the pool: LV201's typos per read, LV204's
    hint, severity and fix per argument, a parameter's hint and spelling. (The old loops
    compared every pair: 2.25 million, minutes of CPU; the time is in bench/README.md.)"""
    from launchverify import suggest

    compared = {"pairs": 0}

    class Matcher(suggest.difflib.SequenceMatcher):  # type: ignore[misc, name-defined]
        def ratio(self) -> float:
            compared["pairs"] += 1
            return float(super().ratio())

    def counted(function):  # type: ignore[no-untyped-def]
        def wrapper(*arguments):  # type: ignore[no-untyped-def]
            compared["pairs"] += 1
            return function(*arguments)
        return wrapper

    monkeypatch.setattr(suggest.difflib, "SequenceMatcher", Matcher)
    for name in ("edit_distance", "_is_abbreviation", "word_similarity", "name_similarity"):
        monkeypatch.setattr(suggest, name, counted(getattr(suggest, name)))
    declared = frozenset(DECLARED)  # as the rules pass them
    found: dict[str, list[object]] = {"lv201": [], "lv204": [], "parameter": []}

    def lv201() -> None:
        found["lv201"] = [typos(read, declared) for read in READS]

    def lv204() -> None:
        found["lv204"] = [(did_you_mean(read, declared), sole_typo(read, declared),
                           closest(read, declared), sole_typo(read, declared))
                          for read in READS]

    def parameter() -> None:
        found["parameter"] = [(did_you_mean(read, declared), sole_spelling(read, declared))
                              for read in READS]

    for work in (lv201, lv204, parameter):
        _forget()  # what each rule meets: nothing asked before
        compared["pairs"] = 0
        work()
        assert compared["pairs"] <= 20 * len(READS), (work.__name__, compared["pairs"])
    assert found["lv201"][7][0] == "argument_0007"
    assert found["lv204"][3] == (" (did you mean 'argument_0003'?)", None, "argument_0003",
                                 None)  # many are two edits away: not the only typo
    assert found["parameter"][3] == (" (did you mean 'argument_0003'?)", None)


def _forget() -> None:
    """Empty the suggestions' memories, as a fresh process has them."""
    from launchverify import suggest

    for cached in (suggest._typos, suggest._closest, suggest._typo_index, suggest._word_tree):
        cached.cache_clear()


def test_file_names_use_the_same_typos() -> None:
    files = [f"params_{i:04d}.yaml" for i in range(1500)]
    assert file_name_typos("params_0007.yml", files) == ["params_0007.yaml"]
    assert file_name_typos("parans_0007.yaml", files)[0] == "params_0007.yaml"
