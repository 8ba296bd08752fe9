"""When checks run: one at a time, off the protocol's thread, a change's after a pause.

Typing sends a change per key; checking each would queue work the next key makes stale.
A document is checked once no change came for ``DEBOUNCE`` seconds (at once when opened
or saved); documents due together are checked together, and changes that come in during
a check are checked after it. The check runs in a thread of its own so that the server
keeps answering (hover, code actions) meanwhile; results come back to the event loop,
the only place that writes to the client.
"""

from __future__ import annotations

import asyncio
import contextlib
import threading
from collections.abc import Awaitable, Callable
from pathlib import Path
from typing import TypeVar

DEBOUNCE = 0.3  # seconds without a change before a changed document is checked

T = TypeVar("T")


class Scheduler:
    """Runs ``check`` on the documents due, one check at a time."""

    def __init__(self, check: Callable[[frozenset[Path]], Awaitable[None]]) -> None:
        self._check = check
        self._timers: dict[Path, asyncio.TimerHandle] = {}
        self._due: set[Path] = set()
        self._running: asyncio.Task[None] | None = None

    def request(self, path: Path, delay: float = 0.0) -> None:
        """Check a document after ``delay`` seconds, unless asked again before."""
        timer = self._timers.pop(path, None)
        if timer is not None:
            timer.cancel()
        loop = asyncio.get_running_loop()
        self._timers[path] = loop.call_later(delay, self._ready, path)

    def cancel(self) -> None:
        """Forget what is not yet checked (the server is shutting down)."""
        for timer in self._timers.values():
            timer.cancel()
        self._timers.clear()
        self._due.clear()

    def _ready(self, path: Path) -> None:
        self._timers.pop(path, None)
        self._due.add(path)
        if self._running is None or self._running.done():
            self._running = asyncio.ensure_future(self._drain())

    async def _drain(self) -> None:
        while self._due:
            paths = frozenset(self._due)
            self._due.clear()
            await self._check(paths)


def in_thread(function: Callable[[], T]) -> asyncio.Future[T]:
    """Run ``function`` in a daemon thread; its result arrives on the running event loop.

    A daemon thread, not an executor's: a check still running when the client says
    ``exit`` must not hold the process up.
    """
    loop = asyncio.get_running_loop()
    future: asyncio.Future[T] = loop.create_future()

    def settle(result: T | None, error: BaseException | None) -> None:
        if future.done():
            return
        if error is not None:
            future.set_exception(error)
        else:
            future.set_result(result)  # type: ignore[arg-type]

    def work() -> None:
        try:
            result = function()
        except BaseException as error:  # handed to the awaiting coroutine
            outcome: tuple[T | None, BaseException | None] = (None, error)
        else:
            outcome = (result, None)
        with contextlib.suppress(RuntimeError):  # the loop closed: nobody waits
            loop.call_soon_threadsafe(settle, *outcome)

    threading.Thread(target=work, name="launchverify-check", daemon=True).start()
    return future
