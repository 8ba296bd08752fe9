"""launchverify's side of the workers: Python launch files in, validated IR out.

``IsolatedPython`` stands where the in-process Python frontend stood (``load(path,
sink)``): each Python launch file is evaluated by a worker forked from the zygote (one
that is done may take the next file of its repository, ``reuse``),
up to ``jobs`` at once (``prefetch`` queues files the check will need), and what comes
back is decoded by ``codec`` with every field checked. A worker whose files have
OpaqueFunctions stays until the check ends (or until ``MAX_ALIVE`` others are newer), so
the walk can run them when it reaches them; it may still take other files meanwhile.
Whatever goes wrong in a worker (it dies, exits early, exceeds its time, sends
garbage) becomes a problem on its file, never an exception here.
"""

from __future__ import annotations

import os
import select
import time
from collections import deque
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from launchverify.frontends.python.importer import absent_modules_asked
from launchverify.ir import actions as a
from launchverify.isolation.channel import Channel, ChannelError, Closed
from launchverify.isolation.codec import CodecError, Decoder, Encoder, TooLarge
from launchverify.isolation.confine import WITHOUT_LANDLOCK, Limits, beneath, readable_folders
from launchverify.isolation.worker import Setting
from launchverify.isolation.zygote import Zygote
from launchverify.problems import Problem, ProblemKind, ProblemSink
from launchverify.span import Span
from launchverify.workspace import reading
from launchverify.workspace.packages import PackageIndex
from launchverify.workspace.reading import read_file

GRACE = 2.0  # seconds past the time limit before a worker is killed
MAX_ALIVE = 64  # idle workers kept for their OpaqueFunctions (about 8 MB each)
MAX_READS = 10_000  # files one answer may say it read (more: unknown)
MAX_PATH = 4096  # characters of one of them
_ENTRY_POINTS = (b"def generate_launch_description", b"def generate_test_description")


@dataclass(eq=False)
class _Process:
    """One worker process; the files it took share it."""

    number: int
    channel: Channel
    busy: _Request | None = None  # the request it is answering (one at a time)
    holders: list[_Worker] = field(default_factory=list)  # files whose callbacks it runs

    @property
    def free(self) -> bool:
        """Return whether it may be sent a request (it answers one at a time)."""
        return self.busy is None or self.busy.done

    @property
    def closed(self) -> bool:
        return self.channel.fd < 0


@dataclass(eq=False)
class _Worker:
    """One file's worker as launchverify sees it (its process may serve other files too)."""

    path: Path
    process: _Process
    ended: str | None = None  # why it can no longer answer
    first: int = 0  # its callbacks' numbers in its process start here
    loaded: int = 0  # callbacks its evaluation made (those a fresh worker makes again)
    recycled: bool = False  # its process ended (memory, another file): a fresh one takes over
    spent: float = 0.0  # seconds its file's requests took: the time limit is for all of them
    repository: Path | None = None  # the files it may take after this one (``reuse``)
    reused: bool = False  # it evaluated another file before this one
    # the decoder of its file's answers, kept for the next: they may name records of
    # earlier ones (``codec``); ``None`` once an answer broke off (they no longer match)
    decoder: Decoder | None = None
    collected: list[_Callback] = field(default_factory=list)  # the answer's callbacks

    @property
    def number(self) -> int:
        return self.process.number

    @property
    def channel(self) -> Channel:
        return self.process.channel


@dataclass(eq=False)
class _Request:
    """A message sent to a worker, waiting for its answer."""

    worker: _Worker
    deadline: float
    started: float = 0.0
    reply: dict[str, Any] | None = None
    failure: str | None = None
    load: _Load | None = None  # the evaluation it answers, if it is one

    @property
    def done(self) -> bool:
        return self.reply is not None or self.failure is not None

    @property
    def path(self) -> Path:
        """Return the file the request is about (its evaluation's, or the worker's)."""
        return self.load.path if self.load is not None else self.worker.path


@dataclass(eq=False)
class _Load:
    """A file's evaluation: queued, running or done."""

    path: Path
    request: _Request | None = None
    launch: a.LaunchFile | None = None
    problems: list[Problem] = field(default_factory=list)
    done: bool = False


