"""ROS 2 distributions and the launch features each has.

A check is made for one distribution when it is known (``--distro``, the configuration's
``distro``, else ``ROS_DISTRO`` of a sourced installation); without one every feature is
accepted. The first distribution with each feature comes from the launch_ros changelogs
(``autostart``: 0.26.7 in jazzy, absent in humble; ``<lifecycle_node>`` and
``<composable_lifecycle_node>``: rolling 0.29.x; ``LifecycleTransition``: not in humble).
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from contextvars import ContextVar

DISTROS = ("humble", "iron", "jazzy", "kilted", "rolling")
FIRST = {
    "LifecycleNode(autostart=...)": "jazzy",
    "LifecycleTransition": "iron",
    "the <lifecycle_node> tag": "rolling",
    "the <composable_lifecycle_node> tag": "rolling",
    "ROS_AUTOMATIC_DISCOVERY_RANGE": "iron",  # rcl's discovery_options.c
}
_CURRENT: ContextVar[str | None] = ContextVar("launchverify_distro", default=None)


def current() -> str | None:
    """Return the distribution being checked (``None``: any)."""
    return _CURRENT.get()


def missing(feature: str) -> str | None:
    """Return why a feature is missing in the checked distribution (``None``: it is there).

    Examples:
        >>> with checking("humble"):
        ...     missing("LifecycleNode(autostart=...)")
        'LifecycleNode(autostart=...) is not in humble (since jazzy)'
        >>> missing("LifecycleNode(autostart=...)") is None
        True
    """
    distro = current()
    first = FIRST[feature]
    if distro is None or distro not in DISTROS or \
            DISTROS.index(distro) >= DISTROS.index(first):
        return None
    return f"{feature} is not in {distro} (since {first})"


@contextmanager
def checking(distro: str | None) -> Iterator[None]:
    """Check for one distribution inside the block."""
    token = _CURRENT.set(distro)
    try:
        yield
    finally:
        _CURRENT.reset(token)
