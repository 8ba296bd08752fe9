"""The ROS 2 managed-node state machine (rcl_lifecycle's default one), as data.

A request names a transition (``lifecycle_msgs/Transition`` id, or a label as ``ros2
lifecycle set`` takes it). rcl accepts it only from the primary state the transition leaves;
otherwise nothing changes and the ``change_state`` service answers ``success=false``. An
accepted transition goes through its transition state, runs the node's callback and ends
where the callback's result leads; each step publishes a ``TransitionEvent`` (start state,
goal state and, only since rolling, the transition's label), which launch_ros turns into a
``StateTransition`` event. CREATE (0) and DESTROY (8) are ids of the message but not
transitions of the machine. ``never_matches`` says when an ``OnStateTransition``'s labels
match none of the events the machine can publish (``EVENTS``).
"""

from __future__ import annotations

from collections.abc import Iterable
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


# ----------------------------------------------------------------------------- event labels
#
# launch_ros turns each ``TransitionEvent`` into a ``StateTransition`` event holding the
# message's labels, and ``OnStateTransition(transition=, start_state=, goal_state=)``
# compares each given value with ``==``: exact, case-sensitive, never performed (a
# substitution, number or list equals no label). rcl fills in the start and goal states;
# the transition itself (id and label) stays empty until rolling's rcl (ros2/rcl#1019,
# fixed by ros2/rcl#1269 in 2025): on humble to kilted ``transition=`` matches nothing.

STATE_LABELS = tuple(STATE_IDS)
REQUEST_LABELS = ("configure", "cleanup", "activate", "deactivate", "shutdown")
EVENT_TRANSITION_LABELS = (*REQUEST_LABELS, *RESULT_LABELS.values())
FILTER_FIELDS = ("transition", "start_state", "goal_state")
TRANSITION_LABELS_SINCE = "rolling"  # the first distribution whose events carry them
NOT_TEXT = "<substitution>"  # how the Python model records a label that is not a str


def _every_event() -> tuple[TransitionEvent, ...]:
    found: dict[TransitionEvent, None] = {}
    for transition in TRANSITIONS.values():
        for outcome in RESULT_LABELS:
            for on_error in RESULT_LABELS:
                result = request(transition.start, transition.id, outcome, on_error)
                assert result is not None
                found.update(dict.fromkeys(result[1]))
    return tuple(found)


EVENTS = _every_event()  # every event the default state machine can publish


def transition_labels(distro: str | None) -> bool | None:
    """Return whether a distribution's events carry transition labels (``None``: unknown).

    Examples:
        >>> transition_labels("jazzy"), transition_labels("rolling"), transition_labels(None)
        (False, True, None)
    """
    from launchverify.models.distros import DISTROS

    if distro is None:
        return None
    if distro not in DISTROS:
        return True  # newer than launchverify knows
    return DISTROS.index(distro) >= DISTROS.index(TRANSITION_LABELS_SINCE)


@dataclass(frozen=True, slots=True)
class NeverMatches:
    """Why an ``OnStateTransition``'s labels match no event, and what would.

    ``field`` is the argument to change; ``hint`` the change, as it would be written
    (``goal_state='active'``, ``leave out start_state='unconfigured'``). ``pair``: each
    label is one rcl publishes in its field, but no single event carries them together
    (LV504: the handler awaits a transition the node cannot take from that state); else
    one label is never published in its field at all (LV508).
    """

    field: str
    value: str
    reason: str
    hint: str | None = None
    pair: bool = False

    @property
    def argument(self) -> str:
        """Return the argument as written (``goal_state='activated'``)."""
        shown = "<not a string>" if self.value == NOT_TEXT else repr(self.value)
        return f"{self.field}={shown}"


def never_matches(filters: tuple[tuple[str, str], ...],
                  distro: str | None = None) -> NeverMatches | None:
    """Return why no event can pass an ``OnStateTransition``'s filters (``None``: some can).

    ``distro`` decides whether events carry transition labels (``None``: any distribution,
    so a transition label counts as matching, as on rolling).

    Examples:
        >>> never_matches((("goal_state", "activated"),)).hint
        "goal_state='active'"
        >>> never_matches((("start_state", "unconfigured"), ("goal_state", "inactive"))).hint
        "start_state='configuring'"
        >>> never_matches((("start_state", "configuring"), ("goal_state", "inactive"))) is None
        True
        >>> never_matches((("transition", "configure"),), "jazzy").hint
        "goal_state='configuring'"
    """
    given = dict(filters)
    for field in FILTER_FIELDS:
        if field in given:
            problem = _label_problem(field, given[field], given, distro)
            if problem is not None:
                return problem
    if any(_passes(event, given) for event in EVENTS):
        return None
    return _combination_problem(given)


