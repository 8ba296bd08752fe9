"""Models of ``LaunchContext`` and ``launch.utilities``, for OpaqueFunction bodies.

An OpaqueFunction runs with a concrete context: the launch configurations as they are
under the arguments being evaluated. Performing a substitution there gives a string; what
is unknown comes back as a placeholder.
"""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path
from typing import Any

from launchverify.models.launch_api.base import Modelled, Substitution, _unknown
from launchverify.models.launch_api.launch_substitutions import TextSubstitution
from launchverify.models.launch_api.placeholders import has_placeholder
from launchverify.models.launch_api.unknown import LAUNCH_BUILTINS, Opaque


class LaunchContext(Modelled):
    """``launch.LaunchContext`` as an OpaqueFunction sees it."""

    def __init__(self, *, argv: Any = None, noninteractive: bool = False,
                 configurations: dict[str, str] | None = None,
                 performer: Callable[[Any], str] | None = None,
                 condition_evaluator: Callable[[Any], bool] | None = None,
                 launch_file: str = "") -> None:
        self._argv = argv if argv is not None else []
        self._noninteractive = noninteractive
        self._launch_configurations = RecordingDict(configurations or {})
        if performer is None:  # a context the launch file made itself: a fresh one
            from launchverify.models.launch_api import runtime

            tools = runtime.current.context_tools if runtime.current is not None else None
            if tools is not None:
                performer, condition_evaluator = tools(self._launch_configurations)
        self._performer = performer
        self._condition_evaluator = condition_evaluator
        self._globals: dict[str, Any] = {}
        self._locals: dict[str, Any] = {}
        self._unknown_names = False  # extended by a mapping of code launchverify cannot see
        if launch_file:  # what IncludeLaunchDescription sets for the file it includes
            self._locals.update(current_launch_file_path=launch_file,
                                current_launch_file_directory=str(Path(launch_file).parent))
        self._event_handlers: list[Any] = []

    @property
    def argv(self) -> Any:
        """Return the command line arguments given to the launch (launch's API)."""
        return self._argv

    @property
    def noninteractive(self) -> bool:
        """Return whether the launch is non-interactive (launch's API)."""
        return self._noninteractive

    @property
    def launch_configurations(self) -> RecordingDict:
        """Return the launch configurations in scope (launch's API)."""
        return self._launch_configurations

    @property
    def environment(self) -> Any:
        """Return the environment: ``os.environ``, as launch does (robot values unknown)."""
        return os.environ

    @property
    def is_shutdown(self) -> bool:
        """Return whether the launch is shutting down: statically it never is."""
        return False

    @property
    def asyncio_loop(self) -> None:
        """Return launch's event loop: statically there is none."""
        return None

    @property
    def locals(self) -> _AttributeDict:
        """Return the locals (and globals) as read-only attributes (launch's API)."""
        return _AttributeDict(self.get_locals_as_dict(), unknown_names=self._unknown_names)

    def get_locals_as_dict(self) -> dict[str, Any]:
        """Return the globals, overridden by the locals (launch's API)."""
        return {**self._globals, **self._locals}

    def extend_globals(self, extensions: dict[str, Any]) -> None:
        """Add globals (launch's API); a vendor's mapping adds names nobody can list."""
        self._unknown_names |= _unknown(extensions)
        self._globals.update(extensions)

    def extend_locals(self, extensions: dict[str, Any]) -> None:
        """Add locals (launch's API); a vendor's mapping adds names nobody can list."""
        self._unknown_names |= _unknown(extensions)
        self._locals.update(extensions)

    def perform_substitution(self, substitution: Any) -> str:
        """Return the value of a substitution under this context's configurations."""
        if self._performer is None:
            raise RuntimeError("this LaunchContext cannot perform substitutions")
        return self._performer(substitution)

    def evaluate_condition(self, condition: Any) -> bool:
        """Return whether a condition holds under this context's configurations."""
        if self._condition_evaluator is None:
            raise RuntimeError("this LaunchContext cannot evaluate conditions")
        return self._condition_evaluator(condition)

    def register_event_handler(self, event_handler: Any, append: bool = False) -> None:
        """Accept a handler registration (statically no event happens)."""
        if append:
            self._event_handlers.append(event_handler)
        else:
            self._event_handlers.insert(0, event_handler)

    def unregister_event_handler(self, event_handler: Any) -> None:
        """Remove a registered handler (``ValueError`` when it is not, as launch raises)."""
        self._event_handlers.remove(event_handler)

    def would_handle_event(self, event: Any) -> bool:
        """Return whether a registered handler matches ``event`` (launch's API)."""
        return any(handler.matches(event) for handler in self._event_handlers)

    def emit_event_sync(self, event: Any) -> None:
        """Queue an event (launch's API): statically events are not processed."""

    async def emit_event(self, event: Any) -> None:
        """Queue an event (launch's API, a coroutine): statically events are not processed."""

    def add_completion_future(self, completion_future: Any) -> None:
        """Accept a future launch would wait for (launch's API): statically none runs."""


