"""Run a plan: processes, handlers, timers, respawn, output and shutdown, as ros2 launch does.

Every process starts in its own session (its own process group, so signals reach its
children too); a guard process kills the groups if launchverify itself is killed
(``guard.py``). Shutdown
follows ``launch``: SIGINT to each process, SIGTERM ``sigterm_timeout`` seconds later,
SIGKILL ``sigkill_timeout`` seconds after that; a second Ctrl-C (or SIGTERM to
launchverify) escalates to SIGTERM at once, a third to SIGKILL. Whatever happens, no
process group outlives the run.

Every event is written to ``events.log`` in the run folder (and kept in ``events`` for
tests): ``start NAME pid``, ``exit NAME code``, ``signal NAME SIGINT``, ``respawn NAME``,
``handler EVENT file:line``, ``timer file:line``, ``shutdown REASON``.

When the reader of the screen goes away (``launchverify run FILE | head``), the launch
goes on, as ros2 launch's does when its logging cannot write: what it prints goes to the
run folder's logs only.
"""

from __future__ import annotations

import asyncio
import contextlib
import os
import signal
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TextIO

from launchverify.executor.guard import Guard
from launchverify.executor.plan import Plan, Process, transition_label
from launchverify.graph import TransitionRequest

LINE_LIMIT = 1 << 20


@dataclass
class Running:
    """One start of a process."""

    process: Process
    label: str  # launch's ``name-N``
    child: asyncio.subprocess.Process
    log: TextIO
    started: float
    shutdown_timers: list[asyncio.TimerHandle] = field(default_factory=list)
    signalled: bool = False  # we asked it to stop


