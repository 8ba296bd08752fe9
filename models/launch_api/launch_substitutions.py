"""Models of ``launch.substitutions`` and ``launch.conditions``.

Constructor signatures follow ros2/launch (humble to rolling); each model keeps its
arguments and turns them into the IR expression of ``launchverify.ir.subst``.
"""

from __future__ import annotations

import operator
from collections.abc import Iterable
from typing import Any

from launchverify.ir import conditions as c
from launchverify.ir import subst as s
from launchverify.models.launch_api.base import (
    Condition,
    Converter,
    Substitution,
    _unknown,
    check_substitutions,
    described,
    launch_getter,
    normalized,
)
from launchverify.models.launch_api.placeholders import placeholder


class TextSubstitution(Substitution):
    """``TextSubstitution(text=...)``."""

    def __init__(self, *, text: str) -> None:
        super().__init__()
        if not isinstance(text, str):
            raise TypeError(f"TextSubstitution expected Text object got '{type(text)}' instead.")
        self._text = text

    @property
    def text(self) -> str:
        """Return the text (launch's API)."""
        return self._text

    def describe(self) -> str:
        return f"'{self._text}'"

    def perform(self, context: Any) -> str:
        return self._text

    def to_sub(self, cv: Converter) -> s.Sub:
        return cv.sub(self._text)


class LaunchConfiguration(Substitution):
    """``LaunchConfiguration(variable_name, *, default=None)``."""

    def __init__(self, variable_name: Any, *, default: Any = None) -> None:
        super().__init__()
        self._variable_name = variable_name
        self._default = default

    variable_name = launch_getter("_variable_name",
                                  "Return the name as a list of substitutions (launch's API).")

    def describe(self) -> str:
        return f"LaunchConfig({described(self._variable_name)})"

    def to_sub(self, cv: Converter) -> s.Sub:
        default = None if self._default is None else cv.sub(_default_items(self._default))
        name = cv.written(self._span, self._variable_name, position=0, keyword="variable_name")
        return s.LaunchConfig(name, default, where=self._span)


def _default_items(default: Any) -> list[Any]:
    """Return a default as launch keeps it: items that are not text become ``str(item)``.

    So ``default=True`` is ``'True'``, not ``'true'``, as ``PythonExpression`` then sees it.
    """
    items = default if isinstance(default, (list, tuple)) else [default]
    return [item if isinstance(item, (str, Substitution)) or _unknown(item) else str(item)
            for item in items]


class EnvironmentVariable(Substitution):
    """``EnvironmentVariable(name, *, default_value=None)``."""

    def __init__(self, name: Any, *, default_value: Any = None) -> None:
        super().__init__()
        self._name = name
        self._default_value = default_value

    name = launch_getter("_name", "Return the variable's name as substitutions (launch's API).")

    default_value = launch_getter(
        "_default_value", "Return the default as substitutions, or ``None`` (launch's API).")

    def describe(self) -> str:
        return f"EnvVar({described(self._name)})"

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.EnvVar(cv.sub(self._name), cv.opt_sub(self._default_value))


class PythonExpression(Substitution):
    """``PythonExpression(expression, python_modules=['math'])``."""

    def __init__(self, expression: Any, python_modules: Any = None) -> None:
        super().__init__()
        self._expression = expression
        self._python_modules = python_modules

    expression = launch_getter("_expression",
                               "Return the expression as substitutions (launch's API).")

    @property
    def python_modules(self) -> list[Any]:
        """Return the modules to import, as substitutions (launch's API)."""
        modules = ["math"] if self._python_modules is None else self._python_modules
        return normalized(modules)  # type: ignore[no-any-return]

    def describe(self) -> str:
        modules = ", ".join(sub.describe() for sub in self.python_modules)
        return f"PythonExpr({described(self._expression)}, [{modules}])"

    def to_sub(self, cv: Converter) -> s.Sub:
        modules = None
        if self._python_modules is not None:
            names = self._python_modules if isinstance(
                self._python_modules, (list, tuple)) else [self._python_modules]
            parts: list[s.Sub] = []
            for index, name in enumerate(names):
                if index:
                    parts.append(s.Text(","))
                parts.append(cv.sub(name))
            modules = s.concat(parts)
        return s.PythonExpr(cv.sub(self._expression), modules)


