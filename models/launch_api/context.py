"""Models of ``LaunchContext`` and ``launch.utilities``, for OpaqueFunction bodies.

An OpaqueFunction runs with a concrete context: the launch configurations as they are
under the arguments being evaluated. Performing a substitution there gives a string; what
is unknown comes back as a placeholder.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterable
from pathlib import Path
from types import SimpleNamespace
from typing import Any

from launchverify.models.launch_api.base import Substitution
from launchverify.models.launch_api.launch_substitutions import TextSubstitution


class LaunchContext:
    """``launch.LaunchContext`` as an OpaqueFunction sees it."""

    def __init__(self, argv: Any = None, *, noninteractive: bool = False,
                 configurations: dict[str, str] | None = None,
                 performer: Callable[[Any], str] | None = None,
                 condition_evaluator: Callable[[Any], bool] | None = None,
                 launch_file: str = "") -> None:
        self.argv = list(argv or [])
        self.noninteractive = noninteractive
        self.launch_configurations = RecordingDict(configurations or {})
        if performer is None:  # a context the launch file made itself: a fresh one
            from launchverify.models.launch_api import runtime

            tools = runtime.current.context_tools if runtime.current is not None else None
            if tools is not None:
                performer, condition_evaluator = tools(self.launch_configurations)
        self._performer = performer
        self._condition_evaluator = condition_evaluator
        self.locals = SimpleNamespace(
            current_launch_file_path=launch_file,
            current_launch_file_directory=str(Path(launch_file).parent),
            launch_configurations=self.launch_configurations,
        )
        self.environment = os.environ

    def perform_substitution(self, substitution: Any) -> str:
        """Return the value of a substitution under this context's configurations."""
        if self._performer is None:
            raise RuntimeError("this LaunchContext cannot perform substitutions")
        return self._performer(substitution)

    def evaluate_condition(self, condition: Any) -> bool:
        """Return whether a condition holds under this context's configurations."""
        if self._condition_evaluator is None:
            raise RuntimeError("this LaunchContext cannot evaluate conditions")
        return self._condition_evaluator(condition)

    def get_locals_as_dict(self) -> dict[str, Any]:
        """Return the locals (launch's API)."""
        return dict(vars(self.locals))

    def extend_locals(self, new_locals: dict[str, Any]) -> None:
        """Add locals (launch's API)."""
        for key, value in new_locals.items():
            setattr(self.locals, key, value)

    def register_event_handler(self, event_handler: Any, append: bool = False) -> None:
        """Accept a handler registration (statically nothing happens)."""


class MissingConfiguration(KeyError):
    """A configuration the OpaqueFunction reads but nobody set."""

    @property
    def configuration(self) -> str:
        """Return the name read."""
        return str(self.args[0])


class RecordingDict(dict[str, str]):
    """The configurations an OpaqueFunction sees; remembers which ones it read."""

    def __init__(self, values: dict[str, str]) -> None:
        super().__init__(values)
        self.read: list[tuple[str, bool, bool]] = []  # name, found, has a default

    def __getitem__(self, key: str) -> str:
        found = super().__contains__(key)
        self.read.append((key, found, False))
        if not found:
            raise MissingConfiguration(key)
        return super().__getitem__(key)

    def get(self, key: str, default: Any = None) -> Any:
        self.read.append((key, super().__contains__(key), True))
        return super().get(key, default)

    def __contains__(self, key: object) -> bool:
        if isinstance(key, str):
            self.read.append((key, super().__contains__(key), True))
        return super().__contains__(key)


def normalize_to_list_of_substitutions(subs: Any) -> list[Any]:
    """``launch.utilities.normalize_to_list_of_substitutions``."""
    if isinstance(subs, (str, Substitution)):
        subs = [subs]
    out: list[Any] = []
    for item in subs:
        out.append(TextSubstitution(text=item) if isinstance(item, str) else item)
    return out


def perform_substitutions(context: LaunchContext, subs: Iterable[Any]) -> str:
    """``launch.utilities.perform_substitutions``."""
    return "".join(context.perform_substitution(s) for s in normalize_to_list_of_substitutions(
        subs))


def perform_typed_substitution(context: LaunchContext, value: Any, data_type: Any) -> Any:
    """``launch.utilities.type_utils.perform_typed_substitution`` (strings only)."""
    return perform_substitutions(context, value) if not isinstance(value, bool) else value
