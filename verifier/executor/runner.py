"""``launchverify run``: verify, then start (embedded, or through the real ``ros2 launch``).

A run starts the launch under one assignment: the ``name:=value`` given, every other
argument at its default. ``check`` reports what holds for *some* assignment (an LV101
that needs ``use_mock_hardware:=true``); ``run`` refuses only for errors that hold for
this one, and says how many others there are (``Verdict``).
"""

from __future__ import annotations

import asyncio
import dataclasses
import os
import shlex
import shutil
import subprocess
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Protocol, TextIO

from launchverify.engine import CheckOptions, Report, UsageError, build_index, run_check
from launchverify.executor.command import install_prefixes
from launchverify.executor.dry_run import Locate, describe
from launchverify.executor.plan import Plan, PlanError, build_plan
from launchverify.executor.supervisor import Supervisor
from launchverify.rule import Finding, Severity

if TYPE_CHECKING:
    from launchverify.graph import LaunchGraph


@dataclass
class RunOptions:
    """What ``launchverify run`` was asked to do."""

    check: CheckOptions
    dry_run: bool = False
    force: bool = False
    engine: str = "embedded"
    log_dir: Path | None = None
    arguments: dict[str, str] = field(default_factory=dict)
    # told the check's outcome before anything starts (and whether the start is refused)
    on_checked: Callable[[Verdict], None] | None = None


@dataclass
class Verdict:
    """The check as it bears on this run.

    ``report`` holds the findings that hold for the arguments as given (errors for other
    values left out); ``elsewhere`` counts the errors left out, which ``check`` lists.
    """

    report: Report
    refused: bool
    elsewhere: int = 0


def log_root() -> Path:
    """Return where ROS 2 writes logs: ROS_LOG_DIR, else ROS_HOME/log, else ~/.ros/log."""
    if os.environ.get("ROS_LOG_DIR"):
        return Path(os.environ["ROS_LOG_DIR"])
    home = os.environ.get("ROS_HOME")
    return Path(home) / "log" if home else Path.home() / ".ros" / "log"


def run(options: RunOptions, out: TextIO, err: TextIO) -> tuple[int, Report]:
    """Verify the launch file; unless refused, run it. Return the exit code and the check.

    The check sees the real environment (plus ``--env``): ``$(env ...)`` takes the values
    the processes will see, as ros2 launch does. Every decision is made before anything
    starts (``Start``); a dry run prints it and stops there, whatever the engine.
    """
    options.check.environment = {**os.environ, **options.check.environment}
    report = run_check(options.check)
    verdict = judge(options.check, report, force=options.force)
    if options.on_checked is not None:
        options.on_checked(verdict)
    if verdict.refused:
        return 1, report
    if not report.graphs:
        raise UsageError("nothing to run")
    start = prepare(options, report)  # starts nothing
    if options.dry_run:
        from launchverify.render.inert import inert

        for line in start.describe():  # names and values from the checked files
            out.write(inert(line) + "\n")
        return 0, report
    return start.start(out, err), report


DRY_RUN_STAMP, DRY_RUN_PID = "<start time>", "<pid>"  # the run folder's parts a dry run
# cannot know


class Start(Protocol):
    """What a run will start, decided in full; ``start`` is the only way to a process."""

    def describe(self) -> list[str]:
        """Return what ``start`` would do, as ``--dry-run`` prints it."""

    def start(self, out: TextIO, err: TextIO) -> int:
        """Start it; return the launch's exit status."""


def prepare(options: RunOptions, report: Report) -> Start:
    """Return what the run starts under its engine, starting nothing (a refusal raises).

    Only a real run's plan evaluates ``$(command ...)`` (as launch does when it runs).
    """
    root = report.graphs[0]
    workspace = options.check.workspace or _workspace_of(report)
    if options.engine == "ros2":
        return Ros2Launch(_ros2_argv(options), root, workspace, options.check.paths)
    # a dry run names the folder the run would make by its pattern: its time and process
    # id are the run's, not known before it starts (and nothing is made now)
    stamp, pid = ((DRY_RUN_STAMP, DRY_RUN_PID) if options.dry_run
                  else (time.strftime("%Y-%m-%d-%H-%M-%S"), str(os.getpid())))
    run_dir = (options.log_dir or log_root()) / f"launchverify-{stamp}-{pid}"
    try:
        plan = build_plan(root, install_prefixes(workspace), run_dir / "params",
                          strict=not options.dry_run)
    except PlanError as error:
        raise UsageError(str(error), lines=True) from error
    return Embedded(plan, run_dir, workspace, options.check.paths)


@dataclass
class Embedded:
    """A run of the plan by launchverify's own engine (``supervisor.py``)."""

    plan: Plan
    run_dir: Path
    workspace: Path | None
    paths: list[Path]

    def describe(self) -> list[str]:
        lines = describe(self.plan, _locate(self.paths, self.workspace))
        if any(process.command.files for process in self.plan.processes.values()):
            lines.append(f"note: the run makes its folder {self.run_dir} when it starts "
                         f"({DRY_RUN_STAMP} and {DRY_RUN_PID} its own) and writes each "
                         "parameter file there before the process that reads it")
        return lines

    def start(self, out: TextIO, err: TextIO) -> int:
        self.run_dir.mkdir(parents=True, exist_ok=True)
        err.write(f"launchverify: logging to {self.run_dir}\n")
        supervisor = Supervisor(self.plan, self.run_dir, out, ros2=shutil.which("ros2"))
        return asyncio.run(supervisor.run())