class _AttributeDict:
    """What ``LaunchContext.locals`` returns: the locals as read-only attributes."""

    def __init__(self, values: dict[str, Any], *, unknown_names: bool = False) -> None:
        self.__dict__["_values"] = values
        self.__dict__["_unknown_names"] = unknown_names

    def __getattr__(self, key: str) -> Any:
        values = self.__dict__["_values"]
        if key not in values and (self.__dict__["_unknown_names"] or _unknown(key)):
            return Opaque(f"context.locals.{key}")  # a vendor's mapping may hold it
        if key not in values:
            raise AttributeError(f"context.locals does not contain attribute '{key}', it "
                                 f"contains: [{', '.join(values)}]")
        return values[key]

    def __setattr__(self, key: str, value: Any) -> None:
        raise AttributeError(f"can't set attribute '{key}', locals are read-only")


class MissingConfiguration(KeyError):
    """A configuration the OpaqueFunction reads but nobody set."""

    @property
    def configuration(self) -> str:
        """Return the name read."""
        return str(self.args[0])


class RecordingDict(dict[str, str]):
    """The configurations an OpaqueFunction sees; remembers which ones it read.

    Reading them as a whole (iterating, measuring, copying, comparing or printing them)
    sets ``whole``: what the function does may then depend on any of them.
    """

    def __init__(self, values: dict[str, str]) -> None:
        super().__init__(values)
        self.read: list[tuple[str, bool, bool]] = []  # name, found, has a default
        self.whole = False

    def __getitem__(self, key: str) -> str:
        found = super().__contains__(key)
        if not found and isinstance(key, str) and has_placeholder(key):
            self.whole = True  # a name only the robot knows: it may be any of them
            return Opaque(f"the launch configuration {key}")
        self.read.append((key, found, False))
        if not found:
            raise MissingConfiguration(key)
        return super().__getitem__(key)

    def get(self, key: str, default: Any = None) -> Any:
        self.read.append((key, super().__contains__(key), True))
        return super().get(key, default)

    def __contains__(self, key: object) -> bool:
        if isinstance(key, str):
            self.read.append((key, super().__contains__(key), True))
        return super().__contains__(key)

    def setdefault(self, key: str, default: Any = None) -> Any:
        self.read.append((key, super().__contains__(key), True))
        return super().setdefault(key, default)

    def pop(self, key: str, *default: Any) -> Any:
        self.read.append((key, super().__contains__(key), bool(default)))
        return super().pop(key, *default)


def _reading_all(name: str) -> Callable[..., Any]:
    """Return ``dict``'s method ``name``, noting that the mapping is read as a whole."""
    method = getattr(dict, name)

    def whole(self: RecordingDict, *args: Any, **kwargs: Any) -> Any:
        self.whole = True
        return method(self, *args, **kwargs)

    whole.__name__ = name
    return whole


# Overriding ``__iter__`` also takes ``dict(d)``, ``{**d}`` and ``f(**d)`` off CPython's
# fast path, through ``keys``; ``repr`` and comparisons read the entries in C.
for _name in ("__iter__", "__len__", "__reversed__", "__repr__", "__eq__", "__ne__",
              "__or__", "__ror__", "__reduce__", "__reduce_ex__", "keys", "values", "items",
              "copy", "popitem"):
    setattr(RecordingDict, _name, _reading_all(_name))


def normalize_to_list_of_substitutions(subs: Any) -> list[Any]:
    """``launch.utilities.normalize_to_list_of_substitutions``."""
    def one(item: Any) -> Any:
        if isinstance(item, Substitution):
            return item
        if isinstance(item, (str, Path)):
            return TextSubstitution(text=str(item))
        if _unknown(item):
            return item
        raise TypeError(f"Failed to normalize given item of type '{type(item)}', when only "
                        "'str' or 'launch.Substitution' were expected.")

    if isinstance(subs, (str, Path, Substitution)) or _unknown(subs):
        return [one(subs)]
    return [one(item) for item in subs]


