"""The zygote: a fresh interpreter started once per check that forks the workers.

It is started with ``exec``, never forked from launchverify, and with an environment
built from scratch: no byte of the caller's environment (a CI job's tokens, on the
initial stack of a forked process) nor of launchverify's own state reaches a worker's
memory. It receives what workers share (the ``Setting``, the unsaved buffers, the size
limit, the folders reads are confined to) through a pipe, imports the models and warms
up once; forking a worker from it then costs about a millisecond.

It talks to launchverify over a ``SOCK_SEQPACKET`` control socket: a spawn request
carries the worker's end of a fresh socket pair (``SCM_RIGHTS``); the zygote answers when a
worker ends (its wait status), kills a worker on request (it is the parent, so a pid is
never reused under it), removes each worker's scratch folder, and when launchverify goes
away (end of file on the control socket) kills every worker and exits.
"""

from __future__ import annotations

import contextlib
import gc
import json
import os
import pickle
import select
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
from dataclasses import dataclass
from pathlib import Path
from typing import Any, NoReturn

from launchverify.frontends.python import fast_yaml
from launchverify.frontends.python.sandbox import SCRATCH_PREFIX
from launchverify.isolation.confine import Confinement
from launchverify.isolation.worker import Setting, serve
from launchverify.workspace import reading

_PACKET = 1 << 16
_KEPT_NEWS = 1024  # ended workers remembered for wait()


@dataclass
class Ended:
    """How a worker ended, as ``waitpid`` said."""

    code: int | None  # exit status
    signal: int | None  # the signal that killed it

    def describe(self) -> str:
        """Return the end in words."""
        if self.code is None and self.signal is None:
            return "could not be started (no process or temporary folder could be made)"
        if self.signal is not None:
            try:
                name = signal.Signals(self.signal).name
            except ValueError:
                name = f"signal {self.signal}"
            if self.signal == signal.SIGSYS:
                name += " (a system call the sandbox forbids, such as sending a signal)"
            return f"was killed by {name}"
        return f"exited with status {self.code}"


@dataclass
class _Started:
    """A zygote started, importing the models, that has not been told its setting."""

    process: subprocess.Popen[bytes]
    control: socket.socket
    setup: int  # the pipe its setup goes down

    @classmethod
    def start(cls) -> _Started:
        ours, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
        setup_read, setup_write = os.pipe()
        try:
            process = subprocess.Popen(
                [sys.executable, "-I", "-X", "utf8", "-c", _BOOT, str(theirs.fileno()),
                 str(setup_read), json.dumps(sys.path)],
                pass_fds=(theirs.fileno(), setup_read), env=_fresh_environment(),
                stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                stderr=None if os.environ.get("LAUNCHVERIFY_DEBUG_WORKERS")
                else subprocess.DEVNULL,
                start_new_session=True)  # the terminal's Ctrl-C is launchverify's
        except OSError:
            ours.close()
            os.close(setup_write)
            raise
        finally:
            theirs.close()
            os.close(setup_read)
        return cls(process, ours, setup_write)

    def discard(self) -> None:
        self.control.close()
        with contextlib.suppress(OSError):
            os.close(self.setup)
        self.process.kill()
        self.process.wait()


_STARTED: list[_Started] = []  # at most one, started ahead (``start_ahead``)


def start_ahead() -> None:
    """Start the next check's zygote now, beside what launchverify does meanwhile.

    A fresh interpreter takes a tenth of a second to import the models; started when
    the launch files are found, it is ready when the first one needs it.
    """
    if not _STARTED:
        with contextlib.suppress(OSError):
            _STARTED.append(_Started.start())


def discard_ahead() -> None:
    """End a zygote started ahead that no check took."""
    while _STARTED:
        _STARTED.pop().discard()