@dataclass
class Ros2Launch:
    """The verified file handed to the real ``ros2 launch``.

    ros2 launch evaluates the file itself, its Python in ros2 launch's own process: a dry
    run cannot ask it what it would start (``ros2 launch --print`` runs that Python too).
    It shows the commands as the check evaluated them instead, then the handover.
    """

    argv: list[str]
    root: LaunchGraph
    workspace: Path | None
    paths: list[Path]

    def describe(self) -> list[str]:
        handover = f"run {shlex.join(self.argv)}"
        try:
            plan = build_plan(self.root, install_prefixes(self.workspace),
                              Path("<parameter files of ros2 launch>"), strict=False)
        except PlanError as error:
            first, *more = error.lines()
            return [handover, f"note: what it starts is known only when it runs: {first}",
                    *more]
        return [handover, *describe(plan, _locate(self.paths, self.workspace)),
                "note: ros2 launch evaluates the file itself (its Python unconfined) and "
                "builds its own commands: those above are the check's evaluation of them"]

    def start(self, out: TextIO, err: TextIO) -> int:
        err.write("launchverify: " + " ".join(self.argv) + "\n")
        return subprocess.call(self.argv)


def judge(check: CheckOptions, report: Report, *, force: bool = False) -> Verdict:
    """Return which of the check's errors hold for the arguments as given.

    An error may hold only for argument values the run does not use: decided by a second
    check where every argument the root declares is pinned to its default (those given
    keep their value), as ``ros2 launch`` would set them. A default written with another
    argument or a variable takes the value the evaluator gives it under the rest; one it
    cannot know before the launch runs (a command's output) stays free, and its errors
    refuse the start.
    """
    if not _errors(report.findings) or not report.graphs:
        return Verdict(report, refused=bool(_errors(report.findings)) and not force)
    defaults = {name: value for name, value in _defaults(report.graphs[0]).items()
                if name not in check.arguments}
    if not defaults:  # nothing more to pin: the check already was the run's
        return Verdict(report, refused=not force)
    pinned = run_check(dataclasses.replace(check, arguments={**defaults, **check.arguments}))
    holding = {_place(f) for f in _errors(pinned.findings)}
    shown = [f for f in report.findings
             if f.severity is not Severity.ERROR or _place(f) in holding]
    seen = {_place(f) for f in shown}
    shown += [f for f in _errors(pinned.findings) if _place(f) not in seen]
    shown.sort(key=Finding.sort_key)
    elsewhere = sum(1 for f in _errors(report.findings) if _place(f) not in holding)
    return Verdict(dataclasses.replace(report, findings=shown),
                   refused=bool(holding) and not force, elsewhere=elsewhere)


def _errors(findings: list[Finding]) -> list[Finding]:
    return [f for f in findings if f.severity is Severity.ERROR]


def _place(finding: Finding) -> tuple[object, ...]:
    """Return what identifies a finding across the two checks (messages may differ)."""
    return (finding.code, str(finding.span.file), finding.span.line, finding.span.column)


def _defaults(graph: LaunchGraph) -> dict[str, str]:
    """Return the defaults of the root file's arguments, declared for sure, when known.

    Only the root's: an included file's arguments take what its include passes.
    """
    found: dict[str, str] = {}
    for argument in graph.arguments:
        if argument.origin.chain or graph.runs(argument.origin) is not True:
            continue
        value = graph.base(argument.default)  # under the given arguments and defaults
        if value is not None:
            found.setdefault(argument.name, value)  # launch keeps the first declaration's
    return found


def _workspace_of(report: Report) -> Path | None:
    """Return the check's workspace (its ``install/`` holds what the run starts)."""
    if report.workspace is not None:
        return report.workspace.folder
    from launchverify.workspace.packages import find_workspace

    return find_workspace(report.graphs[0].root) if report.graphs else None


def _ros2_argv(options: RunOptions) -> list[str]:
    """Return the ``ros2 launch`` command of the verified file and its arguments.

    The file is named by an absolute path: one starting with ``-`` is not an option.
    """
    ros2 = shutil.which("ros2")
    if ros2 is None:
        raise UsageError("--engine ros2 needs the ROS 2 command line (ros2); source your ROS 2 "
                         "installation, or use the embedded engine")
    path = Path(options.check.paths[0]).absolute()
    return [ros2, "launch", str(path), *(f"{k}:={v}" for k, v in options.arguments.items())]


def _locate(paths: list[Path], workspace: Path | None) -> Locate:
    """Return where a file named through a package is in its sources (``describe``)."""
    _, index = build_index(paths, workspace)
    return index.locate
