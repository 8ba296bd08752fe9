"""Models of ``launch.event_handlers``, ``launch.events`` and their launch_ros siblings.

A handler keeps what the evaluator needs: which event it waits for, the target action
(matched by identity, as launch does) and the entities it yields.
"""

from __future__ import annotations

from typing import Any

from launchverify.models.launch_api.base import Modelled, _unknown, caller_span
from launchverify.models.launch_api.lifecycle_msgs import State, Transition


class EventHandler(Modelled):
    """``EventHandler(*, matcher, entities=None, handle_once=False)``."""

    event_name = "event"
    events: tuple[str, ...] = ()  # the names of the launch events this handler is for
    matcher_description = ""

    def __init__(self, *, matcher: Any = None, entities: Any = None,
                 handle_once: bool = False) -> None:
        self._span = caller_span()
        self.matcher = matcher
        self.entities = entities
        self.handle_once = handle_once
        self.target_action: Any = None

    @property
    def handler_description(self) -> str:
        """Return what the handler does, as launch describes it."""
        return "<actions>" if self.entities else ""

    def matches(self, event: Any) -> bool:
        """Return whether the handler handles ``event`` (launch's API)."""
        if self.matcher is not None:
            return bool(self.matcher(event))
        if type(event).__name__ not in self.events:
            return False
        return self.target_action is None or getattr(event, "action", None) is self.target_action

    def handle(self, event: Any, context: Any) -> Any:
        """Return the entities to run for ``event`` (launch's API)."""
        extend = getattr(context, "extend_locals", None)
        if extend is not None:
            extend({"event": event})
        return self.entities

    def describe(self) -> tuple[str, list[Any]]:
        """Return a description and the entities (launch's API)."""
        text = (f"{type(self).__name__}(matcher='{self.matcher_description}', "
                f"handler='{self.handler_description}', handle_once={self.handle_once})")
        entities = self.entities
        if not entities or callable(entities):
            return text, []
        return text, list(entities) if isinstance(entities, (list, tuple)) else [entities]


class OnProcessStart(EventHandler):
    """``OnProcessStart(*, target_action=None, on_start)``."""

    event_name = "process_start"
    events = ("ProcessStarted",)
    matcher_description = "event == ProcessStarted"

    def __init__(self, *, target_action: Any = None, on_start: Any, **kwargs: Any) -> None:
        super().__init__(entities=on_start, **kwargs)
        self.target_action = target_action


class OnProcessExit(EventHandler):
    """``OnProcessExit(*, target_action=None, on_exit)``."""

    event_name = "process_exit"
    events = ("ProcessExited",)
    matcher_description = "event == ProcessExited"

    def __init__(self, *, target_action: Any = None, on_exit: Any, **kwargs: Any) -> None:
        super().__init__(entities=on_exit, **kwargs)
        self.target_action = target_action


class OnProcessIO(EventHandler):
    """``OnProcessIO(*, target_action=None, on_stdin=None, on_stdout=None, on_stderr=None)``."""

    event_name = "process_io"
    events = ("ProcessIO", "ProcessStdin", "ProcessStdout", "ProcessStderr")
    matcher_description = "event == ProcessIO"

    def __init__(self, *, target_action: Any = None, on_stdin: Any = None,
                 on_stdout: Any = None, on_stderr: Any = None, **kwargs: Any) -> None:
        callbacks = [f for f in (on_stdin, on_stdout, on_stderr) if f is not None]
        super().__init__(entities=callbacks[0] if callbacks else None, **kwargs)
        self.target_action = target_action


class OnExecutionComplete(EventHandler):
    """``OnExecutionComplete(*, target_action=None, on_completion)``."""

    event_name = "execution_complete"
    events = ("ExecutionComplete",)
    matcher_description = "event == ExecutionComplete"

    def __init__(self, *, target_action: Any = None, on_completion: Any,
                 **kwargs: Any) -> None:
        super().__init__(entities=on_completion, **kwargs)
        self.target_action = target_action


class OnShutdown(EventHandler):
    """``OnShutdown(*, on_shutdown)``."""

    event_name = "shutdown"
    events = ("Shutdown",)
    matcher_description = "event issubclass of launch.events.Shutdown"

    def __init__(self, *, on_shutdown: Any, **kwargs: Any) -> None:
        super().__init__(entities=on_shutdown, **kwargs)


class OnIncludeLaunchDescription(EventHandler):
    """``OnIncludeLaunchDescription()``: launch's own handler."""

    event_name = "include_launch_description"
    events = ("IncludeLaunchDescription",)
    matcher_description = "event issubclass of launch.events.IncludeLaunchDescription"


