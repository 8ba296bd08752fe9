"""``run --dry-run``: every command the plan would start, and when, starting nothing."""

from __future__ import annotations

import shlex
from collections.abc import Callable
from pathlib import Path

from launchverify.executor.plan import Plan
from launchverify.workspace.paths import display_path

Locate = Callable[[Path], Path | None]


def describe(plan: Plan, locate: Locate | None = None) -> list[str]:
    """Return the plan as lines: the launch's block, then each handler's.

    ``locate`` finds a file named through a package that is not built in its sources:
    ``$(find-pkg-share pkg)/config/x.yaml`` is then a path nobody can open (CMake installs
    ``bringup/config`` there), so the file the user can open is named under the command.
    """
    lines: list[str] = []
    _block(plan, None, "at launch", lines, locate)
    for number, handler in enumerate(plan.handlers):
        if number in plan.blocks:
            target = "any action" if handler.target is None else _target(plan, handler.target)
            _block(plan, number, f"when {handler.event.replace('_', ' ')} of {target} "
                   f"({handler.origin.span.short()})", lines, locate)
    lines.extend(f"note: {note}" for note in plan.notes)
    return lines


def _target(plan: Plan, action: object) -> str:
    for process in plan.processes.values():
        if plan.action(process.execution) is action:
            return process.name
    return getattr(action, "kind", "an action")


def _sources(argv: list[str], locate: Locate | None) -> list[str]:
    """Return a line for each path argument that exists only in a package's sources."""
    found = []
    for argument in argv:
        if locate is None or not argument.startswith("/") or Path(argument).exists():
            continue
        source = locate(Path(argument))
        if source is not None:
            found.append(f"      {argument}: not built here, installed from "
                         f"{display_path(source)}")
    return found


def _block(plan: Plan, within: int | None, title: str, lines: list[str],
           locate: Locate | None) -> None:
    entries: list[str] = []
    for delay, execution in plan.blocks.get(within, ()):
        when = f"after {delay:g} s: " if delay else ""
        process = plan.processes.get(execution)
        if process is not None:
            command = process.command
            entries.append(f"  {when}start {process.name}: {shlex.join(command.argv)}")
            entries.extend(_sources(command.argv, locate))
            if command.cwd:
                entries.append(f"      cwd {command.cwd}")
            for name, value in command.env.items():
                entries.append(f"      env {name}=" + ("(unset)" if value is None else value))
            if command.replace_env is not None:
                entries.append("      env replaced by: " + " ".join(
                    f"{k}={v}" for k, v in command.replace_env.items()))
            for path, text in command.files.items():
                entries.append(f"      would write {path} first:")
                entries.extend(f"        {line}" for line in text.splitlines())
            extras = [f"output={process.output}"]
            if process.respawn:
                retries = process.respawn_max_retries
                extras.append(f"respawn (delay {process.respawn_delay or 0.0:g} s, retries "
                              f"{'unlimited' if retries is None or retries < 0 else retries})")
            extras.append(f"sigterm_timeout={process.sigterm_timeout:g}")
            entries.append("      " + ", ".join(extras))
        elif (log := plan.log(execution)) is not None:
            entries.append(f"  {when}log {log[0]}: {log[1]}")
        elif plan.shutdown_reason(execution) is not None:
            entries.append(f"  {when}shut down")
        for request in plan.requests.get(execution, ()):
            entries.append(f"  {when}lifecycle request at {request.origin.span.short()}")
        for argv in plan.components.get(execution, ()):
            entries.append(f"  {when}ros2 {shlex.join(argv)}")
    if entries:
        lines.append(title + ":")
        lines.extend(entries)