class Zygote:
    """launchverify's handle on its zygote."""

    def __init__(self, setting: Setting) -> None:
        started = _STARTED.pop() if _STARTED else _Started.start()
        setup = pickle.dumps({
            "setting": setting, "temporary": tempfile.gettempdir(),
            "unsaved": reading.unsaved_contents(), "limit": reading.limit(),
            "roots": reading.confined_to()})
        # written beside: the zygote may still be importing, and the setup be large
        threading.Thread(target=_write_all, args=(started.setup, setup), daemon=True).start()
        self.process = started.process
        self.pid = started.process.pid
        self.control = started.control
        self.ended: dict[int, Ended] = {}
        self._next = 0

    def spawn(self, request: dict[str, Any]) -> tuple[int, int]:
        """Start a worker; return its number and launchverify's end of its channel."""
        self.drain()
        mine, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_STREAM)
        number = self._next
        self._next += 1
        try:
            message = json.dumps({"op": "spawn", "id": number, "request": request}).encode()
            socket.send_fds(self.control, [message], [theirs.fileno()])
        except OSError:
            mine.close()
            raise
        finally:
            theirs.close()
        mine.setblocking(False)
        return number, mine.detach()

    def drain(self) -> None:
        """Read the news of ended workers that have come in, without waiting.

        The zygote reports every worker that ends, most of them after answering: news
        nobody waits for. Left unread, they would fill the socket after a few hundred
        workers and the zygote, blocked on its report, would start no more.
        """
        while select.select([self.control], [], [], 0)[0]:
            try:
                packet = self.control.recv(_PACKET)
            except OSError:
                return
            if not packet:
                return
            self._record(packet)

    def _record(self, packet: bytes) -> None:
        news = json.loads(packet)
        self.ended[news["id"]] = Ended(news["code"], news["signal"])
        while len(self.ended) > _KEPT_NEWS:  # the oldest: long answered, nobody asks
            del self.ended[next(iter(self.ended))]

    def kill(self, number: int) -> None:
        """Kill a worker (nothing happens if it has ended)."""
        self.drain()
        with contextlib.suppress(OSError):
            self.control.send(json.dumps({"op": "kill", "id": number}).encode())

    def wait(self, number: int, seconds: float) -> Ended | None:
        """Return how a worker ended, waiting up to ``seconds`` for the news."""
        deadline = _now() + seconds
        while number not in self.ended:
            remaining = deadline - _now()
            if remaining <= 0 or not select.select([self.control], [], [], remaining)[0]:
                return None
            try:
                packet = self.control.recv(_PACKET)
            except OSError:
                return None
            if not packet:
                return None
            self._record(packet)
        return self.ended.pop(number)

    def close(self) -> None:
        """Stop the zygote and every worker (they die with it)."""
        self.control.close()
        try:
            self.process.wait(timeout=5)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()


class _Server:
    """The zygote's side."""

    def __init__(self, control: socket.socket, setting: Setting, temporary: str) -> None:
        self.control = control
        self.setting = setting
        self.temporary = temporary
        self.workers: dict[int, tuple[int, str]] = {}  # pid -> (number, scratch folder)
        self.numbers: dict[int, int] = {}  # number -> pid

    def run(self) -> None:
        signal.signal(signal.SIGINT, signal.SIG_IGN)  # (a session of its own already)
        _forget_environment()
        self.confinement = Confinement(self.setting.limits, landlock=self.setting.landlock)
        fast_yaml.install()  # workers load YAML with libyaml where it reads alike
        _warm_up(self.setting)
        gc.freeze()  # workers' collections never touch (and copy) the inherited heap
        gc.enable()  # forked from a check that paused it: a launch file's code runs as usual
        wake_read, wake_write = os.pipe()
        os.set_blocking(wake_write, False)
        signal.set_wakeup_fd(wake_write)
        signal.signal(signal.SIGCHLD, lambda signum, frame: None)
        try:
            while True:
                ready = select.select([self.control.fileno(), wake_read], [], [])[0]
                if wake_read in ready:
                    os.read(wake_read, 4096)
                    self.reap()
                if self.control.fileno() in ready and not self.receive(wake_read, wake_write):
                    return
        finally:
            self.stop_all()

    def stop_all(self) -> None:
        """Kill every worker, wait for them, remove their folders."""
        for pid in list(self.workers):
            with contextlib.suppress(OSError):
                os.kill(pid, signal.SIGKILL)
        while self.workers:
            try:
                pid, _ = os.waitpid(-1, 0)
            except ChildProcessError:
                break
            self.forget(pid)
        for pid in list(self.workers):
            self.forget(pid)

    def receive(self, *wake: int) -> bool:
        try:
            packet, fds, _, _ = socket.recv_fds(self.control, _PACKET, 1)
        except OSError:
            return False
        if not packet:
            return False
        message = json.loads(packet)
        if message["op"] == "spawn" and fds:
            self.spawn(message["id"], message["request"], fds[0], wake)
        elif message["op"] == "kill":
            pid = self.numbers.get(message["id"])
            if pid is not None:
                with contextlib.suppress(OSError):
                    os.kill(pid, signal.SIGKILL)
        for fd in fds:
            with contextlib.suppress(OSError):
                os.close(fd)
        return True

    def spawn(self, number: int, request: dict[str, Any], fd: int, wake: tuple[int, ...]) -> None:
        try:
            scratch = tempfile.mkdtemp(prefix=SCRATCH_PREFIX, dir=self.temporary)
        except OSError:
            scratch = ""
        try:
            pid = os.fork() if scratch else -1
        except OSError:
            pid = -1
        if pid < 0:  # no folder or no process: the worker "ends" at once, never started
            if scratch:
                shutil.rmtree(scratch, ignore_errors=True)
            with contextlib.suppress(OSError):
                self.control.send(json.dumps({"id": number, "code": None,
                                              "signal": None}).encode())
            return
        if pid == 0:
            _become_worker(self.control, wake, fd, request, scratch, self.setting,
                           self.confinement)
        self.workers[pid] = (number, scratch)
        self.numbers[number] = pid

    def reap(self) -> None:
        while True:
            try:
                pid, status = os.waitpid(-1, os.WNOHANG)
            except ChildProcessError:
                return
            if pid == 0:
                return
            number = self.forget(pid)
            if number is None:
                continue
            news = {"id": number, "code": os.WEXITSTATUS(status) if os.WIFEXITED(status) else None,
                    "signal": os.WTERMSIG(status) if os.WIFSIGNALED(status) else None}
            with contextlib.suppress(OSError):  # never block: a full socket drops news
                self.control.send(json.dumps(news).encode(), socket.MSG_DONTWAIT)

    def forget(self, pid: int) -> int | None:
        entry = self.workers.pop(pid, None)
        if entry is None:
            return None
        number, scratch = entry
        self.numbers.pop(number, None)
        shutil.rmtree(scratch, ignore_errors=True)
        return number