class OnStateTransition(EventHandler):
    """launch_ros ``OnStateTransition(*, entities, target_lifecycle_node=None, ...)``."""

    event_name = "state_transition"
    events = ("StateTransition",)
    matcher_description = "event == StateTransition"

    def __init__(self, *, entities: Any, target_lifecycle_node: Any = None,
                 transition: str | None = None, start_state: str | None = None,
                 goal_state: str | None = None, matcher: Any = None, **kwargs: Any) -> None:
        from launchverify.models.launch_api.launch_ros import LifecycleNode

        if not isinstance(target_lifecycle_node, (LifecycleNode, type(None))) \
                and not _unknown(target_lifecycle_node):  # a vendor's node: may be one
            raise RuntimeError("OnStateTransition requires a 'LifecycleNode' action as the "
                               "target")
        super().__init__(entities=entities, matcher=matcher, **kwargs)
        self.target_action = target_lifecycle_node
        self.filters = tuple((field, value) for field, value in (
            ("transition", transition), ("start_state", start_state),
            ("goal_state", goal_state)) if value is not None)


# ----------------------------------------------------------------------------- events


class Event(Modelled):
    """Base of the modelled events: records its arguments as details."""

    name = "launch.Event"

    def __init__(self, **details: Any) -> None:
        # a vendor's value is kept as its text (the IR holds plain values)
        self.details = {k: str(v) if _unknown(v) else v for k, v in details.items()
                        if isinstance(v, (str, int, bool))}


class Shutdown(Event):
    """``launch.events.Shutdown(*, reason='reason not given', due_to_sigint=False)``."""

    name = "launch.events.Shutdown"

    def __init__(self, *, reason: str = "reason not given", due_to_sigint: bool = False) -> None:
        super().__init__(reason=reason)
        self.reason, self.due_to_sigint = reason, due_to_sigint


class ShutdownProcess(Event):
    """``launch.events.process.ShutdownProcess(*, process_matcher)``."""

    name = "launch.events.process.ShutdownProcess"

    def __init__(self, *, process_matcher: Any) -> None:
        super().__init__()
        self.process_matcher = process_matcher


class SignalProcess(Event):
    """``launch.events.process.SignalProcess(*, signal_number, process_matcher)``."""

    name = "launch.events.process.SignalProcess"

    def __init__(self, *, signal_number: Any, process_matcher: Any) -> None:
        super().__init__()
        self.signal, self.process_matcher = signal_number, process_matcher

    @property
    def signal_name(self) -> str:
        """Return the signal's name (launch's API)."""
        signal: Any = self.signal
        return signal if isinstance(signal, str) else str(signal.name)


_TRANSITIONS = ("TRANSITION_CREATE", "TRANSITION_CONFIGURE", "TRANSITION_CLEANUP",
                "TRANSITION_ACTIVATE", "TRANSITION_DEACTIVATE",
                "TRANSITION_UNCONFIGURED_SHUTDOWN", "TRANSITION_INACTIVE_SHUTDOWN",
                "TRANSITION_ACTIVE_SHUTDOWN", "TRANSITION_DESTROY")
_STATES = ("PRIMARY_STATE_UNKNOWN", "PRIMARY_STATE_UNCONFIGURED", "PRIMARY_STATE_INACTIVE",
           "PRIMARY_STATE_ACTIVE", "PRIMARY_STATE_FINALIZED", "TRANSITION_STATE_CONFIGURING",
           "TRANSITION_STATE_CLEANINGUP", "TRANSITION_STATE_SHUTTINGDOWN",
           "TRANSITION_STATE_ACTIVATING", "TRANSITION_STATE_DEACTIVATING",
           "TRANSITION_STATE_ERRORPROCESSING")


def _by_id(kind: Any, names: tuple[str, ...]) -> dict[int, str]:
    return {getattr(kind, name): name for name in names}


class ChangeState(Event):
    """launch_ros ``ChangeState(*, lifecycle_node_matcher, transition_id)``."""

    name = "launch_ros.events.lifecycle.ChangeState"
    valid_transitions = _by_id(Transition, _TRANSITIONS)
    valid_states = _by_id(State, _STATES)

    def __init__(self, *, lifecycle_node_matcher: Any, transition_id: int) -> None:
        super().__init__(transition_id=transition_id)
        if not _unknown(transition_id) and transition_id not in range(9):  # a vendor's id: any
            raise ValueError(f"given transition_id of '{transition_id}', expected one of "
                             "{0, 1, 2, 3, 4, 5, 6, 7, 8}")
        self.lifecycle_node_matcher = lifecycle_node_matcher
        self.transition_id = transition_id


class StateTransition(Event):
    """launch_ros ``StateTransition``."""


class ActionMatcher:
    """What ``matches_action`` returns: true for one action object (identity)."""

    def __init__(self, target: Any) -> None:
        self.target = target

    def __call__(self, action: Any) -> bool:
        return action is self.target


class NodeNameMatcher:
    """What ``matches_node_name`` returns: true for the node with that name (``/`` added)."""

    def __init__(self, node_name: Any) -> None:
        self.node_name = node_name

    def __call__(self, action: Any) -> bool:
        return bool(getattr(action, "node_name", None) == self.node_name)


def matches_action(target_action: Any) -> ActionMatcher:
    """``launch.events.matches_action``: a matcher on one action object."""
    return ActionMatcher(target_action)


def matches_node_name(node_name: Any) -> NodeNameMatcher:
    """launch_ros ``matches_node_name``."""
    if isinstance(node_name, str) and not node_name.startswith("/"):
        node_name = "/" + node_name
    return NodeNameMatcher(node_name)
