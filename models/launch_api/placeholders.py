"""Strings that stand for values only known on the robot.

Python launch code needs real strings (``os.path.join(get_package_share_directory(p), ...)``,
``os.environ['ROBOT']``); where the value is not known statically we hand it a placeholder
such as ``⟨env:ROBOT⟩``. The Python frontend turns placeholders back into symbolic IR
(an environment input, a package's share folder...) when the string reaches an action.
"""

from __future__ import annotations

import re

OPEN, CLOSE = "\u27e8", "\u27e9"
PATTERN = re.compile(OPEN + r"(env|pkg|prefix|arg|opaque):([^" + CLOSE + r"]*)" + CLOSE)


def placeholder(kind: str, name: str) -> str:
    """Return the placeholder for an unknown value (``kind``: env, pkg, prefix, arg, opaque)."""
    clean = name.replace(OPEN, "<").replace(CLOSE, ">")  # no placeholder inside another
    return f"{OPEN}{kind}:{clean}{CLOSE}"


def environment_variable(name: str, default: str | None = None) -> str:
    """Return the placeholder for a variable of the robot's environment.

    With a default it reads as ``$(env NAME default)`` does: the default when the robot
    does not set it, which launchverify cannot know (environment names hold no ``=``).
    """
    return placeholder("env", name if default is None else f"{name}={default}")


def has_placeholder(text: str) -> bool:
    """Return whether a string carries a value that is not known statically."""
    return OPEN in text


class UnknownMapping(dict):  # type: ignore[type-arg]
    """YAML content only the robot has: any key gives more of it, iteration gives nothing."""

    def __missing__(self, key: object) -> UnknownMapping:
        return UnknownMapping()