class Supervisor:
    """Executes one plan on an asyncio loop."""

    def __init__(self, plan: Plan, run_dir: Path, out: TextIO, *,
                 ros2: str | None = None, now: Callable[[], float] = time.monotonic) -> None:
        self.plan = plan
        self.graph = plan.graph
        self.run_dir = run_dir
        self.out = out
        self.ros2 = ros2
        self.now = now
        self.t0 = now()
        self.events: list[str] = []
        self.running: dict[int, Running] = {}  # by pid
        self.started: set[int] = set()  # executions whose process was started
        self.labels: dict[int, str] = {}  # execution: name-N
        self.counts: dict[str, int] = {}
        self.retries: dict[int, int] = {}
        self.active: set[int] = set()  # registered handlers
        self.spent: set[int] = set()
        self.timers: set[asyncio.TimerHandle] = set()
        self.tasks: set[asyncio.Task[None]] = set()
        self.shutting_down = False
        self.escalation = 0
        self.failures: list[str] = []
        self.done = asyncio.Event()
        self.event_log = (run_dir / "events.log").open("a", encoding="utf-8")
        self.launch_log = (run_dir / "launch.log").open("a", encoding="utf-8")
        self.lifecycle_warned = False
        self.guard = Guard()
        self.screen_gone = False  # the reader of ``out`` has left

    # ------------------------------------------------------------------ reporting

    def event(self, text: str) -> None:
        """Record an event (tests read them; events.log keeps them)."""
        self.events.append(text)
        self.event_log.write(f"{self.now() - self.t0:10.3f} {text}\n")
        self.event_log.flush()

    def say(self, who: str, text: str, *, level: str = "INFO", screen: bool = True) -> None:
        """Print a launch message as ros2 launch formats it (``[INFO] [launch]: ...``)."""
        line = f"[{level}] [{who}]: {text}"
        self.launch_log.write(line + "\n")
        if screen:
            self.screen(line + "\n")

    def screen(self, text: str) -> None:
        """Show text at once; once the reader has gone, drop it (the logs keep it)."""
        if self.screen_gone:
            return
        try:
            self.out.write(text)
            self.out.flush()  # a reader behind a pipe sees lines as they come
        except BrokenPipeError:
            self.screen_gone = True
            _send_to_devnull(self.out)

    # ------------------------------------------------------------------ main

    async def run(self) -> int:
        """Run until nothing is left to do or a shutdown completes; return the exit code."""
        loop = asyncio.get_running_loop()
        for number in (signal.SIGINT, signal.SIGTERM):
            loop.add_signal_handler(number, self.on_signal, number)
        await self.guard.start()
        try:
            for note in self.plan.notes:
                self.say("launch", note, level="WARNING")
            self.execute_block(None)
            self.check_done()
            await self.done.wait()
        finally:
            for number in (signal.SIGINT, signal.SIGTERM):
                loop.remove_signal_handler(number)
            self.kill_everything()
            for task in list(self.tasks):
                task.cancel()
            await self.guard.close()
            self.event_log.close()
            self.launch_log.close()
        return 1 if self.failures else 0

    def check_done(self) -> None:
        """Finish when no process runs and nothing is scheduled."""
        if not self.running and not self.timers and not self.tasks:
            self.done.set()

    def on_signal(self, number: int) -> None:
        """Ctrl-C shuts down; again (or SIGTERM) escalates."""
        name = signal.Signals(number).name
        if not self.shutting_down:
            self.shutdown(f"{name} received", escalate=number == signal.SIGTERM)
            return
        self.escalation += 1
        target = signal.SIGTERM if self.escalation == 1 else signal.SIGKILL
        self.say("launch", f"{name} received again, sending {target.name} to every process",
                 level="WARNING")
        for running in list(self.running.values()):
            self.send(running, target)

    # ------------------------------------------------------------------ actions

    def execute_block(self, within: int | None) -> None:
        """Execute what a handler (or the launch) runs, each action after its timers."""
        for delay, execution in self.plan.blocks.get(within, ()):
            if delay is None or delay <= 0:
                self.execute(execution)
            else:
                self.schedule(delay, execution)

    def schedule(self, delay: float, execution: int) -> None:
        loop = asyncio.get_running_loop()
        handle: asyncio.TimerHandle

        def fire() -> None:
            self.timers.discard(handle)
            if not self.shutting_down:
                self.execute(execution)
            self.check_done()

        handle = loop.call_later(delay, fire)
        self.timers.add(handle)

    def execute(self, execution: int) -> None:
        """Execute one action."""
        for number in self.plan.registers.get(execution, ()):
            self.active.add(number)
        if execution in self.plan.processes:
            self.start(execution)
            return  # complete when the process exits
        log = self.plan.log(execution)
        if log is not None:
            self.say("launch.user", log[1], level=log[0].upper())
        reason = self.plan.shutdown_reason(execution)
        if reason is not None:
            self.shutdown(reason)
        for request in self.plan.requests.get(execution, ()):
            self.lifecycle(request)
        self.load_components(execution)
        self.fire("execution_complete", execution)

    # ------------------------------------------------------------------ handlers

    def fire(self, event: str, execution: int) -> None:
        """Run the handlers an event of ``execution``'s action reaches."""
        record = self.graph.executed[execution]
        for number in sorted(self.active - self.spent):
            handler = self.plan.handlers[number]
            if handler.event != event:
                continue
            if handler.target is not None:
                if handler.target is not record.action:
                    continue
                registrar = handler.execution
                if registrar is not None and not self.graph.executed[registrar].same_run(
                        record):
                    continue
            if handler.once:
                self.spent.add(number)
            self.event(f"handler {event} {handler.origin.span.short()}")
            self.execute_block(number)

    # ------------------------------------------------------------------ processes

    def start(self, execution: int, *, respawn: bool = False) -> None:
        """Start a process (again, when respawning)."""
        if self.shutting_down:
            return
        process = self.plan.processes[execution]
        if execution in self.started and not respawn:
            self.failures.append(f"{process.name}: executed more than once")
            self.say("launch", f"process {process.name} is executed more than once: launch "
                     "refuses (an event handler runs it again)", level="ERROR")
            return
        self.started.add(execution)
        if execution not in self.labels:
            count = self.counts.get(process.name, 0) + 1
            self.counts[process.name] = count
            self.labels[execution] = f"{process.name}-{count}"
        task = asyncio.get_running_loop().create_task(self.supervise(execution))
        self.tasks.add(task)
        task.add_done_callback(self.task_done)

    def task_done(self, task: asyncio.Task[None]) -> None:
        self.tasks.discard(task)
        if not task.cancelled() and task.exception() is not None:
            error = task.exception()
            self.failures.append(str(error))
            self.say("launch", f"internal error: {error!r}", level="ERROR")
        self.check_done()

    def environment(self, process: Process) -> dict[str, str]:
        command = process.command
        env = dict(command.replace_env) if command.replace_env is not None else dict(os.environ)
        for name, value in command.env.items():
            if value is None:
                env.pop(name, None)
            else:
                env[name] = value
        return env

    async def supervise(self, execution: int) -> None:
        """Start one process, forward its output, and handle its exit."""
        process = self.plan.processes[execution]
        label = self.labels[execution]
        command = process.command
        for path, text in command.files.items():
            path.parent.mkdir(parents=True, exist_ok=True)
            if not path.exists():
                path.write_text(text, encoding="utf-8")
        log = (self.run_dir / f"{label}.log").open("a", encoding="utf-8")
        try:
            if command.shell:
                child = await asyncio.create_subprocess_shell(
                    " ".join(command.argv), cwd=command.cwd, env=self.environment(process),
                    stdin=asyncio.subprocess.DEVNULL, stdout=asyncio.subprocess.PIPE,
                    stderr=asyncio.subprocess.PIPE, start_new_session=True,
                    limit=LINE_LIMIT)
            else:
                child = await asyncio.create_subprocess_exec(
                    *command.argv, cwd=command.cwd, env=self.environment(process),
                    stdin=asyncio.subprocess.DEVNULL, stdout=asyncio.subprocess.PIPE,
                    stderr=asyncio.subprocess.PIPE, start_new_session=True,
                    limit=LINE_LIMIT)
        except OSError as error:
            log.close()
            self.failures.append(f"{label}: {error}")
            self.say(label, f"failed to start: {error.strerror or error}", level="ERROR")
            self.fire("process_exit", execution)
            return
        running = Running(process, label, child, log, self.now())
        self.running[child.pid] = running
        self.guard.add(child.pid)
        self.event(f"start {label} {child.pid}")
        self.say(label, f"process started with pid [{child.pid}]")
        self.fire("process_start", execution)
        if process.autostart and process.lifecycle_fqn:
            self.transition(process.lifecycle_fqn, ["configure", "activate"])
        self.load_components(execution)
        if self.shutting_down:  # a shutdown began while it started
            self.stop(running)
        assert child.stdout is not None and child.stderr is not None
        await asyncio.gather(self.forward(running, child.stdout, "stdout", execution),
                             self.forward(running, child.stderr, "stderr", execution))
        code = await child.wait()
        for timer in running.shutdown_timers:
            timer.cancel()
        del self.running[child.pid]
        self.guard.remove(child.pid)
        log.close()
        self.exited(running, execution, code)

    async def forward(self, running: Running, stream: asyncio.StreamReader, which: str,
                      execution: int) -> None:
        """Print and log a process's output as its ``output`` setting says."""
        output = running.process.output
        to_screen = output in ("screen", "both") or (output == "log" and which == "stderr")
        while True:
            try:
                raw = await stream.readline()
            except (ValueError, asyncio.LimitOverrunError):
                raw = await stream.read(LINE_LIMIT)
            if not raw:
                return
            line = raw.decode("utf-8", errors="replace").rstrip("\n")
            running.log.write(f"{line}\n")
            self.launch_log.write(f"[{running.label}] {line}\n")
            if to_screen:
                self.screen(f"[{running.label}] {line}\n")

    def exited(self, running: Running, execution: int, code: int) -> None:
        """A process ended: report it, fire handlers, respawn or complete."""
        label, process = running.label, running.process
        self.event(f"exit {label} {code}")
        pid = running.child.pid
        if code == 0:
            self.say(label, f"process has finished cleanly [pid {pid}]")
        else:
            self.say(label, f"process has died [pid {pid}, exit code {code}, cmd "
                     f"'{' '.join(process.command.argv)}'].", level="ERROR")
            if not running.signalled:
                self.failures.append(f"{label} exited with {code}")
        self.fire("process_exit", execution)
        retries = self.retries.get(execution, 0)
        if (process.respawn and not self.shutting_down
                and (process.respawn_max_retries is None or process.respawn_max_retries < 0
                     or retries < process.respawn_max_retries)):
            self.retries[execution] = retries + 1
            self.event(f"respawn {label}")
            loop = asyncio.get_running_loop()
            handle: asyncio.TimerHandle

            def again() -> None:
                self.timers.discard(handle)
                self.start(execution, respawn=True)
                self.check_done()

            handle = loop.call_later(process.respawn_delay or 0.0, again)
            self.timers.add(handle)
            return
        self.fire("execution_complete", execution)

    # ------------------------------------------------------------------ shutdown

    def shutdown(self, reason: str, *, escalate: bool = False) -> None:
        """Shut the launch down: cancel timers, stop every process with escalation."""
        if self.shutting_down:
            return
        self.shutting_down = True
        self.event(f"shutdown {reason}")
        self.say("launch", f"shutdown requested: {reason}")
        for timer in list(self.timers):
            timer.cancel()
        self.timers.clear()
        for number in sorted(self.active - self.spent):
            handler = self.plan.handlers[number]
            if handler.event == "shutdown":
                if handler.once:
                    self.spent.add(number)
                self.event(f"handler shutdown {handler.origin.span.short()}")
                self.execute_block(number)
        for running in list(self.running.values()):
            self.stop(running)
            if escalate:
                self.send(running, signal.SIGTERM)
        self.check_done()

    def stop(self, running: Running) -> None:
        """SIGINT now, SIGTERM after sigterm_timeout, SIGKILL after sigkill_timeout more."""
        if running.signalled:
            return
        running.signalled = True
        loop = asyncio.get_running_loop()
        process = running.process
        self.send(running, signal.SIGINT)
        running.shutdown_timers.append(loop.call_later(
            process.sigterm_timeout, self.escalate, running, signal.SIGTERM,
            process.sigterm_timeout))
        running.shutdown_timers.append(loop.call_later(
            process.sigterm_timeout + process.sigkill_timeout, self.escalate, running,
            signal.SIGKILL, process.sigkill_timeout))

    def escalate(self, running: Running, number: signal.Signals, waited: float) -> None:
        if running.child.returncode is not None:
            return
        previous = "SIGINT" if number == signal.SIGTERM else "SIGTERM"
        self.say(running.label, f"failed to terminate '{waited:g}' seconds after receiving "
                 f"'{previous}', escalating to '{number.name}'", level="ERROR")
        self.send(running, number)

    def send(self, running: Running, number: signal.Signals) -> None:
        """Signal a process's whole group."""
        if running.child.returncode is not None:
            return
        running.signalled = True
        self.event(f"signal {running.label} {number.name}")
        with contextlib.suppress(ProcessLookupError, PermissionError):
            os.killpg(running.child.pid, number)

    def kill_everything(self) -> None:
        """Leave nothing behind: SIGKILL every process group still alive."""
        for running in list(self.running.values()):
            with contextlib.suppress(ProcessLookupError, PermissionError):
                os.killpg(running.child.pid, signal.SIGKILL)
        for pid in list(self.running):
            with contextlib.suppress(ChildProcessError):
                os.waitpid(pid, 0)

    # ------------------------------------------------------------------ components

    def load_components(self, execution: int) -> None:
        """Load an action's composable nodes into their container, as launch_ros does."""
        commands = self.plan.components.get(execution)
        if not commands:
            return
        if self.ros2 is None:
            for argv in commands:
                self.event(f"component {argv[3]}/{argv[4]} not loaded")
            return
        task = asyncio.get_running_loop().create_task(self.ros2_load(commands))
        self.tasks.add(task)
        task.add_done_callback(self.task_done)

    async def ros2_load(self, commands: list[list[str]]) -> None:
        """Run ``ros2 component load`` for each component, waiting for the container."""
        for argv in commands:
            failure = await self.ros2_call(argv, attempts=40)
            if self.shutting_down:
                return
            if failure is None:
                self.event(f"component {argv[3]}/{argv[4]} loaded into {argv[2]}")
            else:
                self.say("launch", f"failed to load {argv[4]} into {argv[2]}: {failure}",
                         level="ERROR")

    async def ros2_call(self, argv: list[str], attempts: int) -> str | None:
        """Run ``ros2 ARGV`` until it succeeds, retrying while what it addresses comes up.

        Returns ``None`` on success (or when a shutdown stops the retries), else what the
        last attempt printed.
        """
        assert self.ros2 is not None
        output = b""
        for _attempt in range(attempts):
            if self.shutting_down:
                return None
            child = await asyncio.create_subprocess_exec(
                self.ros2, *argv, stdout=asyncio.subprocess.PIPE,
                stderr=asyncio.subprocess.STDOUT, start_new_session=True)
            output, _ = await child.communicate()
            if child.returncode == 0:
                return None
            await asyncio.sleep(0.5)
        return output.decode(errors="replace").strip()

    # ------------------------------------------------------------------ lifecycle

    def lifecycle(self, request: TransitionRequest) -> None:
        """Ask lifecycle nodes to change state through ``ros2 lifecycle set``."""
        targets = self.lifecycle_targets(request)
        words = [transition_label(self.graph.base(t) or t.describe())
                 for t in request.transitions]
        for fqn in targets:
            self.transition(fqn, words)

    def lifecycle_targets(self, request: TransitionRequest) -> list[str]:
        if request.matcher == "action":
            return [p.lifecycle_fqn for p in self.plan.processes.values()
                    if p.lifecycle_fqn and self.plan.action(p.execution) is request.target]
        if request.matcher == "name":
            names = [self.graph.base(n) for n in request.names]
            return [n if n.startswith("/") else "/" + n for n in names if n]
        return []

    def transition(self, fqn: str, words: list[str]) -> None:
        if self.ros2 is None:
            if not self.lifecycle_warned:
                self.say("launch", "lifecycle transitions are not performed: the ROS 2 "
                         "command line (ros2) is not installed", level="WARNING")
                self.lifecycle_warned = True
            self.event(f"lifecycle {fqn} {' '.join(words)} not performed")
            return
        task = asyncio.get_running_loop().create_task(self.ros2_transitions(fqn, words))
        self.tasks.add(task)
        task.add_done_callback(self.task_done)

    async def ros2_transitions(self, fqn: str, words: list[str]) -> None:
        """Take a node through transitions in order, stopping at the first that fails."""
        for word in words:  # the node's services may not be up yet: retried
            failure = await self.ros2_call(["lifecycle", "set", fqn, word], attempts=20)
            if self.shutting_down:
                return
            if failure is not None:
                self.say("launch", f"lifecycle transition '{word}' of {fqn} failed: "
                         f"{failure}", level="ERROR")
                return
            self.event(f"lifecycle {fqn} {word}")


def _send_to_devnull(out: TextIO) -> None:
    """Point a stream whose reader has gone at devnull: what it still holds goes there.

    (Else the interpreter's last flush would fail on it again.)
    """
    try:
        descriptor = out.fileno()
    except (AttributeError, OSError, ValueError):  # not a file (a test's buffer)
        return
    devnull = os.open(os.devnull, os.O_WRONLY)
    try:
        os.dup2(devnull, descriptor)
    finally:
        os.close(devnull)
