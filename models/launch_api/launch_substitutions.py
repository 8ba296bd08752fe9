"""Models of ``launch.substitutions`` and ``launch.conditions``.

Constructor signatures follow ros2/launch (humble to rolling); each model keeps its
arguments and turns them into the IR expression of ``launchverify.ir.subst``.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from launchverify.ir import conditions as c
from launchverify.ir import subst as s
from launchverify.models.launch_api.base import (
    Condition,
    Converter,
    Substitution,
    check_substitutions,
)


class TextSubstitution(Substitution):
    """``TextSubstitution(text=...)``."""

    def __init__(self, *, text: str) -> None:
        super().__init__()
        if not isinstance(text, str):
            raise TypeError(f"TextSubstitution expected Text object got '{type(text)}' instead.")
        self.text = text

    def to_sub(self, cv: Converter) -> s.Sub:
        return cv.sub(self.text)


class LaunchConfiguration(Substitution):
    """``LaunchConfiguration(variable_name, *, default=None)``."""

    def __init__(self, variable_name: Any, *, default: Any = None) -> None:
        super().__init__()
        self.variable_name = variable_name
        self.default = default

    def to_sub(self, cv: Converter) -> s.Sub:
        default = None if self.default is None else cv.sub(
            self.default if not isinstance(self.default, (list, tuple)) or self.default
            else ""
        )
        return s.LaunchConfig(cv.sub(self.variable_name), default)


class EnvironmentVariable(Substitution):
    """``EnvironmentVariable(name, *, default_value=None)``."""

    def __init__(self, name: Any, *, default_value: Any = None) -> None:
        super().__init__()
        self.name = name
        self.default_value = default_value

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.EnvVar(cv.sub(self.name), cv.opt_sub(self.default_value))


class PythonExpression(Substitution):
    """``PythonExpression(expression, python_modules=['math'])``."""

    def __init__(self, expression: Any, python_modules: Any = None) -> None:
        super().__init__()
        self.expression = expression
        self.python_modules = python_modules

    def to_sub(self, cv: Converter) -> s.Sub:
        modules = None
        if self.python_modules is not None:
            names = self.python_modules if isinstance(self.python_modules, (list, tuple)) else [
                self.python_modules]
            parts: list[s.Sub] = []
            for index, name in enumerate(names):
                if index:
                    parts.append(s.Text(","))
                parts.append(cv.sub(name))
            modules = s.concat(parts)
        return s.PythonExpr(cv.sub(self.expression), modules)


class Command(Substitution):
    """``Command(command, *, on_stderr='fail')``: never run statically."""

    def __init__(self, command: Any, *, on_stderr: Any = "fail") -> None:
        super().__init__()
        self.command = command
        self.on_stderr = on_stderr

    def to_sub(self, cv: Converter) -> s.Sub:
        command = self.command
        if isinstance(command, (list, tuple)):
            command = list(command)
        return s.Command(cv.sub(command), cv.opt_sub(self.on_stderr))


class FindExecutable(Substitution):
    """``FindExecutable(*, name)``."""

    def __init__(self, *, name: Any) -> None:
        super().__init__()
        self.name = name

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.FindExecutable(cv.sub(self.name))


class PathJoinSubstitution(Substitution):
    """``PathJoinSubstitution(substitutions)``: ``os.path.join`` of the parts; ``/`` appends."""

    def __init__(self, substitutions: Iterable[Any]) -> None:
        super().__init__()
        self.substitutions = list(substitutions)

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.PathJoin(tuple(cv.sub(part) for part in self.substitutions))

    def __truediv__(self, other: Any) -> PathJoinSubstitution:
        return PathJoinSubstitution([*self.substitutions, other])


class PathSubstitution(PathJoinSubstitution):
    """``PathSubstitution(path)`` (rolling): a path to build on with ``/``."""

    def __init__(self, path: Any) -> None:
        super().__init__([path])


class ThisLaunchFile(Substitution):
    """``ThisLaunchFile()``."""

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.ThisLaunchFile()


class ThisLaunchFileDir(Substitution):
    """``ThisLaunchFileDir()``."""

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.ThisLaunchFileDir()


class LaunchLogDir(Substitution):
    """``LaunchLogDir()``."""

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.LaunchLogDir()


class AnonName(Substitution):
    """``AnonName(name)``."""

    def __init__(self, name: Any) -> None:
        super().__init__()
        self.name = name

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.AnonName(cv.sub(self.name))


class LocalSubstitution(Substitution):
    """``LocalSubstitution(expression, description=None)``: a value of ``context.locals``."""

    def __init__(self, expression: str, description: str | None = None) -> None:
        super().__init__()
        self.expression = expression

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.LocalSub(self.expression)


class NotSubstitution(Substitution):
    """``NotSubstitution(value)``."""

    def __init__(self, value: Any) -> None:
        super().__init__()
        self.value = value

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.NotSub(cv.sub(self.value))


class AndSubstitution(Substitution):
    """``AndSubstitution(left, right)``."""

    def __init__(self, left: Any, right: Any) -> None:
        super().__init__()
        self.left, self.right = left, right

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.AndSub(cv.sub(self.left), cv.sub(self.right))


class OrSubstitution(Substitution):
    """``OrSubstitution(left, right)``."""

    def __init__(self, left: Any, right: Any) -> None:
        super().__init__()
        self.left, self.right = left, right

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.OrSub(cv.sub(self.left), cv.sub(self.right))


class AnySubstitution(Substitution):
    """``AnySubstitution(*args)``."""

    def __init__(self, *args: Any) -> None:
        super().__init__()
        self.args = args

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.AnySub(tuple(cv.sub(arg) for arg in self.args))


class AllSubstitution(Substitution):
    """``AllSubstitution(*args)``."""

    def __init__(self, *args: Any) -> None:
        super().__init__()
        self.args = args

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.AllSub(tuple(cv.sub(arg) for arg in self.args))


class EqualsSubstitution(Substitution):
    """``EqualsSubstitution(left, right)``."""

    def __init__(self, left: Any, right: Any) -> None:
        super().__init__()
        self.left, self.right = left, right

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.EqualsSub(cv.sub(_equals_text(self.left)), cv.sub(_equals_text(self.right)))


class NotEqualsSubstitution(Substitution):
    """``NotEqualsSubstitution(left, right)``."""

    def __init__(self, left: Any, right: Any) -> None:
        super().__init__()
        self.left, self.right = left, right

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.NotEqualsSub(cv.sub(_equals_text(self.left)), cv.sub(_equals_text(self.right)))


def _equals_text(value: Any) -> Any:
    """``EqualsSubstitution`` turns ``None`` into '' and booleans into true/false."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return str(value)
    return value


