"""Answers of the SMT layer, as plain data (no z3 needed to read them)."""

from __future__ import annotations

from dataclasses import dataclass, field

from launchverify.ir.symbolic import Guard, describe_placed


@dataclass(frozen=True)
class Witness:
    """Launch-argument values (``name:=value``) under which something happens.

    Empty when it happens under the arguments as given (command line, then defaults).
    """

    values: dict[str, str] = field(default_factory=dict)

    def describe(self) -> str:
        """Return ``a:=1 b:=2``, or ``the arguments as given``."""
        if not self.values:
            return "the arguments as given"
        return " ".join(f"{k}:={v}" for k, v in sorted(self.values.items()))


@dataclass(frozen=True)
class Contradiction:
    """Why a condition can never hold: the guards and argument domains that clash."""

    guards: tuple[Guard, ...]
    domains: tuple[str, ...] = ()

    def describe(self) -> str:
        """Return the clashing facts, each with where it is written."""
        parts = [describe_placed(guard) for guard in self.guards]
        parts.extend(self.domains)
        return " and ".join(parts)
