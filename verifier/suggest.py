"""Did-you-mean suggestions for names that match nothing."""

from __future__ import annotations

import difflib
from collections.abc import Iterable


def did_you_mean(name: str, candidates: Iterable[str]) -> str:
    """Return ``" (did you mean 'x'?)"`` for the closest candidate, or an empty string.

    Examples:
        >>> did_you_mean("use_sim_tme", ["use_sim_time", "robot"])
        " (did you mean 'use_sim_time'?)"
    """
    matches = difflib.get_close_matches(name, sorted(set(candidates)), n=1, cutoff=0.75)
    return f" (did you mean {matches[0]!r}?)" if matches else ""