def _become_worker(control: socket.socket, wake: tuple[int, ...], fd: int,
                   request: dict[str, Any], scratch: str, setting: Setting,
                   confinement: Confinement) -> NoReturn:
    signal.set_wakeup_fd(-1)
    signal.signal(signal.SIGCHLD, signal.SIG_DFL)
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    control.close()
    for other in wake:
        os.close(other)
    serve(fd, request, scratch, setting, confinement)


def _warm_up(setting: Setting) -> None:
    """Evaluate launchverify's own warm-up launch file, so that workers start warm."""
    from launchverify.frontends.python import PythonFrontend
    from launchverify.ir import actions as a
    from launchverify.isolation.codec import Encoder, iter_records
    from launchverify.problems import ProblemSink

    path = Path(__file__).with_name("warm_up_launch.txt")
    with contextlib.suppress(Exception):
        launch = PythonFrontend(setting.index, setting.workspace).load(path, ProblemSink())
        for record in list(iter_records(launch)):
            if isinstance(record, a.OpaqueFunction):
                record.run({}, path)
        json.dumps(Encoder(lambda function: 0).encode(launch))


# launchverify's own sys.path first (-I ignores PYTHONPATH), then the models' imports,
# which run while launchverify builds its index; then the setup, read from the pipe
# (the dataclasses' compiled methods are read from launchverify's cache, never written)
_BOOT = ("import json, sys; sys.path[:] = json.loads(sys.argv[3]); "
         "from launchverify.process.code_cache import install; install(); "
         "from launchverify.isolation.zygote import boot; boot(*sys.argv[1:3])")


def _fresh_environment() -> dict[str, str]:
    """Return the zygote's environment: what Python needs, nothing of the caller's."""
    return {"LC_ALL": "C.UTF-8", "PATH": os.defpath}


def _write_all(fd: int, data: bytes) -> None:
    try:
        with os.fdopen(fd, "wb") as pipe:
            pipe.write(data)
    except OSError:  # the zygote is gone: launchverify sees it on the control socket
        pass


def boot(control_fd: str, setup_fd: str) -> NoReturn:
    """Run the zygote in a fresh interpreter (see the module's docstring)."""
    try:
        with os.fdopen(int(setup_fd), "rb") as pipe:
            setup = pickle.loads(pipe.read())
        tempfile.tempdir = setup["temporary"]  # as launchverify's: never asked of the environment
        reading.restore(setup["unsaved"], setup["limit"], setup["roots"])
        control = socket.socket(fileno=int(control_fd))
        _Server(control, setup["setting"], setup["temporary"]).run()
    finally:
        os._exit(0)


def _forget_environment() -> None:
    """Drop the zygote's few environment variables: a worker has none to read.

    Launch files see a symbolic environment; the real one (``os.environ``,
    ``posix.environ`` and the C environment) is emptied here, once, before any worker
    exists. (It never held the caller's: see ``_fresh_environment``.)
    """
    os.environ.clear()
    with contextlib.suppress(ImportError, AttributeError):
        import posix

        posix.environ.clear()


def _now() -> float:
    import time

    return time.monotonic()
