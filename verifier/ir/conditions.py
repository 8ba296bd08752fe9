"""Conditions as written on actions (``if=``, ``unless=``, ``IfCondition``, ...)."""

from __future__ import annotations

from dataclasses import dataclass

from launchverify.ir.subst import Sub


class Condition:
    """Base of the conditions an action can carry."""

    __slots__ = ()

    def describe(self) -> str:
        """Return the condition as a user would write it."""
        raise NotImplementedError


@dataclass(frozen=True, slots=True)
class IfCondition(Condition):
    """True when the expression is ``true``/``1`` (case-insensitive); ``if=``."""

    expression: Sub

    def describe(self) -> str:
        return f"if {self.expression.describe()}"


@dataclass(frozen=True, slots=True)
class UnlessCondition(Condition):
    """True when the expression is ``false``/``0``; ``unless=``."""

    expression: Sub

    def describe(self) -> str:
        return f"unless {self.expression.describe()}"


@dataclass(frozen=True, slots=True)
class ConfigEquals(Condition):
    """``LaunchConfigurationEquals``: exact string match; ``expected=None`` means unset."""

    name: Sub
    expected: Sub | None
    negate: bool = False

    def describe(self) -> str:
        op = "!=" if self.negate else "=="
        expected = "<unset>" if self.expected is None else repr(self.expected.describe())
        return f"$(var {self.name.describe()}) {op} {expected}"


@dataclass(frozen=True, slots=True)
class OpaqueCondition(Condition):
    """A condition launchverify cannot model (a Python predicate)."""

    description: str

    def describe(self) -> str:
        return f"<{self.description}>"
