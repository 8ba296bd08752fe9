"""Framed JSON messages over a socket between launchverify and a worker process.

A frame is an 8-byte big-endian length and that many bytes of JSON. The parent reads
without blocking and never more than ``limit`` bytes per message, so a worker that writes
garbage, writes too much or stops mid-frame is a problem on its file, not a hang.
"""

from __future__ import annotations

import json
import os
import select
import struct
import time
from typing import Any

_HEADER = struct.Struct(">Q")
DEFAULT_LIMIT = 64 * 1024 * 1024


class ChannelError(Exception):
    """The other side sent something that is not a message."""


class Closed(ChannelError):
    """The other side closed the channel (or died)."""


class TimedOut(ChannelError):
    """No complete message arrived in time."""


def dumps(message: object) -> bytes:
    """Return one framed message (ASCII JSON: lone surrogates survive the trip)."""
    body = json.dumps(message, separators=(",", ":")).encode("ascii")
    return _HEADER.pack(len(body)) + body


class Channel:
    """One end of a worker's socket, read incrementally."""

    def __init__(self, fd: int, limit: int = DEFAULT_LIMIT) -> None:
        self.fd = fd
        self.limit = limit
        self._buffer = bytearray()
        self.closed = False

    def fileno(self) -> int:
        return self.fd

    def send(self, message: object, deadline: float | None = None) -> None:
        """Write one message, waiting for room until ``deadline`` (monotonic seconds)."""
        data = memoryview(dumps(message))
        while data:
            if deadline is not None:
                _wait(self.fd, deadline, write=True)
            try:
                written = os.write(self.fd, data)
            except BlockingIOError:
                continue
            except OSError as error:
                raise Closed(str(error)) from None
            data = data[written:]

    def receive(self, deadline: float | None = None) -> Any:
        """Return the next message, waiting until ``deadline`` at most."""
        while True:
            message = self.take()
            if message is not None:
                return message[0]
            if deadline is not None:
                _wait(self.fd, deadline)
            self.fill()

    def fill(self) -> None:
        """Read what is available (raises ``Closed`` at the end of the stream)."""
        try:
            chunk = os.read(self.fd, 1 << 20)
        except BlockingIOError:
            return
        except OSError as error:
            raise Closed(str(error)) from None
        if not chunk:
            self.closed = True
            raise Closed("the worker closed its channel")
        self._buffer += chunk
        if len(self._buffer) > self.limit + _HEADER.size:
            raise ChannelError(f"a message larger than {self.limit} bytes")

    def take(self) -> tuple[Any] | None:
        """Return ``(message,)`` when a whole one has arrived, else ``None``."""
        if len(self._buffer) < _HEADER.size:
            return None
        (length,) = _HEADER.unpack_from(self._buffer)
        if length > self.limit:
            raise ChannelError(f"a message announced as {length} bytes")
        end = _HEADER.size + length
        if len(self._buffer) < end:
            return None
        body = bytes(self._buffer[_HEADER.size:end])
        del self._buffer[:end]
        try:
            return (json.loads(body),)
        except (ValueError, RecursionError) as error:
            raise ChannelError(f"a malformed message ({type(error).__name__})") from None

    def close(self) -> None:
        if self.fd >= 0:
            os.close(self.fd)
            self.fd = -1


def _wait(fd: int, deadline: float, *, write: bool = False) -> None:
    remaining = deadline - time.monotonic()
    if remaining <= 0:
        raise TimedOut("no answer in time")
    poller = select.poll()
    poller.register(fd, select.POLLOUT if write else select.POLLIN)
    if not poller.poll(remaining * 1000):
        raise TimedOut("no answer in time")
