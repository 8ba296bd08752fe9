"""The ROS 2 managed-node state machine (rcl_lifecycle's default one), as data.

A request names a transition (``lifecycle_msgs/Transition`` id, or a label as ``ros2
lifecycle set`` takes it). rcl accepts it only from the primary state the transition leaves;
otherwise nothing changes and the ``change_state`` service answers ``success=false``. An
accepted transition goes through its transition state, runs the node's callback and ends
where the callback's result leads; each step publishes a ``TransitionEvent`` (start state,
goal state, transition label), which launch_ros turns into a ``StateTransition`` event.
CREATE (0) and DESTROY (8) are ids of the message but not transitions of the machine.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

Outcome = Literal["success", "failure", "error"]

PRIMARY_STATES = ("unconfigured", "inactive", "active", "finalized")
TRANSITION_STATES = ("configuring", "cleaningup", "shuttingdown", "activating",
                     "deactivating", "errorprocessing")
STATE_IDS = {
    "unknown": 0, "unconfigured": 1, "inactive": 2, "active": 3, "finalized": 4,
    "configuring": 10, "cleaningup": 11, "shuttingdown": 12, "activating": 13,
    "deactivating": 14, "errorprocessing": 15,
}
RESULT_LABELS: dict[Outcome, str] = {
    "success": "transition_success", "failure": "transition_failure",
    "error": "transition_error",
}


@dataclass(frozen=True, slots=True)
class Transition:
    """One requestable transition: where it starts, its transition state, where it ends."""

    id: int
    name: str  # as in lifecycle_msgs/Transition: TRANSITION_<name>
    label: str  # as rcl publishes it and ``ros2 lifecycle set`` takes it
    start: str
    via: str
    success: str
    failure: str

    def goal(self, outcome: Outcome) -> str:
        """Return the state the transition ends in for a callback result."""
        if outcome == "success":
            return self.success
        return self.failure if outcome == "failure" else "errorprocessing"


TRANSITIONS: dict[int, Transition] = {t.id: t for t in (
    Transition(1, "CONFIGURE", "configure", "unconfigured", "configuring", "inactive",
               "unconfigured"),
    Transition(2, "CLEANUP", "cleanup", "inactive", "cleaningup", "unconfigured", "inactive"),
    Transition(3, "ACTIVATE", "activate", "inactive", "activating", "active", "inactive"),
    Transition(4, "DEACTIVATE", "deactivate", "active", "deactivating", "inactive", "active"),
    Transition(5, "UNCONFIGURED_SHUTDOWN", "shutdown", "unconfigured", "shuttingdown",
               "finalized", "finalized"),
    Transition(6, "INACTIVE_SHUTDOWN", "shutdown", "inactive", "shuttingdown", "finalized",
               "finalized"),
    Transition(7, "ACTIVE_SHUTDOWN", "shutdown", "active", "shuttingdown", "finalized",
               "finalized"),
)}
MESSAGE_ONLY = {0: "CREATE", 8: "DESTROY"}  # ids ChangeState accepts, rcl does not register
CONFIGURE, CLEANUP, ACTIVATE, DEACTIVATE = 1, 2, 3, 4
# Where error processing ends, by the on_error callback's result.
AFTER_ERROR: dict[Outcome, str] = {"success": "unconfigured", "failure": "finalized",
                                   "error": "finalized"}


@dataclass(frozen=True, slots=True)
class TransitionEvent:
    """What a lifecycle node publishes on ``transition_event`` (labels)."""

    transition: str
    start: str
    goal: str


def transition_name(transition: int | str) -> str:
    """Return how launch names a transition in messages (``TRANSITION_CONFIGURE``)."""
    if isinstance(transition, str):
        return transition
    known = TRANSITIONS.get(transition)
    name = known.name if known else MESSAGE_ONLY.get(transition, str(transition))
    return f"TRANSITION_{name}"


def resolve(state: str, transition: int | str) -> Transition | None:
    """Return the transition a request starts from ``state``, or ``None`` if rcl refuses it.

    A label (``ros2 lifecycle set NODE shutdown``) picks the transition with that label
    that leaves ``state``.

    Examples:
        >>> resolve("unconfigured", 1).via, resolve("unconfigured", 3)
        ('configuring', None)
        >>> resolve("active", "shutdown").name
        'ACTIVE_SHUTDOWN'
    """
    if isinstance(transition, str):
        for candidate in TRANSITIONS.values():
            if candidate.label == transition and candidate.start == state:
                return candidate
        return None
    known = TRANSITIONS.get(transition)
    return known if known is not None and known.start == state else None


def request(state: str, transition: int | str,
            outcome: Outcome = "success",
            on_error: Outcome = "success") -> tuple[str, tuple[TransitionEvent, ...]] | None:
    """Return the state after a request and the events it publishes; ``None`` if refused.

    Examples:
        >>> state, events = request("unconfigured", 1)
        >>> state, [(e.start, e.goal) for e in events]
        ('inactive', [('unconfigured', 'configuring'), ('configuring', 'inactive')])
        >>> request("inactive", 3, outcome="error")[0]
        'unconfigured'
    """
    found = resolve(state, transition)
    if found is None:
        return None
    goal = found.goal(outcome)
    events = [TransitionEvent(found.label, state, found.via),
              TransitionEvent(RESULT_LABELS[outcome], found.via, goal)]
    if goal == "errorprocessing":
        goal = AFTER_ERROR[on_error]
        events.append(TransitionEvent(RESULT_LABELS[on_error], "errorprocessing", goal))
    return goal, tuple(events)


def completes(transition: int | str, event: TransitionEvent) -> bool:
    """Return whether an event is the successful end of a transition (LifecycleTransition).

    Examples:
        >>> completes(1, TransitionEvent("transition_success", "configuring", "inactive"))
        True
    """
    known = TRANSITIONS.get(transition) if isinstance(transition, int) else None
    return known is not None and event.start == known.via and event.goal == known.success


def requestable(state: str) -> tuple[Transition, ...]:
    """Return the transitions rcl accepts from a primary state."""
    return tuple(t for t in TRANSITIONS.values() if t.start == state)


def parse_transition(text: str) -> int | str | None:
    """Read a transition as ``ros2 lifecycle set`` or a launch file gives it (id or label).

    Examples:
        >>> parse_transition("3"), parse_transition("configure"), parse_transition("jump")
        (3, 'configure', None)
    """
    text = text.strip()
    if text.isdigit():
        return int(text)
    if text.startswith("TRANSITION_"):
        for known in TRANSITIONS.values():
            if known.name == text[len("TRANSITION_"):]:
                return known.id
    labels = {t.label for t in TRANSITIONS.values()}
    return text if text in labels else None