class Command(Substitution):
    """``Command(command, *, on_stderr='fail')``: never run statically."""

    def __init__(self, command: Any, *, on_stderr: Any = "fail") -> None:
        super().__init__()
        self._command = command
        self._on_stderr = on_stderr

    command = launch_getter("_command", "Return the command line as substitutions (launch's API).")

    on_stderr = launch_getter(
        "_on_stderr", "Return what to do with output on stderr, as substitutions (launch's API).")

    def describe(self) -> str:
        return f"Command({described(self._command)})"

    def to_sub(self, cv: Converter) -> s.Sub:
        command = self._command
        if isinstance(command, (list, tuple)):
            command = list(command)
        return s.Command(cv.sub(command), cv.opt_sub(self._on_stderr))


class FindExecutable(Substitution):
    """``FindExecutable(*, name)``."""

    def __init__(self, *, name: Any) -> None:
        super().__init__()
        self._name = name

    name = launch_getter("_name", "Return the executable's name as substitutions (launch's API).")

    def describe(self) -> str:
        return f"FindExec({described(self._name)})"

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.FindExecutable(cv.sub(self._name))


class PathJoinSubstitution(Substitution):
    """``PathJoinSubstitution(substitutions)``: ``os.path.join`` of the parts; ``/`` appends."""

    def __init__(self, substitutions: Iterable[Any]) -> None:
        super().__init__()
        self._parts = list(substitutions)

    @property
    def substitutions(self) -> list[list[Any]]:
        """Return the path components, each a list of substitutions (launch's API)."""
        return [normalized(part) for part in self._parts]

    def __repr__(self) -> str:
        parts = ", ".join(described(part) for part in self._parts)
        return f"PathJoinSubstitution('{parts}')"

    def to_sub(self, cv: Converter) -> s.Sub:
        last = len(self._parts) - 1  # a file's name, often: located for fixes
        return s.PathJoin(tuple(
            cv.written(self._span, part, position=0, keyword="substitutions", item=last,
                       items=len(self._parts))
            if index == last else cv.sub(part) for index, part in enumerate(self._parts)))

    def __truediv__(self, other: Any) -> PathJoinSubstitution:
        return PathJoinSubstitution([*self._parts, other])


class PathSubstitution(PathJoinSubstitution):
    """``PathSubstitution(path)``: each substitution of ``path`` is a path component."""

    def __init__(self, path: Any) -> None:
        parts = [path] if isinstance(path, (str, Substitution)) or _unknown(path) else list(path)
        super().__init__(parts)


class ThisLaunchFile(Substitution):
    """``ThisLaunchFile()``."""

    def describe(self) -> str:
        return "ThisLaunchFile()"

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.ThisLaunchFile()


class ThisLaunchFileDir(PathJoinSubstitution):
    """``ThisLaunchFileDir()``: a ``PathSubstitution`` of itself (``/`` appends)."""

    def __init__(self) -> None:
        super().__init__([self])

    def describe(self) -> str:
        return "ThisLaunchFileDir()"

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.ThisLaunchFileDir()


class LaunchLogDir(PathJoinSubstitution):
    """``LaunchLogDir()``: a ``PathSubstitution`` of itself (``/`` appends)."""

    def __init__(self) -> None:
        super().__init__([self])

    def describe(self) -> str:
        return "LaunchLogDir()"

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.LaunchLogDir()


class AnonName(Substitution):
    """``AnonName(name)``."""

    def __init__(self, name: Any) -> None:
        super().__init__()
        self._name = name

    name = launch_getter("_name", "Return the name as substitutions (launch's API).")

    def describe(self) -> str:
        return f"AnonName({described(self._name)})"

    def compute_name(self, id_value: str) -> str:
        """Return an anonymous name: host, process and a random number, unknown statically."""
        return placeholder("opaque", f"anonymous name for {id_value}")

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.AnonName(cv.sub(self._name))


class LocalSubstitution(Substitution):
    """``LocalSubstitution(expression, description=None)``: a value of ``context.locals``."""

    def __init__(self, expression: str, description: str | None = None) -> None:
        super().__init__()
        self._expression = expression
        self._description = description

    @property
    def expression(self) -> str:
        """Return the expression on ``context.locals`` (launch's API)."""
        return self._expression

    @property
    def description(self) -> str | None:
        """Return the description given (launch's API)."""
        return self._description

    def describe(self) -> str:
        shown = self._expression if self._description is None else self._description
        return f"LocalVar('{shown}')"

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.LocalSub(self._expression)


