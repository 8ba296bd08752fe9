"""Models of ``launch.event_handlers``, ``launch.events`` and their launch_ros siblings.

A handler keeps what the evaluator needs: which event it waits for, the target action
(matched by identity, as launch does) and the entities it yields.
"""

from __future__ import annotations

from typing import Any

from launchverify.models.launch_api.base import caller_span


class EventHandler:
    """``EventHandler(*, matcher, entities=None, handle_once=False)``."""

    event_name = "event"

    def __init__(self, *, matcher: Any = None, entities: Any = None,
                 handle_once: bool = False) -> None:
        self._span = caller_span()
        self.matcher = matcher
        self.entities = entities
        self.handle_once = handle_once
        self.target_action: Any = None

    def describe(self) -> tuple[str, list[Any]]:
        """Return a description and the entities (launch's API)."""
        return type(self).__name__, list(self.entities or [])


class OnProcessStart(EventHandler):
    """``OnProcessStart(*, target_action=None, on_start)``."""

    event_name = "process_start"

    def __init__(self, *, target_action: Any = None, on_start: Any, **kwargs: Any) -> None:
        super().__init__(entities=on_start, **kwargs)
        self.target_action = target_action


class OnProcessExit(EventHandler):
    """``OnProcessExit(*, target_action=None, on_exit)``."""

    event_name = "process_exit"

    def __init__(self, *, target_action: Any = None, on_exit: Any, **kwargs: Any) -> None:
        super().__init__(entities=on_exit, **kwargs)
        self.target_action = target_action


class OnProcessIO(EventHandler):
    """``OnProcessIO(*, target_action=None, on_stdin=None, on_stdout=None, on_stderr=None)``."""

    event_name = "process_io"

    def __init__(self, *, target_action: Any = None, on_stdin: Any = None,
                 on_stdout: Any = None, on_stderr: Any = None, **kwargs: Any) -> None:
        callbacks = [f for f in (on_stdin, on_stdout, on_stderr) if f is not None]
        super().__init__(entities=callbacks[0] if callbacks else None, **kwargs)
        self.target_action = target_action


class OnExecutionComplete(EventHandler):
    """``OnExecutionComplete(*, target_action=None, on_completion)``."""

    event_name = "execution_complete"

    def __init__(self, *, target_action: Any = None, on_completion: Any,
                 **kwargs: Any) -> None:
        super().__init__(entities=on_completion, **kwargs)
        self.target_action = target_action


class OnShutdown(EventHandler):
    """``OnShutdown(*, on_shutdown)``."""

    event_name = "shutdown"

    def __init__(self, *, on_shutdown: Any, **kwargs: Any) -> None:
        super().__init__(entities=on_shutdown, **kwargs)


class OnIncludeLaunchDescription(EventHandler):
    """``OnIncludeLaunchDescription()``: launch's own handler."""

    event_name = "include_launch_description"


class OnStateTransition(EventHandler):
    """launch_ros ``OnStateTransition(*, entities, target_lifecycle_node=None, ...)``."""

    event_name = "state_transition"

    def __init__(self, *, entities: Any, target_lifecycle_node: Any = None,
                 transition: str | None = None, start_state: str | None = None,
                 goal_state: str | None = None, matcher: Any = None, **kwargs: Any) -> None:
        from launchverify.models.launch_api.launch_ros import LifecycleNode

        if not isinstance(target_lifecycle_node, (LifecycleNode, type(None))):
            raise RuntimeError("OnStateTransition requires a 'LifecycleNode' action as the "
                               "target")
        super().__init__(entities=entities, matcher=matcher, **kwargs)
        self.target_action = target_lifecycle_node
        self.filters = tuple((field, value) for field, value in (
            ("transition", transition), ("start_state", start_state),
            ("goal_state", goal_state)) if value is not None)


# ----------------------------------------------------------------------------- events


class Event:
    """Base of the modelled events: records its arguments as details."""

    def __init__(self, **details: Any) -> None:
        self.details = {k: v for k, v in details.items() if isinstance(v, (str, int, bool))}


class Shutdown(Event):
    """``launch.events.Shutdown(*, reason='reason not given', due_to_sigint=False)``."""

    def __init__(self, *, reason: str = "reason not given", due_to_sigint: bool = False) -> None:
        super().__init__(reason=reason)


class ShutdownProcess(Event):
    """``launch.events.process.ShutdownProcess(*, process_matcher)``."""

    def __init__(self, *, process_matcher: Any) -> None:
        super().__init__()
        self.process_matcher = process_matcher


class SignalProcess(Event):
    """``launch.events.process.SignalProcess(*, signal_number, process_matcher)``."""

    def __init__(self, *, signal_number: Any, process_matcher: Any) -> None:
        super().__init__()


class ChangeState(Event):
    """launch_ros ``ChangeState(*, lifecycle_node_matcher, transition_id)``."""

    def __init__(self, *, lifecycle_node_matcher: Any, transition_id: int) -> None:
        super().__init__(transition_id=transition_id)
        if transition_id not in range(9):
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