def perform_substitutions(context: LaunchContext, subs: Any) -> str:
    """``launch.utilities.perform_substitutions``."""
    if _unknown(context):  # a context from code launchverify cannot see: the text is unknown
        from launchverify.models.launch_api.unknown import Opaque

        return Opaque("perform_substitutions(an unknown context)")
    return "".join(context.perform_substitution(s) if isinstance(s, Substitution) else str(s)
                   for s in normalize_to_list_of_substitutions(subs))


_SCALARS = (int, float, bool, str)
# the launch file's ``int`` and ``float`` (they keep an unknown unknown) are Python's
_PYTHON_TYPES: dict[Any, type] = {LAUNCH_BUILTINS["int"]: int, LAUNCH_BUILTINS["float"]: float}


def _extract_type(data_type: Any) -> tuple[Any, bool]:
    """``extract_type``: ``List[int]`` -> ``(int, True)``, ``bool`` -> ``(bool, False)``."""
    arguments = getattr(data_type, "__args__", None)
    if getattr(data_type, "__origin__", None) is list and arguments:
        return _PYTHON_TYPES.get(arguments[0], arguments[0]), True
    data_type = _PYTHON_TYPES.get(data_type, data_type)
    if data_type not in _SCALARS:
        raise ValueError(f"Unrecognized data type: {data_type}")
    return data_type, False


def _valid(value: Any) -> bool:
    if isinstance(value, list):
        member = next((type(x) for x in value if type(x) is not str), str)
        return member in _SCALARS and all(isinstance(x, member) for x in value)
    return isinstance(value, _SCALARS)


def coerce_to_type(value: str, data_type: Any = None) -> Any:
    """``launch.utilities.type_utils.coerce_to_type``: YAML rules, or the type asked for."""
    import yaml

    if _unknown(data_type) or has_placeholder(value):  # a vendor's type or text: unknown
        return Opaque(f"{value} as {data_type}")

    def as_yaml(text: str, message: str) -> Any:
        if not text:
            return text
        try:
            output = yaml.safe_load(text)
        except Exception as error:
            raise ValueError(f"{message}: yaml.safe_load() failed\n{error}") from None
        if not _valid(output):
            raise ValueError(f"{message}: output type is not allowed, got {type(output)}")
        return output

    if data_type is None:
        return as_yaml(value, f"Failed to convert '{value}' using yaml rules")
    kind, is_list = _extract_type(data_type)
    if is_list:
        output = as_yaml(value, f"Cannot convert value '{value}' to a list of '{kind}'")
        if not isinstance(output, list) or not all(isinstance(x, kind) for x in output):
            raise ValueError(f"Cannot convert value '{value}' to a list of '{kind}'")
        return output
    if kind is str:
        return value
    if kind in (int, float):
        return kind(value)
    if kind is bool:
        value = {"1": "true", "0": "false"}.get(value, value)
    output = as_yaml(value, f"Failed to convert '{value}' to '{kind}'")
    if isinstance(output, kind):
        return output
    raise ValueError(f"Cannot convert value '{value}' to '{kind}'")


def perform_typed_substitution(context: LaunchContext, value: Any, data_type: Any) -> Any:
    """``launch.utilities.type_utils.perform_typed_substitution``."""
    if _unknown(value) or _unknown(data_type):  # a vendor's value or type: unknown
        return Opaque(f"{value} as {data_type}")
    if isinstance(value, _SCALARS):
        if data_type is not None and not isinstance(value, _extract_type(data_type)[0]):
            raise TypeError(f"value=`{value}` is a scalar and not an instance of `{data_type}`")
        return value
    if isinstance(value, (Substitution, list)) and all(
            isinstance(item, Substitution) for item in (
                value if isinstance(value, list) else [value])) and value != []:
        return coerce_to_type(perform_substitutions(context, value), data_type)
    if isinstance(value, list):
        kind = _extract_type(data_type)[0] if data_type is not None else None
        return [coerce_to_type(perform_substitutions(context, item), kind)
                if isinstance(item, (list, Substitution)) else item for item in value]
    return coerce_to_type(perform_substitutions(context, value), data_type)
