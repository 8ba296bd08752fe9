"""Names of the packages released for ROS 2 humble, jazzy, kilted and rolling.

A package that is neither in the workspace nor installed may simply live on the robot; one
that is also unknown to every ROS 2 distribution is most likely a typo. The list comes from
ros/rosdistro's distribution files (see the header of ``known_packages.txt``).
"""

from __future__ import annotations

from functools import cache
from importlib import resources


@cache
def released_packages() -> frozenset[str]:
    """Return every package name released in a supported ROS 2 distribution."""
    text = resources.files("launchverify.models").joinpath("known_packages.txt").read_text()
    return frozenset(
        line.strip() for line in text.splitlines() if line.strip() and not line.startswith("#")
    )


def is_released(name: str) -> bool:
    """Return whether ``name`` is a released ROS 2 package."""
    return name in released_packages()
