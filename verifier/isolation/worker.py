"""A worker: one Python launch file evaluated in a confined process.

Forked from the zygote for one file, it closes every descriptor but its channel, leaves
the zygote's session, confines itself (``confine``), arms the audit hook, then runs the
file and sends back its IR as plain data. It stays to run the file's OpaqueFunctions when
the parent's walk reaches them, one request at a time, each under the time limit, until
the parent closes the channel. Meanwhile it may take the next file of its repository
(``reuse``): the OpaqueFunctions of every file it took stay callable, each in the state
its own file left (``_Worker.switch``). It never returns: it ends with ``os._exit``, so nothing the
launch file registered (``atexit``, finalizers) runs after the last answer.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import traceback
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, NoReturn

from launchverify.frontends.python import PythonFrontend
from launchverify.frontends.python.sandbox import (
    SymbolicEnviron,
    TimeLimitExceeded,
    arm,
    take_opened,
    time_limit,
)
from launchverify.isolation.channel import Channel, ChannelError
from launchverify.isolation.codec import Decoder, Encoder
from launchverify.isolation.confine import Confinement, Limits, beneath
from launchverify.isolation.reuse import Baseline
from launchverify.models import distros
from launchverify.problems import ProblemSink
from launchverify.workspace.packages import PackageIndex


@dataclass(frozen=True)
class Setting:
    """What every worker of a check shares (inherited through the zygote's memory)."""

    index: PackageIndex
    workspace: Path
    readable: tuple[str, ...]  # folders the worker may read (Landlock)
    limits: Limits
    distro: str | None
    environment: dict[str, str]  # --env: the machine's variables a launch file may read
    arguments: dict[str, str] = field(default_factory=dict)  # name:=value on the command line
    debug: bool = False  # keep stderr and print our own failures (LAUNCHVERIFY_DEBUG_WORKERS)
    absent_modules: bool = False  # ablation: only launch, launch_ros and Python's own exist
    landlock: bool = True  # False: as on kernels without it (LAUNCHVERIFY_WITHOUT_LANDLOCK)


def serve(fd: int, request: dict[str, Any], scratch: str, setting: Setting,
          confinement: Confinement) -> NoReturn:
    """Run the worker on channel ``fd``; never returns."""
    status = 0
    try:
        _keep_only(fd, keep_stderr=setting.debug)
        os.setsid()
        channel = Channel(fd)
        protections = confinement.apply(scratch, _with_folder(setting.readable, request))
        arm(scratch, setting.environment)
        _Worker(channel, setting, protections.describe(), scratch).run(request)
    except BaseException:  # our own failure: the parent reports the worker's end
        if setting.debug:
            traceback.print_exc()
        status = 70
    os._exit(status)


class _Worker:
    def __init__(self, channel: Channel, setting: Setting, protections: str,
                 scratch: str) -> None:
        self.channel = channel
        self.setting = setting
        self.protections = protections
        self.scratch = scratch
        self.callbacks: list[Callable[..., Any]] = []
        # each file's encoder, kept for its OpaqueFunctions' answers: a record sent before
        # is sent as a reference to it (the parent keeps the matching decoder)
        self.encoders: dict[str, Encoder] = {}
        self.owners: list[str] = []  # the file each callback belongs to
        self.variables: dict[str, dict[str, str]] = {}  # each file's os.environ, as it left it
        self.serving = ""  # the file of the request being answered, or answered last
        self.baseline: Baseline | None = None
        self.kept_by: str | None = None  # why it may take no other file

    def switch(self, path: str) -> str | None:
        """Serve ``path`` next; return why it may not be served here, if it may not.

        A file's OpaqueFunctions run in the state that file left: after another file,
        only if that one left the worker as it found it (each file may disturb only
        itself), and with the environment variables that file set (each file is its own
        ``ros2 launch``). Checked here, with no timer running.
        """
        if path != self.serving:
            if self.kept_by is None and self.baseline is not None:
                self.kept_by = self.baseline.disturbed()
            if self.kept_by is not None:
                return self.kept_by
            self._serve(path)
        return None

    def _serve(self, path: str) -> None:
        self.serving = path
        environ: object = os.environ
        if type(environ) is SymbolicEnviron:  # (else: the file's own doing, its loss)
            environ.use(self.variables.setdefault(path, dict(self.setting.environment)))

    def register(self, function: Callable[..., Any]) -> int:
        self.callbacks.append(function)
        self.owners.append(self.serving)
        return len(self.callbacks) - 1

    def run(self, request: dict[str, Any]) -> None:
        with distros.checking(self.setting.distro):
            # recorded only when the parent may send more (touching every module copies
            # the zygote's pages: about 10 ms)
            self.baseline = Baseline.take() if request.get("reuse") else None
            self._serve(str(request.get("path", "")))
            self.answer(self.load, request)
            while True:
                try:
                    request = self.channel.receive()
                except ChannelError:
                    return  # the parent is done with this worker
                if request.get("op") == "load":
                    self.load_another(request)
                else:
                    self.call_for(request)

    def load_another(self, request: dict[str, Any]) -> None:
        """Evaluate another file of the repository if the last one left the worker as it was.

        When it may not, the parent starts the file in a fresh worker.
        """
        refused = self.switch(str(request.get("path", "")))
        if refused is not None:
            self.channel.send({"op": "error", "message": "this worker takes no other file: "
                               f"{refused}", "where": None, "again": True})
            return
        self.answer(self.load, request)

    def call_for(self, request: dict[str, Any]) -> None:
        """Run an OpaqueFunction if its file may be served here.

        When it may not (another file since disturbed the worker), the parent evaluates
        the file again in a fresh worker and asks that one.
        """
        number = request.get("callback")
        if isinstance(number, int) and 0 <= number < len(self.owners):
            refused = self.switch(self.owners[number])
            if refused is not None:
                self.channel.send({"op": "error", "message": "this worker no longer serves "
                                   f"the file: {refused}", "where": None, "again": True})
                return
        self.answer(self.call, request)

    def answer(self, handler: Callable[[dict[str, Any]], dict[str, Any]],
               request: dict[str, Any]) -> None:
        try:
            with time_limit(self.setting.limits.seconds):
                reply = handler(request)
        except TimeLimitExceeded as error:
            reply = {"op": "error", "message": f"{error} (an endless loop?)",
                     "where": _user_line(error)}
        except BaseException as error:
            reply = {"op": "error", "message": _describe(error), "where": _user_line(error)}
        if handler == self.load:
            self.kept_by = ("its file failed" if reply.get("op") != "loaded"
                            else "it was not asked to take more" if self.baseline is None
                            else self.kept_by)
            reply["reusable"] = self.kept_by is None  # (the rest is checked if it is reused)
            _clear(self.scratch)
        reply["read"] = take_opened()  # what the answer rests on (kept results say)
        self.channel.send(reply)

    def load(self, request: dict[str, Any]) -> dict[str, Any]:
        path = Path(request["path"])
        sink = ProblemSink()
        frontend = PythonFrontend(self.setting.index, self.setting.workspace,
                                  self.setting.arguments,
                                  absent_modules=self.setting.absent_modules)
        first = len(self.callbacks)
        launch = frontend.load(path, sink)
        encoder = self.encoders[self.serving] = Encoder(self.register)
        data = encoder.encode((launch, tuple(sink.problems)))
        return {"op": "loaded", "protections": self.protections, "data": data,
                "callbacks": len(self.callbacks) - first, "first": first}

    def call(self, request: dict[str, Any]) -> dict[str, Any]:
        number = request.get("callback")
        if not isinstance(number, int) or not 0 <= number < len(self.callbacks):
            return {"op": "error", "message": "no such callback", "where": None}
        arguments = Decoder(lambda n: _not_callable).decode(request["arguments"])
        if not isinstance(arguments, tuple) or len(arguments) != 2:
            return {"op": "error", "message": "malformed call", "where": None}
        result = self.callbacks[number](arguments[0], Path(str(arguments[1])))
        owner = self.owners[number]
        encoder = self.encoders.get(owner) or Encoder(self.register)
        base = encoder.sent
        try:
            data = encoder.encode(result)
        except BaseException:
            self.encoders.pop(owner, None)  # half sent: the next answer starts afresh
            raise
        return {"op": "result", "data": data, "base": base}


def _clear(scratch: str) -> None:
    """Empty the scratch folder between files (the next one starts with nothing there)."""
    try:
        entries = list(os.scandir(scratch))
    except OSError:
        return
    for entry in entries:
        with contextlib.suppress(Exception):  # what is refused stays: the next file copes
            if entry.is_dir(follow_symlinks=False):
                shutil.rmtree(entry.path, ignore_errors=True)
            else:
                Path(entry.path).unlink()


def _not_callable(*args: object) -> None:
    raise TypeError("the parent sends no callbacks")


def _with_folder(readable: tuple[str, ...], request: dict[str, Any]) -> tuple[str, ...]:
    """Add the launch file's folder to what may be read, unless it is there already."""
    folder = os.path.realpath(Path(request["path"]).parent)
    return readable if beneath(folder, readable) else (*readable, folder)


def _keep_only(fd: int, *, keep_stderr: bool = False) -> None:
    """Close every descriptor but ``fd``; standard streams go to /dev/null."""
    null = os.open(os.devnull, os.O_RDWR)
    for stream in (0, 1) if keep_stderr else (0, 1, 2):
        if stream != fd:
            os.dup2(null, stream)
    keep = {0, 1, 2, fd}
    try:  # (os.listdir: pathlib here cost a quarter of a millisecond per worker)
        open_fds = [int(name) for name in os.listdir("/proc/self/fd")]  # noqa: PTH208
    except OSError:
        open_fds = list(range(3, 1024))
    for other in open_fds:
        if other not in keep:
            with contextlib.suppress(OSError):
                os.close(other)


def _describe(error: BaseException) -> str:
    text = str(error)
    return f"{type(error).__name__}: {text[:300]}" if text else type(error).__name__


def _user_line(error: BaseException) -> list[object] | None:
    """Return ``[file, line]`` of the innermost frame outside launchverify, if any."""
    from launchverify.own_code import is_own_file

    frames = [f for f in traceback.extract_tb(error.__traceback__)
              if not is_own_file(f.filename) and not f.filename.startswith("<")]
    return [frames[-1].filename, frames[-1].lineno or 1] if frames else None
