"""A guard process that kills the run's process groups if launchverify itself is killed.

Processes start in their own sessions, so nothing else stops them when launchverify
dies without cleaning up (SIGKILL, a crash). ``PR_SET_PDEATHSIG`` would need a
``preexec_fn``, which makes every start a full ``fork`` (6 ms each here, against under
1 ms); instead one small guard process reads process-group ids from a pipe and, when the
pipe closes without the word ``done``, kills every group still registered.
"""

from __future__ import annotations

import asyncio
import contextlib
import sys

GUARD = """
import os, signal, sys
signal.signal(signal.SIGINT, signal.SIG_IGN)
groups = set()
for line in sys.stdin:
    word = line.strip()
    if word == "done":
        sys.exit(0)
    if word.startswith("-"):
        groups.discard(int(word[1:]))
    elif word:
        groups.add(int(word))
for group in groups:
    try:
        os.killpg(group, signal.SIGKILL)
    except OSError:
        pass
"""


class Guard:
    """The guard of one run."""

    def __init__(self) -> None:
        self.child: asyncio.subprocess.Process | None = None

    async def start(self) -> None:
        """Start the guard (in its own session: a Ctrl-C does not reach it)."""
        self.child = await asyncio.create_subprocess_exec(
            sys.executable, "-c", GUARD, stdin=asyncio.subprocess.PIPE,
            stdout=asyncio.subprocess.DEVNULL, stderr=asyncio.subprocess.DEVNULL,
            start_new_session=True)

    def say(self, word: str) -> None:
        if self.child is not None and self.child.stdin is not None:
            with contextlib.suppress(OSError, RuntimeError):
                self.child.stdin.write(f"{word}\n".encode())

    def add(self, group: int) -> None:
        """Register a process group to kill if launchverify dies."""
        self.say(str(group))

    def remove(self, group: int) -> None:
        """Forget a process group that has ended."""
        self.say(f"-{group}")

    async def close(self) -> None:
        """End the guard after a clean run: it kills nothing."""
        if self.child is None:
            return
        self.say("done")
        with contextlib.suppress(OSError, RuntimeError, ConnectionResetError):
            if self.child.stdin is not None:
                self.child.stdin.close()
            await asyncio.wait_for(self.child.wait(), timeout=5)