def _passes(event: TransitionEvent, given: dict[str, str]) -> bool:
    values = {"transition": event.transition, "start_state": event.start,
              "goal_state": event.goal}
    return all(values[field] == label for field, label in given.items())


def _quoted(labels: Iterable[str]) -> str:
    """Return labels as a list in words: ``'a', 'b' or 'c'``."""
    items = [f"'{label}'" for label in sorted(labels)]
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " or " + items[-1]


def _label_problem(field: str, value: str, given: dict[str, str],
                   distro: str | None) -> NeverMatches | None:
    """Return why one label matches no event, alone (``None``: some event has it)."""
    if value == NOT_TEXT:
        return NeverMatches(field, value, "the label is not a plain string (a substitution, "
                            "number or list): launch_ros compares it with the event's label "
                            "by ==, without performing it, and it equals none")
    if field == "transition":
        return _transition_problem(value, given, distro)
    starts = {event.start for event in EVENTS}
    goals = {event.goal for event in EVENTS}
    if value not in STATE_IDS:
        near = closest_state(value, field)
        if near is not None and near.lower() == value.lower():
            reason = (f"'{value}' is not a state label: launch_ros compares labels exactly "
                      "and rcl's are lower case")
        elif near is not None and value.lower() in _SYNONYMS:
            reason = (f"'{value}' is not a state of the lifecycle state machine (a node that "
                      f"is {value.lower()} is '{near}')")
        elif near is not None:
            reason = f"'{value}' is not a state of the lifecycle state machine"
        else:
            reason = (f"'{value}' is not a state of the lifecycle state machine, whose "
                      f"states are {_quoted(STATE_LABELS[1:])}")
        return NeverMatches(field, value, reason, near and f"{field}='{near}'")
    if field == "start_state" and value not in starts:
        why = ("no node is ever in 'unknown'" if value == "unknown" else
               f"no transition leaves '{value}' (it is final)")
        hint = f"goal_state='{value}'" if value in goals and "goal_state" not in given else None
        return NeverMatches(field, value, f"{why}, so no transition event starts there", hint)
    if field == "goal_state" and value not in goals:
        return NeverMatches(field, value, f"no transition event ends in '{value}': no node "
                            "is ever in it")
    return None


def _transition_problem(value: str, given: dict[str, str],
                        distro: str | None) -> NeverMatches | None:
    labelled = transition_labels(distro)
    near = value if value in EVENT_TRANSITION_LABELS else closest_transition(value)
    if labelled is False:
        reason = (f"on {distro} rcl publishes transition events with an empty transition "
                  f"label (ros2/rcl#1019, filled in since {TRANSITION_LABELS_SINCE}), so "
                  "the handler's transition never equals it")
        if near is not None and near != value:
            reason += f" ('{value}' is not a transition label either)"
        hint = None if near is None else _by_states(near, given)
        if hint is None:
            reason += "; filter on start_state and goal_state instead"
        return NeverMatches("transition", value, reason, hint)
    if value in EVENT_TRANSITION_LABELS:
        return None
    reason = f"'{value}' is not a transition label of the lifecycle events"
    if value in STATE_IDS:
        reason = f"'{value}' is a state, not a transition label"
    if labelled is None:
        reason += (f" (and before {TRANSITION_LABELS_SINCE} events carry no transition "
                   "label at all: start_state and goal_state are what matches everywhere)")
    return NeverMatches("transition", value, reason, near and f"transition='{near}'")


def _by_states(label: str, given: dict[str, str]) -> str | None:
    """Return the state filters that select the events a transition label would."""
    others = {k: v for k, v in given.items() if k != "transition"}
    if others:
        return (f"leave out transition='{given['transition']}'"
                if any(_passes(e, others) for e in EVENTS) else None)
    matching = [e for e in EVENTS if e.transition == label]
    goals = {event.goal for event in matching}
    starts = {event.start for event in matching}
    if len(goals) == 1:
        return f"goal_state='{goals.pop()}'"
    if len(starts) == 1:
        return f"start_state='{starts.pop()}'"
    return None


