"""Performing substitutions with concrete values, as an OpaqueFunction's context does."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

from launchverify.evaluate.values import Reducer, text_of
from launchverify.ir import conditions as c
from launchverify.ir import subst as s
from launchverify.ir.symbolic import EnvInput
from launchverify.models import booleans
from launchverify.models.launch_api.placeholders import placeholder
from launchverify.span import Span
from launchverify.workspace.packages import PackageIndex


class SubstitutionFailure(Exception):
    """``launch.substitutions.SubstitutionFailure``: what launch raises on a bad lookup."""

    def __init__(self, message: str, configuration: str | None = None) -> None:
        super().__init__(message)
        self.configuration = configuration  # the launch configuration that does not exist


class ConcreteReducer(Reducer):
    """Reduces against fixed launch configurations (unknown values are placeholders)."""

    def __init__(self, index: PackageIndex, configurations: Mapping[str, str],
                 current: Path) -> None:
        super().__init__()
        self.index = index
        self.configurations = configurations
        self.current = current
        self.reads: list[tuple[str, bool, bool]] = []  # name, found, has a default

    def config(self, name: str, default: s.Sub | None, where: Span | None = None,
               written: Span | None = None) -> s.Sub:
        self.reads.append((name, name in self.configurations, default is not None))
        if name in self.configurations:
            return s.Text(self.configurations[name])
        if default is not None:
            return self.reduce(default)
        raise SubstitutionFailure(f"launch configuration '{name}' does not exist", name)

    def package_share(self, name: str, written: Span | None = None) -> s.Sub:
        package = self.index.find(name)
        return s.Text(placeholder("pkg", name) if package is None else str(package.share))

    def package_prefix(self, name: str, written: Span | None = None) -> s.Sub:
        package = self.index.find(name)
        if package is None or package.prefix is None:
            return s.Text(placeholder("prefix", name))
        return s.Text(str(package.prefix))

    def this_file(self, directory: bool) -> s.Sub:
        return s.Text(str(self.current.parent if directory else self.current))

    def env_input(self, sub: EnvInput) -> s.Sub:
        return sub.default if sub.default is not None else s.Text(placeholder("env", sub.name))

    def perform(self, expression: s.Sub) -> str:
        """Return the value as a string; what stays unknown becomes a placeholder."""
        result = self.reduce(expression)
        text = text_of(result)
        if text is not None:
            return text
        parts = result.parts if isinstance(result, s.Concat) else (result,)
        return "".join(
            p.text if isinstance(p, s.Text) else placeholder("opaque", p.describe())
            for p in parts
        )

    def holds(self, condition: c.Condition | None) -> bool:
        """Return whether a condition holds (launch raises on a non-boolean value)."""
        if condition is None:
            return True
        if isinstance(condition, (c.IfCondition, c.UnlessCondition)):
            value = booleans.condition_truth(self.perform(condition.expression))
            return value if isinstance(condition, c.IfCondition) else not value
        if isinstance(condition, c.ConfigEquals):
            name = self.perform(condition.name)
            self.reads.append((name, name in self.configurations, True))
            current = self.configurations.get(name)
            expected = None if condition.expected is None else self.perform(condition.expected)
            return (current == expected) != condition.negate
        raise SubstitutionFailure(f"cannot evaluate {condition.describe()}")