class NotSubstitution(Substitution):
    """``NotSubstitution(value)``."""

    def __init__(self, value: Any) -> None:
        super().__init__()
        self._value = value

    value = launch_getter("_value", "Return the operand as substitutions (launch's API).")

    def describe(self) -> str:
        return f"NotSubstitution({self.value})"

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.NotSub(cv.sub(self._value))


class _BinarySubstitution(Substitution):
    """What ``AndSubstitution`` and ``OrSubstitution`` share (left and right operands)."""

    func: Any = None

    def __init__(self, left: Any, right: Any) -> None:
        super().__init__()
        self._left, self._right = left, right

    left = launch_getter("_left", "Return the left operand as substitutions (launch's API).")

    right = launch_getter("_right", "Return the right operand as substitutions (launch's API).")

    def describe(self) -> str:
        return f"{type(self).__name__}({self.left} {self.right})"


class AndSubstitution(_BinarySubstitution):
    """``AndSubstitution(left, right)``."""

    func = staticmethod(operator.and_)

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.AndSub(cv.sub(self._left), cv.sub(self._right))


class OrSubstitution(_BinarySubstitution):
    """``OrSubstitution(left, right)``."""

    func = staticmethod(operator.or_)

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.OrSub(cv.sub(self._left), cv.sub(self._right))


class _ContainerSubstitution(Substitution):
    """What ``AnySubstitution`` and ``AllSubstitution`` share."""

    func: Any = None

    def __init__(self, *args: Any, container: Any = None) -> None:
        super().__init__()
        self._args = (*args, *(container or ()))

    @property
    def args(self) -> list[list[Any]]:
        """Return the operands, each as substitutions (launch's API)."""
        return [normalized(arg) for arg in self._args]

    def describe(self) -> str:
        return f"{type(self).__name__}({' '.join(str(arg) for arg in self.args)})"


class AnySubstitution(_ContainerSubstitution):
    """``AnySubstitution(*args, container=None)``."""

    func = staticmethod(any)

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.AnySub(tuple(cv.sub(arg) for arg in self._args))


class AllSubstitution(_ContainerSubstitution):
    """``AllSubstitution(*args, container=None)``."""

    func = staticmethod(all)

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.AllSub(tuple(cv.sub(arg) for arg in self._args))


class EqualsSubstitution(Substitution):
    """``EqualsSubstitution(left, right)``."""

    def __init__(self, left: Any, right: Any) -> None:
        super().__init__()
        self._left, self._right = _equals_text(left), _equals_text(right)

    left = launch_getter("_left", "Return the left operand as substitutions (launch's API).")

    right = launch_getter("_right", "Return the right operand as substitutions (launch's API).")

    def describe(self) -> str:
        return f"{type(self).__name__}({self.left} {self.right})"

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.EqualsSub(cv.sub(self._left), cv.sub(self._right))


class NotEqualsSubstitution(EqualsSubstitution):
    """``NotEqualsSubstitution(left, right)``."""

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.NotEqualsSub(cv.sub(self._left), cv.sub(self._right))


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
        if not if_value and not else_value and not (_unknown(if_value) or _unknown(else_value)):
            raise RuntimeError("One of if_value and else_value must be specified")
        self._condition, self._if_value, self._else_value = condition, if_value, else_value

    condition = launch_getter("_condition",
                              "Return the condition as substitutions (launch's API).")

    if_value = launch_getter("_if_value",
                             "Return the value when true, as substitutions (launch's API).")

    else_value = launch_getter("_else_value",
                               "Return the value when false, as substitutions (launch's API).")

    def describe(self) -> str:
        return f"IfElseSubstitution({self.condition}, {self.if_value}, {self.else_value})"

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.IfElse(cv.sub(self._condition), cv.sub(self._if_value),
                        cv.sub(self._else_value))


class FileContent(Substitution):
    """``FileContent(path)``."""

    def __init__(self, path: Any) -> None:
        super().__init__()
        self._path = path

    path = launch_getter("_path", "Return the file's path as substitutions (launch's API).")

    def describe(self) -> str:
        return f"FileContent({', '.join(sub.describe() for sub in self.path)})"

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.FileContent(cv.sub(self._path))


