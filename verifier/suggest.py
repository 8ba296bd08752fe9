"""Did-you-mean suggestions for names that match nothing.

Both sides may come from a pull request (1,500 declared arguments and 1,500 reads one
letter off each), so no suggestion compares every pair in Python: ``typos`` asks
rapidfuzz's C implementation of the same edit distance for the candidates within reach,
and ``closest`` bounds difflib's ratio by the longest common subsequence (rapidfuzz
again) and computes difflib's own ratio only for the few that could still win. The
answers are those of the plain loops they replace (``tests/test_suggest.py`` compares
them on generated names).
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Iterable
from functools import lru_cache


def did_you_mean(name: str, candidates: Iterable[str]) -> str:
    """Return ``" (did you mean 'x'?)"`` for the closest candidate, or an empty string.

    Examples:
        >>> did_you_mean("use_sim_tme", ["use_sim_time", "robot"])
        " (did you mean 'use_sim_time'?)"
    """
    match = closest(name, candidates)
    return f" (did you mean {match!r}?)" if match else ""


def did_you_mean_any(name: str, candidates: Iterable[str], count: int = 3) -> str:
    """Return ``" (did you mean 'x' or 'y'?)"`` for up to ``count`` close candidates.

    Closeness ignores case (``lv101`` is ``LV101``); the closest comes first.

    Examples:
        >>> did_you_mean_any("duplicate-node-nam", ["duplicate-node-name", "invalid-name"])
        " (did you mean 'duplicate-node-name'?)"
        >>> did_you_mean_any("lv1011", ["LV101", "LV501"])
        " (did you mean 'LV101'?)"
        >>> did_you_mean_any("frobnicate", ["select", "ignore"])
        ''
    """
    by_key = {candidate.lower(): candidate for candidate in sorted(set(candidates))}
    wanted = name.lower()
    matcher = difflib.SequenceMatcher(b=wanted)
    scored = []
    for key in by_key:
        matcher.set_seq1(key)
        if matcher.real_quick_ratio() >= 0.75 and matcher.quick_ratio() >= 0.75 and \
                (ratio := matcher.ratio()) >= 0.75:
            scored.append((-ratio, edit_distance(wanted, key), key))
    found = [by_key[key] for _, _, key in sorted(scored)[:count]]  # ties: fewest edits, A-Z
    if not found:
        return ""
    quoted = [repr(candidate) for candidate in found]
    listed = quoted[0] if len(quoted) == 1 else f"{', '.join(quoted[:-1])} or {quoted[-1]}"
    return f" (did you mean {listed}?)"


def closest(name: str, candidates: Iterable[str], cutoff: float = 0.75) -> str | None:
    """Return the candidate ``did_you_mean`` names, if any (difflib's closest, 0.75 alike).

    What ``difflib.get_close_matches(name, candidates, n=1, cutoff=cutoff)`` returns.

    Examples:
        >>> closest("use_sim_tme", ["use_sim_time", "robot"]), closest("x", ["robot"])
        ('use_sim_time', None)
    """
    pool = candidates if isinstance(candidates, frozenset) else frozenset(candidates)
    return _closest(name, pool, cutoff)


FIRST_BATCH = 8  # ``closest``: the candidates of highest bound tried first (then 4 times more)


@lru_cache(maxsize=4096)
def _closest(name: str, pool: frozenset[str], cutoff: float) -> str | None:
    """``closest`` remembered: every root reaching an include asks it again (and the fix).

    difflib's ratio, 2 * matches / (both lengths), counts matches that form a common
    subsequence, so twice the longest common subsequence over the lengths bounds it
    (rapidfuzz's Indel similarity, in C). Candidates are tried from the highest bound
    down, the best few first, until a bound falls below the best ratio found (ties go to
    the greater name, as in difflib).
    """
    from rapidfuzz import process
    from rapidfuzz.distance import Indel

    choices = tuple(pool)
    matcher = difflib.SequenceMatcher()
    matcher.set_seq2(name)
    best: tuple[float, str] | None = None
    tried: set[str] = set()
    limit = FIRST_BATCH
    while True:
        within = process.extract(name, choices, scorer=Indel.normalized_similarity,
                                 processor=None, score_cutoff=max(cutoff - 1e-6, 0.0),
                                 limit=limit)
        for bound, candidate in sorted(((_ratio_bound(name, c), c) for c, _, _ in within
                                        if c not in tried), reverse=True):
            if bound < cutoff or (best is not None and (bound, candidate) < best):
                break  # no ratio is above its bound
            tried.add(candidate)
            matcher.set_seq1(candidate)
            ratio = matcher.ratio()
            if ratio >= cutoff and (best is None or (ratio, candidate) > best):
                best = (ratio, candidate)
        if len(within) < limit or (best is not None and within[-1][1] + 1e-9 < best[0]):
            return best[1] if best is not None else None  # the rest are bounded lower
        limit *= 4


def _ratio_bound(name: str, candidate: str) -> float:
    """Return difflib's ratio if every character of the longest common subsequence matched."""
    from rapidfuzz.distance import Indel

    length = len(name) + len(candidate)
    if not length:
        return 1.0
    common = (length - Indel.distance(name, candidate)) // 2
    return 2.0 * common / length  # as difflib computes its ratios


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
def _typo_index(candidates: frozenset[str]) -> tuple[tuple[str, ...], dict[str, frozenset[str]]]:
    """Return the candidates in a sequence (for rapidfuzz) and their bigrams, once per pool."""
    return tuple(candidates), {c: _bigrams(c) for c in candidates}


def typo_of(name: str, candidates: Iterable[str]) -> str | None:
    """Return the candidate ``name`` most likely misspells (one or two edits), if any.

    Examples:
        >>> typo_of("nav2_bringupp", ["nav2_bringup", "nav2_common"])
        'nav2_bringup'
    """
    found = typos(name, candidates)
    return found[0] if found else None


def typos(name: str, candidates: Iterable[str]) -> list[str]:
    """Return every candidate ``name`` may misspell (one or two edits), likeliest first.

    A fix that renames ``name`` is safe only when there is exactly one.

    Examples:
        >>> typos("robot_nme", ["robot_name", "robot_ns", "robot_nm", "robot"])
        ['robot_name', 'robot_nm', 'robot_ns']
    """
    pool = candidates if isinstance(candidates, frozenset) else frozenset(candidates)
    return list(_typos(name, pool))


@lru_cache(maxsize=4096)
def _typos(name: str, pool: frozenset[str]) -> tuple[str, ...]:
    """``typos`` remembered: a rule asks for the hint, the severity and the fix in turn."""
    from rapidfuzz import process
    from rapidfuzz.distance import OSA

    if name in pool:
        return ()
    limit = 1 if len(name) <= 6 else 2
    grams = _bigrams(name)
    needed = len(grams) - 2 * limit  # each edit breaks at most two bigrams
    choices, bigrams = _typo_index(pool)
    found: list[tuple[int, str]] = []
    # ``edit_distance`` in C (optimal string alignment), for every candidate at once
    for candidate, distance, _ in process.extract(name, choices, scorer=OSA.distance,
                                                  processor=None, score_cutoff=limit,
                                                  limit=None):
        if abs(len(candidate) - len(name)) > limit or len(grams & bigrams[candidate]) < needed:
            continue
        found.append((int(distance), candidate))
    return tuple(candidate for _, candidate in sorted(found))


def file_name_typos(name: str, names: Iterable[str]) -> list[str]:
    """Return the file names ``name`` may misspell, likeliest first.

    The part before the first dot must be one or two edits away with the same extensions
    (or the extensions so, with the same stem); stems under three characters match
    nothing (``a.launch.py`` is not a typo of ``b.launch.py``).

    Examples:
        >>> file_name_typos("param.yaml", ["params.yaml", "param.yml", "params.xml", "x.yaml"])
        ['params.yaml']
        >>> file_name_typos("params.yml", ["params.yaml", "params.xml"])
        ['params.xml', 'params.yaml']
    """
    stem, _, suffix = name.partition(".")
    if len(stem) < 3:
        return []
    same_suffix: dict[str, str] = {}
    same_stem: dict[str, str] = {}
    for candidate in names:
        other_stem, _, other_suffix = candidate.partition(".")
        if other_suffix == suffix:
            same_suffix[other_stem] = candidate
        elif other_stem == stem and other_suffix:
            same_stem[other_suffix] = candidate
    found = [same_suffix[s] for s in typos(stem, same_suffix)]
    if found or not suffix:
        return found
    return [same_stem[s] for s in typos(suffix, same_stem)]


SUGGESTION_THRESHOLD = 0.75  # below this, a suggestion would more likely mislead than help


def _words(name: str) -> tuple[str, ...]:
    return tuple(word for word in re.split(r"[_\-]+", name.lower()) if word)


def _is_abbreviation(short: str, long: str) -> bool:
    """Return whether ``short`` keeps the first letter and, in order, letters of ``long``."""
    if short[0] != long[0]:
        return False
    letters = iter(long)
    return all(letter in letters for letter in short)


def _one_slip_apart(first: str, second: str) -> bool:
    """Return whether one edit turns one word into the other (cheap test first)."""
    if first[0] != second[0] and first[-1] != second[-1]:
        return False  # a single edit leaves the first or the last letter in place
    return edit_distance(first, second, 1) <= 1


def word_similarity(word: str, other: str) -> float:
    """Return how alike two words of a package name are: 1 when equal, 0 when unrelated.

    A shortened word (``sim`` for ``simulator``, ``nav2`` for ``navigation2``) counts for
    more the more of the long word it keeps; a one-letter slip counts for almost a match.
    Words under three letters only match exactly: ``gz`` is too short to abbreviate safely.

    Examples:
        >>> word_similarity("description", "descriptions") > word_similarity("sim", "simulator")
        True
        >>> word_similarity("sim", "simulator") > word_similarity("nav2", "navigation2") > 0
        True
        >>> word_similarity("driver", "description")
        0.0
    """
    if word == other:
        return 1.0
    short, long = sorted((word, other), key=len)
    if len(short) < 3:
        return 0.0
    kept = len(short) / len(long)
    scores = [0.0]
    if len(short) >= 4 and _one_slip_apart(short, long):
        scores.append(0.9)
    if long.startswith(short):
        scores.append(0.6 + 0.4 * kept)
    elif _is_abbreviation(short, long):
        scores.append(0.5 + 0.4 * kept)
    return max(scores)


def name_similarity(name: str, other: str) -> float:
    """Return how alike two package names are, from 0 to 1, word by word (split on ``_``).

    The words of both names are aligned in order, so a name that is the start or the end
    of the other (``my_robot`` in ``my_robot_description``) shares all its words; the score
    is twice the matched weight over the number of words of both names (Dice).

    Examples:
        >>> round(name_similarity("ros_gz_sim", "ros_gz_simulator"), 2)
        0.91
        >>> round(name_similarity("nav2_bringup", "navigation2_bringup"), 2)
        0.82
        >>> round(name_similarity("robot_description", "my_robot_description"), 2)
        0.8
        >>> round(name_similarity("my_robot_driver", "my_robot_description"), 2)
        0.67
    """
    return _aligned_words(_words(name), _words(other))


def _aligned_words(first: tuple[str, ...], second: tuple[str, ...]) -> float:
    """Return the Dice score of the best in-order pairing of two names' words."""
    if not first or not second:
        return 0.0
    previous = [0.0] * (len(second) + 1)
    for word in first:
        current = [0.0]
        for j, candidate in enumerate(second, 1):
            paired = previous[j - 1] + word_similarity(word, candidate)
            current.append(max(previous[j], current[j - 1], paired))
        previous = current
    return 2 * previous[-1] / (len(first) + len(second))


@lru_cache(maxsize=8)
def _word_index(candidates: frozenset[str]) -> tuple[tuple[str, tuple[str, ...]], ...]:
    return tuple((c, _words(c)) for c in sorted(candidates))


def _could_reach_threshold(first: int, second: int) -> bool:
    """Return whether names of these word counts can score enough, every word matched."""
    return 2 * min(first, second) / (first + second) >= SUGGESTION_THRESHOLD


def closest_package(name: str, candidates: Iterable[str]) -> str | None:
    """Return the one candidate clearly most like ``name``, or ``None``.

    ``None`` also when nothing reaches ``SUGGESTION_THRESHOLD`` or when two candidates are
    equally close (``my_robot`` with ``my_robot_bringup`` and ``my_robot_description``):
    a guess between them would be a coin toss.

    Examples:
        >>> workspace = ["my_robot_descriptions", "ros_gz_simulator", "navigation2_bringup"]
        >>> [closest_package(n, workspace) for n in ("nav2_bringup", "ros_gz_sim")]
        ['navigation2_bringup', 'ros_gz_simulator']
        >>> closest_package("my_robot_description", workspace)
        'my_robot_descriptions'
        >>> closest_package("acme_private_driver", workspace) is None
        True
    """
    pool = candidates if isinstance(candidates, frozenset) else frozenset(candidates)
    words = _words(name)
    scored = sorted(((_aligned_words(words, candidate_words), candidate)
                     for candidate, candidate_words in _word_index(pool)
                     if candidate != name
                     and _could_reach_threshold(len(words), len(candidate_words))),
                    reverse=True)
    if not scored or scored[0][0] < SUGGESTION_THRESHOLD:
        return None
    if len(scored) > 1 and scored[1][0] == scored[0][0]:
        return None
    return scored[0][1]


def numbered_alike(first: str, second: str) -> bool:
    """Return whether two names differ only in their digits (a numbered family).

    ``input/rois8`` next to ``input/rois7`` is one more of a family, not a typo.

    Examples:
        >>> numbered_alike("input/rois8", "input/rois7"), numbered_alike("amlc", "amcl")
        (True, False)
    """
    return re.sub(r"\d+", "", first) == re.sub(r"\d+", "", second)


def sole_typo(name: str, candidates: Iterable[str]) -> str | None:
    """Return the one candidate ``name`` misspells, when there is exactly one.

    What makes a finding with a did-you-mean an error rather than a warning: a single
    close name (one or two edits, not only digits apart) is almost always what was meant.

    Examples:
        >>> sole_typo("use_sim_tme", ["use_sim_time", "robot"])
        'use_sim_time'
        >>> sole_typo("robot3", ["robot"]) is None
        True
    """
    close = typos(name, candidates)
    if len(close) != 1 or numbered_alike(name, close[0]):
        return None
    return close[0]



def sole_spelling(name: str, candidates: Iterable[str]) -> str | None:
    """Return the one candidate ``name`` writes another way: a typo or shortened words.

    ``sole_typo``'s candidate, else the only candidate with the same words where each
    differs at most by an abbreviation (``max_vel_x`` for ``max_velocity_x``). What makes
    a parameter name an error rather than a warning.

    Examples:
        >>> sole_spelling("max_vel_x", ["max_velocity_x", "max_velocity_y"])
        'max_velocity_x'
        >>> sole_spelling("max_vel", ["max_velocity", "max_vertical"]) is None
        True
    """
    pool = candidates if isinstance(candidates, frozenset) else frozenset(candidates)
    typo = sole_typo(name, pool)
    if typo is not None:
        return typo
    found = _abbreviations(name, _word_tree(pool))
    return found[0] if len(found) == 1 else None


class _WordTree:
    """Names by their words, one level per word (``sole_spelling``'s candidates)."""

    __slots__ = ("by_first", "children", "names")

    def __init__(self) -> None:
        self.children: dict[str, _WordTree] = {}
        # the children's words by first letter and length: a shortened word keeps its
        # first letter, and one of the same length is the same word
        self.by_first: dict[str, dict[int, list[str]]] = {}
        self.names: list[str] = []  # the names whose words end here


@lru_cache(maxsize=8)
def _word_tree(candidates: frozenset[str]) -> _WordTree:
    root = _WordTree()
    for candidate in candidates:
        node = root
        for word in _words(candidate):
            child = node.children.get(word)
            if child is None:
                child = node.children[word] = _WordTree()
                node.by_first.setdefault(word[0], {}).setdefault(len(word), []).append(word)
            node = child
        node.names.append(candidate)
    return root


def _abbreviations(name: str, tree: _WordTree) -> list[str]:
    """Return the names with the words of ``name``, some shortened either way, not all equal.

    Word by word down the tree: the same word, or one of another length with the same
    first letter that shortens it or that it shortens.
    """
    words = _words(name)
    found: list[str] = []
    pending = [(tree, 0, True)]  # (node, words matched, all of them equal)
    while pending:
        node, depth, equal = pending.pop()
        if depth == len(words):
            if not equal:
                found.extend(c for c in node.names if c != name)
            continue
        word = words[depth]
        if (child := node.children.get(word)) is not None:
            pending.append((child, depth + 1, equal))
        for length, others in node.by_first.get(word[0], {}).items():
            if length == len(word):
                continue
            for other in others:
                short, long = (word, other) if len(word) < length else (other, word)
                if _is_abbreviation(short, long):
                    pending.append((node.children[other], depth + 1, False))
    return found