class IsolatedPython:
    """Evaluates Python launch files in confined worker processes."""

    def __init__(self, index: PackageIndex, workspace: Path, *, jobs: int = 1,
                 limits: Limits | None = None, distro: str | None = None,
                 environment: dict[str, str] | None = None,
                 arguments: dict[str, str] | None = None,
                 readable: tuple[str, ...] | None = None) -> None:
        self.limits = limits or Limits()
        if readable is None:
            readable = readable_folders(index, workspace)
        self.setting = Setting(index, workspace, readable,
                               self.limits, distro, dict(environment or {}),
                               dict(arguments or {}),
                               debug=bool(os.environ.get("LAUNCHVERIFY_DEBUG_WORKERS")),
                               absent_modules=absent_modules_asked(),
                               landlock=not os.environ.get(WITHOUT_LANDLOCK))
        self.jobs = max(1, jobs)
        self.protections: str | None = None  # as the first worker reported them
        self.evaluated = 0  # files evaluated by workers
        self._zygote: Zygote | None = None
        self._loads: dict[Path, _Load] = {}
        self._queue: deque[_Load] = deque()
        self._running: list[_Request] = []
        self._alive: dict[_Process, None] = {}  # kept for OpaqueFunctions, oldest use first
        self._helpers: dict[Path, bool] = {}
        self._idle: dict[Path, list[_Worker]] = {}  # done, and may take a file of their repository
        self._repositories: dict[Path, Path] = {}
        self._queued: dict[Path, int] = {}  # files queued, by repository
        self.reused = 0  # files evaluated by a worker that had evaluated another
        self._read: dict[Path, set[str] | None] = {}  # what each file's answers read

    # ------------------------------------------------------------------ the loader

    def prefetch(self, paths: Iterable[Path]) -> None:
        """Queue files the check will load, so that up to ``jobs`` run at once."""
        for path in paths:
            if path not in self._loads and reading.outside(path) is None:
                load = _Load(path)
                self._loads[path] = load
                self._queue.append(load)
                repository = self._repository(path)
                self._queued[repository] = self._queued.get(repository, 0) + 1
        self._start_queued()

    def load(self, path: Path, sink: ProblemSink) -> a.LaunchFile | None:
        """Evaluate a Python launch file; its problems go to ``sink``."""
        load = self._loads.get(path)
        if load is None:
            load = _Load(path)
            self._loads[path] = load
            self._start(load)  # needed now: it starts whatever else runs
        elif load.request is None and not load.done:  # queued: needed now
            self._queue.remove(load)
            self._dequeued(load)
            self._start(load)
        while not load.done:
            self._pump()
            self._start_queued()
        sink.problems.extend(load.problems)
        return load.launch

    def close(self) -> None:
        """End every worker and the zygote."""
        for idle in self._idle.values():
            for worker in idle:
                worker.channel.close()
        self._idle.clear()
        for process in self._alive:
            process.channel.close()
        for request in self._running:
            request.worker.channel.close()
        self._alive.clear()
        self._running.clear()
        if self._zygote is not None:
            self._zygote.close()
            self._zygote = None

    def __enter__(self) -> IsolatedPython:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # ------------------------------------------------------------------ running requests

    def _start_queued(self) -> None:
        while self._queue and len(self._running) < self.jobs:
            load = self._queue.popleft()
            self._dequeued(load)
            self._start(load)

    def _dequeued(self, load: _Load) -> None:
        repository = self._repository(load.path)
        self._queued[repository] = self._queued.get(repository, 1) - 1

    def _start(self, load: _Load, *, fresh: bool = False) -> None:
        """Start a worker on a file (a failure to start one is a problem on the file).

        A worker done with another file of the same repository takes it when one is idle
        (``reuse``), unless ``fresh``.
        """
        repository = self._repository(load.path)
        idle = self._idle.get(repository) if not fresh else None
        if idle:
            idle[:] = [w for w in idle if not w.process.closed]
        done = next((w for w in reversed(idle or ()) if w.process.free), None)
        if done is not None and idle is not None and self._readable(load.path):
            idle.remove(done)
            worker = _Worker(load.path, done.process, repository=repository, reused=True)
            load.request = self._send(worker, {"op": "load", "path": str(load.path)})
            load.request.load = load
            self._running.append(load.request)
            self.reused += 1
            return
        try:  # a worker prepares to take more files when more of its repository wait
            number, fd = self._spawn(load.path, reuse=self._queued.get(repository, 0) > 0)
        except OSError as error:
            load.done = True
            load.problems.append(Problem(
                ProblemKind.EVALUATION, "the evaluation of this file failed: no process "
                f"could be started for it ({error.strerror or error})", Span.of_file(load.path)))
            return
        worker = _Worker(load.path, _Process(number, Channel(fd)), repository=repository)
        load.request = self._send(worker, None)
        load.request.load = load
        self._running.append(load.request)

    def _repository(self, path: Path) -> Path:
        """Return the files a worker of ``path`` may also evaluate: its repository's.

        The nearest folder with ``.git`` up to the workspace, else the file's package, else
        its folder.
        """
        folder = path.parent
        known = self._repositories.get(folder)
        if known is None:
            known = folder
            owner = self.setting.index.owner(path)
            if owner is not None and owner.source is not None:
                known = owner.source
            for parent in (folder, *folder.parents):
                if (parent / ".git").exists():
                    known = parent
                    break
                if parent == self.setting.workspace:
                    break
            self._repositories[folder] = known
        return known

    def _readable(self, path: Path) -> bool:
        """Return whether every worker may read ``path``'s folder (a first file's may be added)."""
        return beneath(os.path.realpath(path.parent), self.setting.readable)

    def _park(self, worker: _Worker) -> None:
        """Keep a worker that may take another file of its repository (a few at most)."""
        if worker.repository is None:
            self._release(worker.process)
            return
        self._idle.setdefault(worker.repository, []).append(worker)
        while sum(len(idle) for idle in self._idle.values()) > self.jobs:
            oldest = next(key for key, idle in self._idle.items() if idle)
            self._release(self._idle[oldest].pop(0).process)
            if not self._idle[oldest]:
                del self._idle[oldest]

    def _release(self, process: _Process) -> None:
        """Let a process go that takes no more files; it stays for its files' callbacks."""
        if not process.holders:
            process.channel.close()  # it exits; the zygote removes its folder

    def _end(self, process: _Process) -> None:
        """Close a process; the files whose callbacks it ran get a fresh one when asked."""
        process.channel.close()
        self._alive.pop(process, None)
        for holder in process.holders:
            holder.recycled = holder.ended is None

    def _spawn(self, path: Path, *, reuse: bool = False) -> tuple[int, int]:
        """Ask the zygote for a worker on ``path``; a new zygote if the old one is gone.

        ``reuse``: the worker records its state before the file, to take another after.
        """
        for attempt in range(2):
            if self._zygote is None:
                self._zygote = Zygote(self.setting)
            try:
                return self._zygote.spawn({"path": str(path), "reuse": reuse})
            except OSError:
                self._zygote.close()
                self._zygote = None
                if attempt:
                    raise
        raise AssertionError("unreachable")

    def _send(self, worker: _Worker, message: dict[str, Any] | None) -> _Request:
        """Send a request; its deadline is what is left of the file's time limit."""
        now = time.monotonic()
        left = max(self.limits.seconds - worker.spent, 0.0)
        request = _Request(worker, now + left + GRACE, now)
        worker.process.busy = request
        if message is not None:
            try:
                worker.channel.send(message, request.deadline)
            except ChannelError as error:
                self._fail(request, f"could not be reached ({error})")
        return request

    def _await(self, request: _Request) -> _Request:
        """Wait for one request's answer (evaluations ahead go on meanwhile)."""
        if not request.done:
            self._running.append(request)
        while not request.done:
            self._pump()
            self._start_queued()
        if request in self._running:
            self._running.remove(request)
        return request

    def _pump(self) -> None:
        """Wait for the next answer or deadline among the requests in flight."""
        if not self._running:
            return
        now = time.monotonic()
        timeout = max(0.0, min(r.deadline for r in self._running) - now)
        poller = select.poll()
        by_fd = {}
        for request in self._running:
            poller.register(request.worker.channel.fd, select.POLLIN)
            by_fd[request.worker.channel.fd] = request
        for fd, _ in poller.poll(timeout * 1000):
            self._receive(by_fd[fd])
        now = time.monotonic()
        for request in self._running:
            if not request.done and request.deadline <= now:
                seconds = self.limits.seconds
                self._fail(request, f"took longer than {seconds:g} s (--time-limit, for the "
                           "whole evaluation of a file) and was stopped (an endless loop, "
                           "or code that does not give way to the timer?)", kill=True)
        for request in [r for r in self._running if r.done]:
            self._running.remove(request)
            request.worker.spent += now - request.started
            if request.worker.process.busy is request:
                request.worker.process.busy = None
            self._finish(request)

    def _receive(self, request: _Request) -> None:
        channel = request.worker.channel
        try:
            channel.fill()
            message = channel.take()
        except Closed:
            self._fail(request, self._ended(request.worker))
            return
        except ChannelError as error:
            self._fail(request, f"sent a malformed answer ({error})", kill=True)
            return
        if message is None:
            return
        reply = message[0]
        if not isinstance(reply, dict) or reply.get("op") not in ("loaded", "result", "error"):
            self._fail(request, "sent a malformed answer", kill=True)
            return
        request.reply = reply
        self._note_reads(request.path, reply.get("read"))

    def _note_reads(self, path: Path, read: object) -> None:
        """Remember the files a worker says an answer about ``path`` read.

        Only those launchverify itself may read count (the list comes from the launch
        file's process: a name elsewhere is not even looked at).
        """
        if (isinstance(read, list) and len(read) <= MAX_READS
                and all(isinstance(p, str) and len(p) < MAX_PATH for p in read)):
            known = self._read.setdefault(path, set())
            if known is not None:
                known.update(p for p in read if p.startswith("/") and reading.outside(p) is None)
        else:
            self._read[path] = None

    def reads(self, path: Path) -> frozenset[str] | None:
        """Return the files the evaluation of ``path`` opened so far (``None``: unknown).

        A file whose worker failed before it answered, or that was not asked, is unknown.
        """
        read = self._read.get(path)
        return None if read is None else frozenset(read)

    def _fail(self, request: _Request, why: str, *, kill: bool = False) -> None:
        worker = request.worker
        request.failure = why
        worker.ended = why
        self._read[request.path] = None
        if kill and self._zygote is not None:
            self._zygote.kill(worker.number)
        self._end(worker.process)

    def _ended(self, worker: _Worker) -> str:
        ended = self._zygote.wait(worker.number, 2.0) if self._zygote is not None else None
        how = ended.describe() if ended is not None else "ended"
        return f"{how} before answering (os._exit, a crash or a signal in the launch file's code?)"

    def _finish(self, request: _Request) -> None:
        if request.load is not None:
            self._loaded(request.load, request)

    # ------------------------------------------------------------------ answers

    def _loaded(self, load: _Load, request: _Request) -> None:
        worker = request.worker
        reply = request.reply
        if worker.reused and (reply is None or reply.get("op") != "loaded"):
            self._release(worker.process)  # an earlier file may be the cause: again, alone
            self.reused -= 1
            load.request = None
            self._start(load, fresh=True)
            return
        load.done = True
        self.evaluated += 1
        if reply is None or reply.get("op") != "loaded":
            if reply is None:
                why, where = f"its process {request.failure}", Span.of_file(load.path)
            else:
                why = str(reply.get("message", ""))[:300]
                where = self._where(load.path, reply.get("where"))
            load.problems.append(Problem(
                ProblemKind.EVALUATION, f"the evaluation of this file failed: {why}", where))
            self._release(worker.process)
            return
        if self.protections is None:
            self.protections = str(reply.get("protections", ""))
        callbacks = worker.collected = []
        decoder = worker.decoder = self._decoder(worker)
        try:
            first = reply.get("first", 0)
            if not isinstance(first, int) or isinstance(first, bool) or first < 0:
                raise CodecError("its callbacks are misnumbered")
            worker.first = first
            decoded = decoder.decode(reply.get("data"))
            if not isinstance(decoded, tuple) or len(decoded) != 2:
                raise CodecError("not a launch file")
            launch, problems = decoded
            if not (launch is None or isinstance(launch, a.LaunchFile)) or not isinstance(
                    problems, tuple) or not all(isinstance(p, Problem) for p in problems):
                raise CodecError("not a launch file")
        except TooLarge as error:  # ros2 launch may take it: unknown here, not broken
            load.problems.append(Problem(
                ProblemKind.UNMODELED, f"not checked: {error}", Span.of_file(load.path)))
            self._end(worker.process)
            return
        except (CodecError, ValueError, TypeError) as error:
            load.problems.append(Problem(
                ProblemKind.EVALUATION, "the evaluation of this file failed: its process sent "
                f"an answer that is not a launch description ({error})",
                Span.of_file(load.path)))
            self._end(worker.process)
            return
        load.launch = launch if launch is None or launch.path == load.path else None
        load.problems.extend(problems)
        _place_callbacks(launch, callbacks)
        if callbacks:
            worker.loaded = len(callbacks)
            worker.process.holders.append(worker)
            self._keep(worker)
        if reply.get("reusable") is True:
            self._park(worker)
        else:
            self._release(worker.process)  # without callbacks to run, it exits

    def _keep(self, worker: _Worker) -> None:
        """Keep a worker's process alive for its files' OpaqueFunctions.

        Beyond ``MAX_ALIVE``, the least recently used one that is not answering ends; its
        files are started again if asked.
        """
        self._alive.pop(worker.process, None)
        self._alive[worker.process] = None
        while len(self._alive) > MAX_ALIVE:
            oldest = next((p for p in self._alive if p.free), None)
            if oldest is None:
                break
            self._end(oldest)

    def _revive(self, worker: _Worker) -> str | None:
        """Start a fresh worker for a recycled one's file; return why it failed, if it did."""
        try:
            number, fd = self._spawn(worker.path)
        except OSError as error:
            return f"could not be started again ({error.strerror or error})"
        fresh = _Worker(worker.path, _Process(number, Channel(fd)), spent=worker.spent)
        request = self._await(self._send(fresh, None))
        worker.spent = fresh.spent
        reply = request.reply
        if reply is None or reply.get("op") != "loaded":
            return f"{request.failure or 'failed'} when it was started again"
        if reply.get("callbacks") != worker.loaded or reply.get("first") != 0:
            fresh.channel.close()
            return "made other OpaqueFunctions when it was evaluated again"
        worker.process, worker.first, worker.recycled = fresh.process, 0, False
        fresh.process.holders.append(worker)
        # its answers now build on the fresh evaluation's records: read them (the walk
        # keeps the first evaluation's, so identity across the two is lost there)
        worker.decoder, collected = self._decoder(worker), worker.collected
        try:
            worker.decoder.decode(reply.get("data"))
        except (CodecError, ValueError, TypeError):
            worker.decoder = None
        finally:
            worker.collected = collected
        return None

    def call(self, worker: _Worker, number: int, configurations: Mapping[str, Any],
             current: Path, span: Span) -> a.OpaqueResult:
        """Run one OpaqueFunction of ``worker``'s file (``number``: its own, from 0)."""
        reply, failure = None, "ended before it was asked"
        for attempt in range(2):
            if worker.recycled:
                why = (self._revive(worker) if number < worker.loaded else
                       "made this OpaqueFunction in an earlier call and was recycled")
                if why is not None:
                    worker.ended = why
            if worker.ended is not None:
                return _failed(span, f"not evaluated: the process evaluating this file "
                               f"{worker.ended}", ProblemKind.UNMODELED)
            if worker.spent >= self.limits.seconds:
                return _failed(span, f"running this OpaqueFunction failed: the evaluation of "
                               f"this file took its whole time limit ({self.limits.seconds:g} "
                               "s, --time-limit) before it", ProblemKind.EVALUATION)
            self._keep(worker)
            while not worker.process.free:  # evaluating another file of its repository
                self._pump()
            if worker.process.closed:  # (which ended it)
                worker.recycled = worker.ended is None
                continue
            arguments = Encoder(_no_register).encode((dict(configurations), str(current)))
            request = self._await(self._send(worker, {
                "op": "call", "callback": number + worker.first, "arguments": arguments}))
            reply, failure = request.reply, request.failure or failure
            if reply is not None and reply.get("again") is True and not attempt:
                # another file its process took since left it changed: alone, afresh
                if worker in worker.process.holders:
                    worker.process.holders.remove(worker)
                worker.recycled = True
                continue
            break
        if reply is None:
            return _failed(span, f"running this OpaqueFunction failed: the process evaluating "
                           f"this file {failure}", ProblemKind.EVALUATION)
        if reply.get("op") != "result":
            where = self._where(worker.path, reply.get("where")) if reply.get("where") else span
            return _failed(where, f"running this OpaqueFunction failed: "
                           f"{str(reply.get('message', ''))[:300]}", ProblemKind.EVALUATION)
        callbacks = worker.collected = []
        base = reply.get("base", 0)
        decoder = worker.decoder if base else self._decoder(worker)
        try:
            if decoder is None or decoder.received != base:
                raise CodecError("it names records of answers launchverify does not have")
            worker.decoder = None  # (again only once this answer is whole)
            result = decoder.decode(reply.get("data"))
            if not isinstance(result, a.OpaqueResult) or not all(
                    isinstance(p, Problem) for p in result.problems):
                raise CodecError("not the result of an OpaqueFunction")
            worker.decoder = decoder
        except TooLarge as error:
            return _failed(span, f"this OpaqueFunction is not checked: {error}",
                           ProblemKind.UNMODELED)
        except (CodecError, ValueError, TypeError) as error:
            return _failed(span, f"running this OpaqueFunction failed: its answer is not a "
                           f"launch description ({error})", ProblemKind.EVALUATION)
        _place_callbacks(result, callbacks)
        return result

    def _decoder(self, worker: _Worker) -> Decoder:
        """Return a decoder for ``worker``'s answers, collecting the callbacks each names."""
        def callback(number: int) -> _Callback:
            worker.collected.append(_Callback(self, worker, number - worker.first))
            return worker.collected[-1]

        return Decoder(callback, span=lambda found: self._own_span(worker.path, found))

    # ------------------------------------------------------------------ places

    def _where(self, path: Path, where: object) -> Span:
        if isinstance(where, list) and len(where) == 2 and isinstance(where[0], str) \
                and isinstance(where[1], int):
            return self._own_span(path, Span(Path(where[0]), max(1, where[1])))
        return Span.of_file(path)

    def _own_span(self, path: Path, span: Span) -> Span:
        """Keep a worker's places in its own file and the helper modules it imports.

        A launch file's code may claim any file name (``compile(src, 'other.py')``): it
        must not put findings on other launch files.
        """
        if span.file == path or self._is_helper(path, span.file):
            return span
        return Span.of_file(path)

    def _is_helper(self, path: Path, file: Path) -> bool:
        known = self._helpers.get(file)
        if known is None:
            known = False
            if file.suffix == ".py" and file.is_absolute() and (
                    file.is_relative_to(self.setting.workspace)
                    or file.is_relative_to(path.parent)):
                try:
                    data = read_file(file, prefix=1 << 20)
                    known = not any(entry in data for entry in _ENTRY_POINTS)
                except OSError:
                    known = False
            self._helpers[file] = known
        return known


class _Callback:
    """An OpaqueFunction body that runs in its file's worker."""

    def __init__(self, pool: IsolatedPython, worker: _Worker, number: int) -> None:
        self.pool = pool
        self.worker = worker
        self.number = number
        self.span: Span = Span.of_file(worker.path)

    def __call__(self, configurations: Mapping[str, Any], current: Path) -> a.OpaqueResult:
        return self.pool.call(self.worker, self.number, configurations, current, self.span)


def _place_callbacks(value: object, callbacks: list[_Callback]) -> None:
    """Point each callback at its OpaqueFunction's line (for its failures)."""
    if not callbacks:
        return
    from launchverify.isolation.codec import iter_records

    for record in iter_records(value):
        if isinstance(record, a.OpaqueFunction) and isinstance(record.run, _Callback):
            record.run.span = record.span


def _failed(span: Span, message: str, kind: ProblemKind) -> a.OpaqueResult:
    return a.OpaqueResult(actions=(), problems=(Problem(kind, message, span),))


def _no_register(function: Callable[..., Any]) -> int:
    raise CodecError("launchverify sends no functions to a worker")