class StringJoinSubstitution(Substitution):
    """``StringJoinSubstitution(substitutions, delimiter='')`` (kilted, rolling)."""

    def __init__(self, substitutions: Iterable[Any], delimiter: Any = "") -> None:
        super().__init__()
        self._parts = list(substitutions)
        self._delimiter = delimiter

    @property
    def substitutions(self) -> list[list[Any]]:
        """Return the parts, each a list of substitutions (launch's API)."""
        return [normalized(part) for part in self._parts]

    delimiter = launch_getter("_delimiter",
                              "Return the delimiter as substitutions (launch's API).")

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.StringJoin(cv.sub(self._delimiter),
                            tuple(cv.sub(part) for part in self._parts))


class ForEachVar(Substitution):
    """``ForEachVar(name, *, default_value=None)`` (kilted, rolling)."""

    def __init__(self, name: Any, *, default_value: Any = None) -> None:
        super().__init__()
        self._name, self._default_value = name, default_value

    name = launch_getter("_name", "Return the variable's name as substitutions (launch's API).")

    default_value = launch_getter(
        "_default_value", "Return the default as substitutions, or ``None`` (launch's API).")

    @classmethod
    def get_local_arg_name(cls, name: str) -> str:
        """Return the name of the context local holding the value (launch's API)."""
        return f"ForEachVar__{name}"

    def describe(self) -> str:
        return (f"{type(self).__name__}(name={described(self._name)}, "
                f"default_value={described(self._default_value or [])})")

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.ForEachVar(cv.sub(self._name), cv.opt_sub(self._default_value))


class ForLoopIndex(ForEachVar):
    """``ForLoopIndex(name)`` (kilted, rolling)."""

    def __init__(self, name: Any, **kwargs: Any) -> None:
        super().__init__(name)

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.ForLoopIndex(cv.sub(self._name))


# ---------------------------------------------------------------------------- conditions


class IfCondition(Condition):
    """``IfCondition(predicate_expression)``."""

    def __init__(self, predicate_expression: Any) -> None:
        super().__init__()
        self._predicate_expression = check_substitutions(predicate_expression)

    def _predicate_func(self, context: Any) -> bool:
        """Return whether the condition holds in ``context`` (what ``evaluate`` calls)."""
        return Condition.evaluate(self, context)

    def to_condition(self, cv: Converter) -> c.Condition:
        return c.IfCondition(cv.sub(self._predicate_expression))


class UnlessCondition(IfCondition):
    """``UnlessCondition(predicate_expression)`` (an ``IfCondition`` negated, as in launch)."""

    def to_condition(self, cv: Converter) -> c.Condition:
        return c.UnlessCondition(cv.sub(self._predicate_expression))


class LaunchConfigurationEquals(Condition):
    """``LaunchConfigurationEquals(launch_configuration_name, expected_value)``."""

    negate = False

    def __init__(self, launch_configuration_name: str, expected_value: Any) -> None:
        super().__init__()
        self._name, self._expected_value = launch_configuration_name, expected_value

    def _predicate_func(self, context: Any) -> bool:
        """Return whether the condition holds in ``context`` (what ``evaluate`` calls)."""
        return Condition.evaluate(self, context)

    def to_condition(self, cv: Converter) -> c.Condition:
        name = cv.written(self._span, self._name, position=0,
                          keyword="launch_configuration_name")
        return c.ConfigEquals(name, cv.opt_sub(self._expected_value), self.negate)


class LaunchConfigurationNotEquals(LaunchConfigurationEquals):
    """``LaunchConfigurationNotEquals(launch_configuration_name, expected_value)``."""

    negate = True


class FunctionCondition(Condition):
    """``launch.Condition(predicate=callable)``: the predicate runs in OpaqueFunctions."""

    def __init__(self, *, predicate: Any = None) -> None:
        super().__init__()
        self._predicate = predicate

    def evaluate(self, context: Any) -> bool:
        """Call the predicate with ``context`` (``False`` without one), as launch does."""
        if self._predicate is None:
            return False
        return self._predicate(context)  # type: ignore[no-any-return]

    def to_condition(self, cv: Converter) -> c.Condition:
        if self._predicate is None:
            return c.IfCondition(s.Text("false"))
        name = getattr(self._predicate, "__name__", "a callable")
        return c.OpaqueCondition(f"condition {name}()")
