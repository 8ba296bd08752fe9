"""The machine a launch file's code asks about: the robot's, which launchverify cannot see.

A launch file (or a vendor's helper it imports) may ask the machine things while it is
loaded: run ``ros2 component types`` and read the output, ask for the host name, look
whether ``/etc/robot/robot.yaml`` exists. On the robot the answers are real. Here nothing
is run and the robot's files are not there, so the answers are unknown values:

- a command (``subprocess``, ``os.system``, ``os.popen``) runs nothing (an LV003 says
  so) and gives an unknown result, whatever is asked of it (its output, its return code);
- the host name is unknown, and so is what the user types at a prompt (``input()``);
- whether a file outside what launchverify sees exists (``os.path.exists``,
  ``Path.is_file``...) is an assumption (``assumed``): "yes" in the plain world (the
  launch is written for a robot that has its files), "no" in the varied one, so a
  failure resting on it is not an error;
- reading such a file, by the launch file or by a library it calls (a vendor's helper
  reading ``/etc/robot/robot.yaml``), gives its content as unknown.

launchverify's own code keeps Python's real functions. The audit hook and the worker's
confinement stay the backstop: nothing here is what keeps a command from running.
"""

from __future__ import annotations

import builtins
import io
import os
import pathlib
import socket
import subprocess
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

from launchverify.frontends.python.sandbox import note_refusal
from launchverify.models.launch_api.placeholders import assumed, has_placeholder
from launchverify.models.launch_api.unknown import Opaque
from launchverify.own_code import for_launchverify

_COMMANDS = ("run", "call", "check_call", "check_output", "Popen", "getoutput",
             "getstatusoutput")


def _command(module: str, name: str) -> Callable[..., Any]:
    def run(*args: Any, **kwargs: Any) -> Any:
        command = args[0] if args else kwargs.get("args", kwargs.get("cmd", ""))
        shown = " ".join(map(str, command)) if isinstance(command, (list, tuple)) else command
        note_refusal(f"{module}.{name} would run {str(shown)[:60]!r} while the file "
                     "is loaded; its result is unknown")
        return Opaque(f"what the command {str(shown)[:60]!r} gives on the robot")

    run.__name__ = name
    return run


def _hostname() -> str:
    return Opaque("the robot's host name")


def _typed(prompt: Any = "") -> str:
    """``input()``: what the user types at the launch's prompt (launchverify's stdin is not it)."""
    return Opaque("what the user types at the prompt")


def _judged(found: bool, path: Any, seen: Callable[[str], bool]) -> bool:
    """Return whether a file exists, as the robot would say: unknown outside what is seen."""
    if found:
        return True
    try:
        text = os.fspath(path)
    except TypeError:
        return False
    text = text.decode(errors="replace") if isinstance(text, bytes) else text
    if has_placeholder(text) or (pathlib.PurePath(text).is_absolute() and not seen(text)):
        return assumed(True, False, f"whether {text} exists on the robot")
    return False


def _existence(real: Callable[[Any], bool], seen: Callable[[str], bool]) -> Callable[[Any], bool]:
    """Wrap an existence check: a file the robot may have is an assumption."""
    def check(path: Any) -> bool:
        if for_launchverify(1):
            return real(path)
        return _judged(real(path), path, seen)

    check.__name__ = getattr(real, "__name__", "exists")
    return check


def _path_existence(real: Callable[..., bool], seen: Callable[[str], bool]) -> Any:
    """Wrap ``Path.exists`` and its kin the same way (a method: the path is ``self``)."""
    def method(self: pathlib.Path, *args: Any, **kwargs: Any) -> bool:
        found = real(self, *args, **kwargs)
        if args or kwargs or for_launchverify(1):
            return found
        return _judged(found, self, seen)

    method.__name__ = real.__name__
    return method


def _opening(real: Callable[..., Any], opener: Callable[..., Any]) -> Callable[..., Any]:
    """Wrap ``open`` for code other than launchverify's: ``opener`` decides what it reads."""
    def open_(file: Any, *args: Any, **kwargs: Any) -> Any:
        if for_launchverify(1):
            return real(file, *args, **kwargs)
        return opener(file, *args, **kwargs)

    return open_


@contextmanager
def robot_machine(seen: Callable[[str], bool], opener: Callable[..., Any]) -> Iterator[None]:
    """Answer a launch file's questions about the machine as unknowns, for a block.

    ``seen(path)``: whether an absolute path lies where launchverify sees the files (the
    workspace, its packages): there a missing file is a fact. ``opener`` is ``open`` as
    the launch file's code gets it (the robot's files read as unknown content).
    """
    patches: list[tuple[Any, str, Any]] = [
        *((subprocess, name, _command("subprocess", name)) for name in _COMMANDS),
        (os, "system", _command("os", "system")),
        (os, "popen", _command("os", "popen")),
        (socket, "gethostname", _hostname),
        (builtins, "input", _typed),
        (builtins, "open", _opening(builtins.open, opener)),
        (io, "open", _opening(io.open, opener)),
    ]
    for owner, name in ((os.path, "exists"), (os.path, "isfile"), (os.path, "isdir"),
                        (os.path, "lexists")):
        patches.append((owner, name, _existence(getattr(owner, name), seen)))
    for name in ("exists", "is_file", "is_dir"):
        patches.append((pathlib.Path, name, _path_existence(getattr(pathlib.Path, name), seen)))
    saved = [(owner, name, getattr(owner, name)) for owner, name, _ in patches]
    for owner, name, stand_in in patches:
        setattr(owner, name, stand_in)
    try:
        yield
    finally:
        for owner, name, original in saved:
            setattr(owner, name, original)
