"""``launchverify run``: verify, then start (embedded, or through the real ``ros2 launch``)."""

from __future__ import annotations

import asyncio
import os
import shutil
import subprocess
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TextIO

from launchverify.engine import CheckOptions, Report, UsageError, run_check
from launchverify.executor.command import install_prefixes
from launchverify.executor.dry_run import describe
from launchverify.executor.plan import PlanError, build_plan
from launchverify.executor.supervisor import Supervisor
from launchverify.rule import Severity


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
    on_checked: Callable[[Report, bool], None] | None = None


def log_root() -> Path:
    """Return where ROS 2 writes logs: ROS_LOG_DIR, else ROS_HOME/log, else ~/.ros/log."""
    if os.environ.get("ROS_LOG_DIR"):
        return Path(os.environ["ROS_LOG_DIR"])
    home = os.environ.get("ROS_HOME")
    return Path(home) / "log" if home else Path.home() / ".ros" / "log"


def run(options: RunOptions, out: TextIO, err: TextIO) -> tuple[int, Report]:
    """Verify the launch file; unless refused, run it. Return the exit code and the check.

    The check sees the real environment (plus ``--env``): ``$(env ...)`` takes the values
    the processes will see, as ros2 launch does.
    """
    options.check.environment = {**os.environ, **options.check.environment}
    report = run_check(options.check)
    refused = any(f.severity is Severity.ERROR for f in report.findings) and not options.force
    if options.on_checked is not None:
        options.on_checked(report, refused)
    if refused:
        return 1, report
    if not report.graphs:
        raise UsageError("nothing to run")
    root = report.graphs[0]
    if options.engine == "ros2":
        return _ros2_launch(options, err), report
    stamp = time.strftime("%Y-%m-%d-%H-%M-%S")
    run_dir = (options.log_dir or log_root()) / f"launchverify-{stamp}-{os.getpid()}"
    workspace = options.check.workspace or _workspace_of(report)
    try:
        plan = build_plan(root, install_prefixes(workspace), run_dir / "params",
                          strict=not options.dry_run)
    except PlanError as error:
        raise UsageError(str(error)) from error
    if options.dry_run:
        from launchverify.render.inert import inert

        for line in describe(plan):  # names and values from the checked files
            out.write(inert(line) + "\n")
        return 0, report
    run_dir.mkdir(parents=True, exist_ok=True)
    err.write(f"launchverify: logging to {run_dir}\n")
    supervisor = Supervisor(plan, run_dir, out, ros2=shutil.which("ros2"))
    return asyncio.run(supervisor.run()), report


def _workspace_of(report: Report) -> Path | None:
    from launchverify.workspace.packages import find_workspace

    return find_workspace(report.graphs[0].root) if report.graphs else None


def _ros2_launch(options: RunOptions, err: TextIO) -> int:
    """Hand the verified file and its arguments to ``ros2 launch``."""
    ros2 = shutil.which("ros2")
    if ros2 is None:
        raise UsageError("--engine ros2 needs the ROS 2 command line (ros2); source your ROS 2 "
                         "installation, or use the embedded engine")
    path = options.check.paths[0]
    argv = [ros2, "launch", str(path), *(f"{k}:={v}" for k, v in options.arguments.items())]
    err.write("launchverify: " + " ".join(argv) + "\n")
    return subprocess.call(argv)
