"""One computation in a forked child while the check goes on.

The includers scan reads every launch file of the workspace (0.4 s on the 1,900 files of
the real-world corpus), and the check needs its answer only once evaluation is over:
a child computes it meanwhile, on a core that evaluation leaves idle while it waits for
its Python workers. The answer comes back pickled through a pipe.

Forking needs a POSIX system and no other thread (``can_fork``); otherwise, or when the
child fails, the computation runs in the checking process when its result is asked for.
"""

from __future__ import annotations

import contextlib
import os
import pickle
import signal
import sys
import threading
from collections.abc import Callable
from typing import Generic, TypeVar

T = TypeVar("T")


def can_fork() -> bool:
    """Return whether forking is possible and safe here (POSIX, and no other thread).

    (macOS can fork, but its system libraries are not safe across a fork: not there.)
    """
    return (hasattr(os, "fork") and sys.platform != "darwin"
            and threading.active_count() == 1)


class Background(Generic[T]):
    """``compute()``, started in a forked child now and collected by ``result``."""

    def __init__(self, compute: Callable[[], T]) -> None:
        self._compute = compute
        self._child: tuple[int, int] | None = None  # (pid, read end of the pipe)
        if can_fork():
            self._child = _start(compute)

    def result(self) -> T:
        """Return the child's answer, or compute it here when the child gave none."""
        if self._child is None:
            return self._compute()
        pid, source = self._child
        self._child = None
        with os.fdopen(source, "rb") as pipe:
            data = pipe.read()
        _, status = os.waitpid(pid, 0)
        if os.WIFEXITED(status) and os.WEXITSTATUS(status) == 0:
            try:
                found: T = pickle.loads(data)  # our own child wrote it
            except Exception:  # a torn answer: compute it here
                return self._compute()
            return found
        return self._compute()

    def close(self) -> None:
        """End the child if its answer was never asked for (the check failed)."""
        if self._child is None:
            return
        pid, source = self._child
        self._child = None
        os.close(source)
        with contextlib.suppress(ProcessLookupError):
            os.kill(pid, signal.SIGKILL)
        os.waitpid(pid, 0)

    def __enter__(self) -> Background[T]:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()


def _start(compute: Callable[[], object]) -> tuple[int, int] | None:
    """Fork a child that writes ``compute()``'s pickle to a pipe and exits."""
    source, sink = os.pipe()
    try:
        pid = os.fork()
    except OSError:
        os.close(source)
        os.close(sink)
        return None
    if pid == 0:  # the child: never returns
        code = 1
        try:
            os.close(source)
            data = pickle.dumps(compute(), protocol=pickle.HIGHEST_PROTOCOL)
            with os.fdopen(sink, "wb") as pipe:
                pipe.write(data)
            code = 0
        finally:
            os._exit(code)
    os.close(sink)
    return pid, source
