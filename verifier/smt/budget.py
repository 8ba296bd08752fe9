"""How much solver time the questions about one root may take (issue 42).

z3's limit is per question (``solver.TIMEOUT_MS``), and the concrete search has none of
its own: a file of a dozen pigeonhole conditions asks many questions of seconds each.
Each root's reasoner has a budget of CPU seconds for all its questions, searches and z3
alike. Once it is spent, every question left is unanswered: "cannot tell", which no
finding rests on (each question maps it to the answer that claims nothing), and the root
gets an LV003 info saying it was not fully judged (``smt.budget_notes``).

CPU time of the thread, not wall time: a busy machine must not cut real files short.
"""

from __future__ import annotations

import time
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

# CPU seconds of questions per root (and per process: with ``-j``, a root's rules may be
# shared out, each process with its own reasoner). The most a real root takes is about
# 2.6 s (autoware.universe's reaction_analyzer checked alone, 212 z3 questions; next come
# detection.launch.xml 1.2 s and pose_twist_estimator 0.6 s, of 895 roots of the
# 41-repository corpus): more than twice that, and a hostile root's check still ends
# within 10 s, less than a Python launch file may take to evaluate.
SOLVER_SECONDS = 6.0


class CannotTell(Exception):
    """A question has no answer: z3 gave up (a timeout, an undecided theory)."""


class BudgetSpent(CannotTell):
    """The root's solver budget is used up: no more questions are answered."""


class Account:
    """The seconds one root's questions have taken, in this process."""

    def __init__(self, spent: float = 0.0) -> None:
        self._spent = spent

    def add(self, seconds: float) -> None:
        """Count the seconds of a question that ended."""
        self._spent += seconds

    def spent(self) -> float:
        """Return the seconds counted so far."""
        return self._spent


class SharedAccount(Account):
    """The seconds one root's questions have taken in every process of a check.

    A root's rules may be shared out between forked processes (``parallel/fanout.py``),
    each with a reasoner of its own: they count in one slot of memory they share, so
    the root's budget is one, whoever asks. Without a lock (a process killed holding it
    would stop the others): two questions of one root ending at the same instant in two
    processes may count as one.
    """

    def __init__(self, slots: Any, index: int) -> None:
        super().__init__()
        self._slots = slots
        self._index = index

    def add(self, seconds: float) -> None:
        self._slots[self._index] += seconds

    def spent(self) -> float:
        return float(self._slots[self._index])


def shared_accounts(count: int, spent: list[float]) -> list[Account]:
    """Return accounts that processes forked from now on share (``spent``: so far).

    Local ones where the system has no shared memory (a container without /dev/shm).
    """
    import multiprocessing

    try:
        slots = multiprocessing.get_context("fork").RawArray("d", spent[:count])
    except OSError:
        return [Account(seconds) for seconds in spent]
    return [SharedAccount(slots, index) for index in range(count)]


class SolverBudget:
    """The CPU seconds left to one root's questions (a question in progress included)."""

    def __init__(self, seconds: float = SOLVER_SECONDS, account: Account | None = None) -> None:
        self.seconds = seconds
        self.account = account or Account()
        self.ran_out = False  # a question went unanswered for want of time (here)
        self._started: float | None = None  # when the question in progress began

    @property
    def left(self) -> float:
        """Return the seconds left, the question in progress not counted."""
        return self.seconds - self.account.spent()

    @contextmanager
    def question(self) -> Iterator[None]:
        """Count the time of a question (one at a time; a nested one is the outer's)."""
        if self._started is not None:
            yield
            return
        self._started = time.thread_time()
        try:
            yield
        finally:
            self.account.add(time.thread_time() - self._started)
            self._started = None

    def remaining(self) -> float:
        """Return the seconds left, the question in progress counted."""
        if self._started is None:
            return self.left
        return self.left - (time.thread_time() - self._started)

    def spent(self) -> bool:
        """Return whether nothing is left (and remember that a question went unanswered)."""
        if self.remaining() > 0:
            return False
        self.ran_out = True
        return True

    def require(self) -> None:
        """Raise ``BudgetSpent`` when nothing is left."""
        if self.spent():
            raise BudgetSpent