class IfElseSubstitution(Substitution):
    """``IfElseSubstitution(condition, if_value='', else_value='')``."""

    def __init__(self, condition: Any, if_value: Any = "", else_value: Any = "") -> None:
        super().__init__()
        if not if_value and not else_value:
            raise RuntimeError("One of if_value and else_value must be specified")
        self.condition, self.if_value, self.else_value = condition, if_value, else_value

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.IfElse(cv.sub(self.condition), cv.sub(self.if_value), cv.sub(self.else_value))


class FileContent(Substitution):
    """``FileContent(path)``."""

    def __init__(self, path: Any) -> None:
        super().__init__()
        self.path = path

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.FileContent(cv.sub(self.path))


class StringJoinSubstitution(Substitution):
    """``StringJoinSubstitution(substitutions, delimiter='')`` (kilted, rolling)."""

    def __init__(self, substitutions: Iterable[Any], delimiter: Any = "") -> None:
        super().__init__()
        self.substitutions = list(substitutions)
        self.delimiter = delimiter

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.StringJoin(cv.sub(self.delimiter),
                            tuple(cv.sub(part) for part in self.substitutions))


class ForEachVar(Substitution):
    """``ForEachVar(name, *, default_value=None)`` (kilted, rolling)."""

    def __init__(self, name: Any, *, default_value: Any = None) -> None:
        super().__init__()
        self.name, self.default_value = name, default_value

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.ForEachVar(cv.sub(self.name), cv.opt_sub(self.default_value))


class ForLoopIndex(Substitution):
    """``ForLoopIndex(name)`` (kilted, rolling)."""

    def __init__(self, name: Any) -> None:
        super().__init__()
        self.name = name

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.ForLoopIndex(cv.sub(self.name))


# ---------------------------------------------------------------------------- conditions


class IfCondition(Condition):
    """``IfCondition(predicate_expression)``."""

    def __init__(self, predicate_expression: Any) -> None:
        super().__init__()
        self.predicate_expression = check_substitutions(predicate_expression)

    def to_condition(self, cv: Converter) -> c.Condition:
        return c.IfCondition(cv.sub(self.predicate_expression))


class UnlessCondition(Condition):
    """``UnlessCondition(predicate_expression)``."""

    def __init__(self, predicate_expression: Any) -> None:
        super().__init__()
        self.predicate_expression = check_substitutions(predicate_expression)

    def to_condition(self, cv: Converter) -> c.Condition:
        return c.UnlessCondition(cv.sub(self.predicate_expression))


class LaunchConfigurationEquals(Condition):
    """``LaunchConfigurationEquals(launch_configuration_name, expected_value)``."""

    negate = False

    def __init__(self, launch_configuration_name: str, expected_value: Any) -> None:
        super().__init__()
        self.name, self.expected_value = launch_configuration_name, expected_value

    def to_condition(self, cv: Converter) -> c.Condition:
        return c.ConfigEquals(cv.sub(self.name), cv.opt_sub(self.expected_value), self.negate)


class LaunchConfigurationNotEquals(LaunchConfigurationEquals):
    """``LaunchConfigurationNotEquals(launch_configuration_name, expected_value)``."""

    negate = True


class FunctionCondition(Condition):
    """``launch.Condition(predicate=callable)``: opaque."""

    def __init__(self, *, predicate: Any = None) -> None:
        super().__init__()
        self.predicate = predicate

    def to_condition(self, cv: Converter) -> c.Condition:
        if self.predicate is None:
            return c.IfCondition(s.Text("false"))
        name = getattr(self.predicate, "__name__", "a callable")
        return c.OpaqueCondition(f"condition {name}()")
