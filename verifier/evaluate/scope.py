"""Launch configurations and environment, scoped exactly as ros2/launch scopes them.

Configurations are one flat dict per scope; pushing a scope makes a *shallow* copy, so the
lists launch_ros keeps there (``ros_remaps``, ``global_params``) are shared with the outer
scope once they exist: a ``SetRemap`` inside a group then leaks out, as it does in launch.
Values are residual expressions; under a symbolic path condition an assignment becomes a
``Select`` between the new and the old value.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from launchverify.ir.subst import Sub, Text
from launchverify.ir.symbolic import PathCondition, Select, Unknown, Unset

ROS_NAMESPACE = "ros_namespace"
ROS_REMAPS = "ros_remaps"
GLOBAL_PARAMS = "global_params"


@dataclass(frozen=True, slots=True)
class ScopedRemap:
    """A ``SetRemap`` rule as stored in the scope, with the path it was set under."""

    src: Sub
    dst: Sub
    origin: Any
    path: PathCondition


@dataclass(frozen=True, slots=True)
class ScopedParam:
    """A ``SetParameter`` value or ``SetParametersFromFile`` file in scope."""

    origin: Any
    path: PathCondition
    name: Sub | None = None
    value: object = None
    file: Sub | None = None
    value_type: str | None = None
    source: Any = None  # the parameter file read (a Path), when it is in the workspace


MAX_VALUE_SIZE = 2000
MAX_TEXT_SIZE = 100_000  # characters


def guarded(path: PathCondition, new: Sub, old: Sub | None, name: str,
            measures: Measures | None = None) -> Sub:
    """Return the value after an assignment made under ``path``.

    A value that grows past ``MAX_VALUE_SIZE`` parts or ``MAX_TEXT_SIZE`` characters (a
    file doubling a configuration, say) becomes unknown instead of exponentially large.
    """
    if path:
        previous = Unset(name) if old is None else old
        if previous != new:
            new = Select(path, new, previous)
    if (measures or Measures()).too_large(new):
        return Unknown(f"value of {name} (too complex to follow)")
    return new


class Measures:
    """The sizes of the values one evaluation assigned, so that each is measured once.

    An assignment under a condition wraps the previous value in a ``Select``: measuring
    the new value from scratch would walk the whole chain again at every assignment. Sizes
    are kept per object (the object too, so that its id stays its own).
    """

    def __init__(self) -> None:
        self._known: dict[int, tuple[Sub, int, int]] = {}  # id -> (value, parts, chars)

    def too_large(self, value: Sub) -> bool:
        """Return whether a value is past either limit (shared parts: see ``text_size``)."""
        if type(value) is Text:  # most values: one part, measured here, not remembered
            return len(value.text) > MAX_TEXT_SIZE
        parts, chars = self._measure(value)
        if parts > MAX_VALUE_SIZE:
            return True
        # ``chars`` counts a shared part each time: past the limit, count it once.
        return chars > MAX_TEXT_SIZE and text_size(value) > MAX_TEXT_SIZE

    def _measure(self, value: Sub) -> tuple[int, int]:
        known = self._known.get(id(value))
        if known is not None:
            return known[1], known[2]
        parts, chars = 1, len(value.text) if isinstance(value, Text) else 0
        for child in value.children():  # each distinct part once: linear even in a doubled value
            if type(child) is Text:  # most parts: measured here, not remembered
                child_parts, child_chars = 1, len(child.text)
            else:
                child_parts, child_chars = self._measure(child)
            parts = min(parts + child_parts, MAX_VALUE_SIZE + 1)
            chars = min(chars + child_chars, MAX_TEXT_SIZE + 1)
        self._known[id(value)] = (value, parts, chars)
        return parts, chars


def text_size(sub: Sub) -> int:
    """Return how many characters of literal text a value holds (each shared part once)."""
    seen: set[int] = set()
    total = 0
    stack = [sub]
    while stack:
        item = stack.pop()
        if id(item) in seen:
            continue
        seen.add(id(item))
        if isinstance(item, Text):
            total += len(item.text)
        stack.extend(item.children())
    return total


@dataclass(frozen=True, slots=True)
class ScopeState:
    """A copy of every scope of one evaluation, to run deferred entities from later.

    launch runs an event handler's entities with the configurations and environment that
    are current when the event is handled, not those where the handler was registered.
    """

    configs: dict[str, Any]
    env: dict[str, Sub | None]
    overrides: dict[str, Any]
    config_stack: tuple[dict[str, Any], ...]
    env_stack: tuple[dict[str, Sub | None], ...]
    override_stack: tuple[dict[str, Any], ...]


def _own_lists(scopes: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """Copy scopes with lists of their own (``ros_remaps``/``global_params`` are appended to).

    A list shared by two scopes (a pushed scope is a shallow copy) stays shared by the copies.
    """
    copies: dict[int, list[Any]] = {}
    return [{k: copies.setdefault(id(v), list(v)) if isinstance(v, list) else v
             for k, v in scope.items()} for scope in scopes]


class Scopes:
    """The stack of configuration and environment scopes of one evaluation."""

    def __init__(self, configs: dict[str, Any]) -> None:
        self.configs: dict[str, Any] = dict(configs)
        self.env: dict[str, Sub | None] = {}
        self._config_stack: list[dict[str, Any]] = []
        self._env_stack: list[dict[str, Sub | None]] = []
        # arguments whose value a later <let>/SetLaunchConfiguration replaced: where
        self.overrides: dict[str, Any] = {}
        self._override_stack: list[dict[str, Any]] = []
        self.measures = Measures()

    def state(self) -> ScopeState:
        """Return a copy of every scope, which later changes here do not touch."""
        *stack, configs = _own_lists([*self._config_stack, self.configs])
        return ScopeState(configs, dict(self.env), dict(self.overrides), tuple(stack),
                          tuple(dict(e) for e in self._env_stack),
                          tuple(dict(o) for o in self._override_stack))

    def restore(self, state: ScopeState) -> None:
        """Make the scopes a copy of ``state`` (which stays as it was)."""
        *self._config_stack, self.configs = _own_lists([*state.config_stack, state.configs])
        self.env = dict(state.env)
        self.overrides = dict(state.overrides)
        self._env_stack = [dict(e) for e in state.env_stack]
        self._override_stack = [dict(o) for o in state.override_stack]

    # launch's PushLaunchConfigurations / PopLaunchConfigurations
    def push_configs(self) -> None:
        """Enter a scope: the new scope starts as a shallow copy."""
        self._config_stack.append(self.configs)
        self.configs = dict(self.configs)
        self._override_stack.append(self.overrides)
        self.overrides = dict(self.overrides)

    def pop_configs(self) -> bool:
        """Leave a scope; return ``False`` if there was none (launch raises)."""
        if not self._config_stack:
            return False
        self.configs = self._config_stack.pop()
        self.overrides = self._override_stack.pop()
        return True

    def push_env(self) -> None:
        """Enter an environment scope."""
        self._env_stack.append(self.env)
        self.env = dict(self.env)

    def pop_env(self) -> bool:
        """Leave an environment scope; ``False`` if there was none."""
        if not self._env_stack:
            return False
        self.env = self._env_stack.pop()
        return True

    def reset_env(self) -> None:
        """Forget every change the launch made to the environment."""
        self.env = {}

    def set(self, name: str, value: Sub, path: PathCondition, *,
            unset: Sub | None = None) -> None:
        """Set a configuration under a path condition.

        Where the path does not hold, the old value stays; ``unset`` says what a
        configuration that was never set means to its readers (``None``: reading fails).
        """
        old = self.configs.get(name)
        self.configs[name] = guarded(path, value, unset if old is None else old, name,
                                     self.measures)

    def get(self, name: str) -> Sub | None:
        """Return a configuration's value, or ``None`` when it was never set."""
        value = self.configs.get(name)
        return value if isinstance(value, Sub) else None

    def append_shared(self, key: str, item: object) -> None:
        """Append to ``ros_remaps``/``global_params`` the way launch_ros does (in place)."""
        items = self.configs.get(key, [])
        items.append(item)
        self.configs[key] = items

    def shared(self, key: str) -> list[Any]:
        """Return the ``ros_remaps``/``global_params`` list in scope."""
        return list(self.configs.get(key, []))