def _combination_problem(given: dict[str, str]) -> NeverMatches:
    """Explain labels each valid alone that no single event carries together."""
    start, goal = given.get("start_state"), given.get("goal_state")
    if "transition" in given:
        label = given["transition"]
        hops = ", ".join(f"'{e.start}' -> '{e.goal}'" for e in EVENTS if e.transition == label)
        states = {k: v for k, v in given.items() if k != "transition"}
        hint = (f"leave out transition='{label}'"
                if any(_passes(e, states) for e in EVENTS) else None)
        return NeverMatches("transition", label, f"no '{label}' event has those states: "
                            f"'{label}' events go {hops}", hint, pair=True)
    assert start is not None and goal is not None
    between = sorted({e.goal for e in EVENTS if e.start == start}
                     & {e.start for e in EVENTS if e.goal == goal})
    if between:
        middle = between[0]
        return NeverMatches("start_state", start, f"no single event goes from '{start}' to "
                            f"'{goal}': the node passes through '{middle}' ('{start}' -> "
                            f"'{middle}', then '{middle}' -> '{goal}')",
                            f"start_state='{middle}'", pair=True)
    origins = {e.start for e in EVENTS if e.goal == goal}
    return NeverMatches("start_state", start, f"no transition event goes from '{start}' to "
                        f"'{goal}': events that end in '{goal}' start in {_quoted(origins)}",
                        pair=True)


# What people write for a state, and the state they mean.
_SYNONYMS = {"activated": "active", "configured": "inactive", "deactivated": "inactive",
             "cleanedup": "unconfigured", "created": "unconfigured", "finalised": "finalized",
             "shutdown": "finalized", "destroyed": "finalized", "error": "errorprocessing"}


def _squash(text: str) -> str:
    """Return a label without case, separators or a ``PRIMARY_STATE_``-like prefix."""
    squashed = "".join(ch for ch in text.lower() if ch.isalnum())
    for prefix in ("primarystate", "transitionstate", "state"):
        if squashed.startswith(prefix) and squashed != prefix:
            return squashed[len(prefix):]
    return squashed


def closest_state(value: str, field: str = "goal_state") -> str | None:
    """Return the state label a misspelled one most likely means.

    A transition's name stands for where it leads (``goal_state``) or the transition
    state the node leaves it from (``start_state``).

    Examples:
        >>> closest_state("Active"), closest_state("configured"), closest_state("inactve")
        ('active', 'inactive', 'inactive')
        >>> closest_state("activate"), closest_state("activate", "start_state")
        ('active', 'activating')
    """
    import difflib

    key = _squash(value)
    for label in STATE_LABELS:
        if _squash(label) == key:
            return label
    if key in _SYNONYMS:
        return _SYNONYMS[key]
    verb = next((t for t in TRANSITIONS.values() if t.label == key), None)
    if verb is not None:
        return verb.success if field == "goal_state" else verb.via
    close = difflib.get_close_matches(key, STATE_LABELS[1:], n=1, cutoff=0.75)
    return close[0] if close else None


def closest_transition(value: str) -> str | None:
    """Return the transition label a wrong one most likely means.

    Examples:
        >>> closest_transition("TRANSITION_CONFIGURE"), closest_transition("activating")
        ('configure', 'activate')
        >>> closest_transition("on_configure_success"), closest_transition("active_shutdown")
        ('transition_success', 'shutdown')
    """
    import difflib

    key = _squash(value)
    if key.startswith("transition") and key != "transition":
        key = key[len("transition"):]
    for label in EVENT_TRANSITION_LABELS:
        if _squash(label) in (key, "transition" + key):
            return label
    for outcome, label in RESULT_LABELS.items():
        if key.endswith(outcome):
            return label
    if key.endswith("shutdown") or key in ("finalized", "finalizing"):
        return "shutdown"
    for transition in TRANSITIONS.values():
        if key in (transition.via, transition.label + "d", transition.label + "ed"):
            return transition.label
    if key in ("active", "activation"):
        return "activate"
    close = difflib.get_close_matches(key, REQUEST_LABELS, n=1, cutoff=0.75)
    return close[0] if close else None
