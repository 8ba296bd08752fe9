"""Did-you-mean suggestions for names that match nothing."""

from __future__ import annotations

import difflib
from collections.abc import Iterable
from functools import lru_cache


def did_you_mean(name: str, candidates: Iterable[str]) -> str:
    """Return ``" (did you mean 'x'?)"`` for the closest candidate, or an empty string.

    Examples:
        >>> did_you_mean("use_sim_tme", ["use_sim_time", "robot"])
        " (did you mean 'use_sim_time'?)"
    """
    matches = difflib.get_close_matches(name, sorted(set(candidates)), n=1, cutoff=0.75)
    return f" (did you mean {matches[0]!r}?)" if matches else ""


def edit_distance(first: str, second: str, limit: int = 3) -> int:
    """Return the Damerau-Levenshtein distance, or ``limit + 1`` once it exceeds ``limit``.

    Examples:
        >>> edit_distance("demo_node_cpp", "demo_nodes_cpp")
        1
    """
    if abs(len(first) - len(second)) > limit:
        return limit + 1
    previous2: list[int] = []
    previous = list(range(len(second) + 1))
    for i, a in enumerate(first, 1):
        current = [i] + [0] * len(second)
        for j, b in enumerate(second, 1):
            cost = 0 if a == b else 1
            current[j] = min(previous[j] + 1, current[j - 1] + 1, previous[j - 1] + cost)
            if i > 1 and j > 1 and a == second[j - 2] and first[i - 2] == b:
                current[j] = min(current[j], previous2[j - 2] + 1)
        if min(current) > limit:
            return limit + 1
        previous2, previous = previous, current
    return previous[-1]


def _bigrams(text: str) -> frozenset[str]:
    return frozenset(text[i : i + 2] for i in range(len(text) - 1))


@lru_cache(maxsize=8)
def _bigram_index(candidates: frozenset[str]) -> tuple[tuple[str, frozenset[str]], ...]:
    return tuple((c, _bigrams(c)) for c in sorted(candidates))


def typo_of(name: str, candidates: Iterable[str]) -> str | None:
    """Return the candidate ``name`` most likely misspells (one or two edits), if any.

    Examples:
        >>> typo_of("nav2_bringupp", ["nav2_bringup", "nav2_common"])
        'nav2_bringup'
    """
    pool = candidates if isinstance(candidates, frozenset) else frozenset(candidates)
    if name in pool:
        return None
    limit = 1 if len(name) <= 6 else 2
    grams = _bigrams(name)
    needed = len(grams) - 2 * limit  # each edit breaks at most two bigrams
    best: tuple[int, str] | None = None
    for candidate, candidate_grams in _bigram_index(pool):
        if abs(len(candidate) - len(name)) > limit or len(grams & candidate_grams) < needed:
            continue
        distance = edit_distance(name, candidate, limit)
        if distance <= limit and (best is None or (distance, candidate) < best):
            best = (distance, candidate)
    return None if best is None else best[1]
