"""``run --dry-run``: every command the plan would start, and when, starting nothing."""

from __future__ import annotations

import shlex

from launchverify.executor.plan import Plan


def describe(plan: Plan) -> list[str]:
    """Return the plan as lines: the launch's block, then each handler's."""
    lines: list[str] = []
    _block(plan, None, "at launch", lines)
    for number, handler in enumerate(plan.handlers):
        if number in plan.blocks:
            target = "any action" if handler.target is None else _target(plan, handler.target)
            _block(plan, number, f"when {handler.event.replace('_', ' ')} of {target} "
                   f"({handler.origin.span.short()})", lines)
    lines.extend(f"note: {note}" for note in plan.notes)
    return lines


def _target(plan: Plan, action: object) -> str:
    for process in plan.processes.values():
        if plan.action(process.execution) is action:
            return process.name
    return getattr(action, "kind", "an action")


def _block(plan: Plan, within: int | None, title: str, lines: list[str]) -> None:
    entries: list[str] = []
    for delay, execution in plan.blocks.get(within, ()):
        when = f"after {delay:g} s: " if delay else ""
        process = plan.processes.get(execution)
        if process is not None:
            command = process.command
            entries.append(f"  {when}start {process.name}: {shlex.join(command.argv)}")
            if command.cwd:
                entries.append(f"      cwd {command.cwd}")
            for name, value in command.env.items():
                entries.append(f"      env {name}=" + ("(unset)" if value is None else value))
            if command.replace_env is not None:
                entries.append("      env replaced by: " + " ".join(
                    f"{k}={v}" for k, v in command.replace_env.items()))
            for path, text in command.files.items():
                entries.append(f"      writes {path}:")
                entries.extend(f"        {line}" for line in text.splitlines())
            extras = [f"output={process.output}"]
            if process.respawn:
                retries = process.respawn_max_retries
                extras.append(f"respawn (delay {process.respawn_delay:g} s, retries "
                              f"{'unlimited' if retries < 0 else retries})")
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
