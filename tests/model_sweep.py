"""The calls the model sweep makes: every modelled callable, each parameter an unknown.

Enumerated from ``MODULES`` (what launch files can import), never from a list of names, so
a model is swept the day it is exported. Each callable's required parameters get known
values (from their annotations, else from ``KNOWN_BY_NAME``); one parameter at a time gets
an unknown of each ``SHAPES`` instead. The calls of one callable are written into one
launch file, which the real pipeline checks (``tests/test_model_sweep.py``).
"""

from __future__ import annotations

import inspect
import json
import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from launchverify.models.launch_api import MODULES

# An unknown of each shape, as a launch file's code makes it from an absent module, and
# its concrete twin: the same call with a valid value in the unknown's place. ``None``:
# the unknown stands for any value, so for the parameter's valid one; ``{item}``: a known
# structure holding unknowns, whose twin holds the parameter's valid item instead.
SHAPES: dict[str, tuple[str, str | None]] = {
    "scalar": ("vendor.value", None),
    "joined": ("vendor.value + '_suffix'", None),
    "unknown list": ("vendor.get_list()", None),
    "callable": ("vendor.function", None),
    "class": ("vendor.Class", None),
    "instance of a derived class": ("Derived()", None),
    "formatted": ("f'{vendor.value}/x'", 'f"{{{item}}}/x"'),
    "list of unknowns": ("[vendor.item, 'known']", "[{item}, 'known']"),
    "comprehension": ("[item for item in vendor.items]", "[item for item in [{item}]]"),
    "appended list": ("_appended()", "[{item}, '']"),
    "dict of unknowns": ("{'key': vendor.value}", "{{'key': {item}}}"),
    "dict with unknown key": ("{vendor.key: 'v'}", "{{{item}: 'v'}}"),
}

# Known values where the annotation says nothing (``Any``): by the parameter's meaning, as
# launch documents it. A required parameter missing here and not annotated fails the
# sweep with its name, so a new model cannot be skipped silently.
KNOWN_BY_NAME = {
    "name": "'x'", "value": "'v'", "package": "'demo_nodes_cpp'",
    "package_name": "'demo_nodes_cpp'", "executable": "'talker'",
    "launch_file_path": "EMPTY_LAUNCH", "function": "_returns_nothing", "left": "'true'",
    "right": "'true'", "file_path": "PARAMS", "actions": "[]", "namespace": "'ns'",
    "source_file": "PARAMS", "msg": "'m'", "event_handler": "OnShutdown(on_shutdown=[])",
    "period": "1.0", "path": "PARAMS", "expression": "'1 + 1'", "substitutions": "['a', 'b']",
    "predicate_expression": "'true'", "launch_configuration_name": "'x'",
    "expected_value": "'v'", "process_matcher": "_matches_any", "subs": "'s'",
    "context": "context", "node_name": "'/x'", "resource_type": "'packages'",
    "resource_name": "'demo_nodes_cpp'", "event": "ShutdownEvent()", "cmd": "['echo', 'a']",
    "launch_description_source": "PythonLaunchDescriptionSource(EMPTY_LAUNCH)",
    "input_values": "'a;b'", "length": "2", "coroutine": "_coroutine", "command": "'echo a'",
    "condition": "IfCondition('true')", "variable_name": "'x'", "text": "'t'",
    "on_completion": "[]", "on_exit": "[]", "on_start": "[]", "on_shutdown": "[]",
    "target_action": "None", "signal_number": "2", "data_type": "str",
    "lifecycle_node_names": "['/x']", "transition_ids": "[1]",
    "target_driver": "None", "nodes_to_start": "[]", "driver_node": "None",
    "composable_node_descriptions": "[]", "target_container": "'/container'",
    "filename": "PARAMS", "src": "'/a'", "dst": "'/b'", "new_log_dir": "'log'",
    "plugin": "'demo_nodes_cpp::Talker'", "param_file": "PARAMS", "entities": "[]",
    "lifecycle_node_matcher": "matches_node_name('/x')", "transition_id": "1",
    "robots_substitution": "''", "replacements": "{}", "param_rewrites": "{}",
    "output_filename": "'out.urdf'", "inp": "XACRO", "doc": "xacro.parse(XACRO)",
    "input_file_name": "XACRO", "controller_names": "['c']", "controller_info_dict": "{}",
    "controller_name": "'c'", "robot_name": "'panda'", "ld": "LaunchDescription()",
    "bridge_name": "'b'",
    "moveit_config": "MoveItConfigsBuilder('panda', package_name=PANDA).to_moveit_configs()",
}

# Parameters valid only together, which no signature says (launch's own checks).
TOGETHER = {
    "IfElseSubstitution": {"if_value": "'a'"},  # "one of if_value and else_value"
    "LaunchDescriptionSource": {"launch_description": "LaunchDescription()"},  # or nothing
    "MoveItConfigsBuilder": {"package_name": "PANDA"},  # a released one: no LV303
    # ``**kwargs`` handed to Node and ComposableNode, which require them
    "LifecycleNode": {"executable": "'talker'"},
    "ComposableNodeContainer": {"executable": "'component_container'",
                                "package": "'rclcpp_components'"},
    "ComposableLifecycleNode": {"package": "'demo_nodes_cpp'",
                                "plugin": "'demo_nodes_cpp::Talker'"},
    "NotSubstitution": {"value": "'true'"},  # performs to a boolean: 'v' raises
}

_REAL_API = json.loads((Path(__file__).resolve().parent.parent / "models" / "launch_api"
                        / "real_api.json").read_text())["classes"]


def real_parameters(modelled: Modelled) -> set[str]:
    """Return the names the real class's constructor takes (the model's own, if unlisted).

    A model may take more (``LaunchContext(configurations=...)``, for launchverify's own
    use): launch files never pass those.
    """
    own = {p.name for p in parameters(modelled.target) or []}
    for real in _REAL_API.values():
        if modelled.label in real.get("exported_as", ()):
            return {name for name in own if re.search(rf"\b{name}\b", real.get("init", ""))}
    return own

# By annotation, where it says enough.
KNOWN_BY_ANNOTATION = {
    "str": "'a'", "bool": "False", "int": "0", "float": "1.0", "LaunchContext": "context",
}

HEADER = '''\
import os

import vendor
import xacro
from launch import Action, Condition, LaunchDescription, LaunchDescriptionSource, Substitution
from launch.actions import GroupAction, IncludeLaunchDescription, LogInfo, OpaqueFunction
from launch.actions import RegisterEventHandler
from launch.actions import DeclareLaunchArgument
from launch.conditions import IfCondition, LaunchConfigurationEquals
from launch.event_handlers import OnShutdown
from launch.events import Shutdown as ShutdownEvent
from launch.launch_description_sources import PythonLaunchDescriptionSource
from launch_ros.actions import Node, SetParameter
from launch_ros.descriptions import Parameter, ParameterFile, ParameterValue
from launch_ros.events import matches_node_name
from moveit_configs_utils import MoveItConfigsBuilder

HERE = os.path.dirname(__file__)
EMPTY_LAUNCH = os.path.join(HERE, 'empty.launch.py')
PARAMS = os.path.join(HERE, '..', 'config', 'params.yaml')
PANDA = 'moveit_resources_panda_moveit_config'
XACRO = os.path.join(HERE, '..', 'urdf', 'robot.urdf.xacro')


exec(compile(HELPERS, '<sweep helpers>', 'exec'), globals())
'''

# The helpers run as code no finding may point at (a file name in brackets): a finding
# about what a call made points at the call's line.
HELPERS = '''\
class Derived(vendor.Base):
    pass


def _appended():
    models = vendor.get_models()
    models.append('')
    return models


def _returns_nothing(*args, **kwargs):
    return []


def _matches_any(*args, **kwargs):
    return True


async def _coroutine(*args, **kwargs):
    return None


# Loop variables mean something only inside their loop.
NOT_PLACED = {'ForEachVar', 'ForLoopIndex'}


def _used(made):
    """Return what uses what a call made in a description (by type: no unknown is asked)."""
    kind = type(made)
    if made is None or kind is type or kind.__name__ in NOT_PLACED:
        return []
    if issubclass(kind, LaunchDescription):
        return [IncludeLaunchDescription(LaunchDescriptionSource(made))]
    if issubclass(kind, Action):
        return [made]
    if issubclass(kind, Substitution):
        return [LogInfo(msg=[made])]
    if issubclass(kind, Condition):
        return [GroupAction([], condition=made)]
    if issubclass(kind, LaunchDescriptionSource):
        return [IncludeLaunchDescription(made)]
    if kind.__name__.startswith('On') or kind.__name__ == 'EventHandler':
        return [RegisterEventHandler(made)]
    if issubclass(kind, ParameterValue):
        return [Node(package='demo_nodes_cpp', executable='talker', parameters=[{'p': made}])]
    if issubclass(kind, (Parameter, ParameterFile)):
        return [Node(package='demo_nodes_cpp', executable='talker', parameters=[made])]
    if issubclass(kind, str):
        return [LogInfo(msg=made)]
    return []


def _case(number, made):
    """Return the call's case: what it made, alone under ``case:=number``.

    Each case excludes the others: the rules see every call, never two together.
    """
    return GroupAction(_used(made), condition=LaunchConfigurationEquals('case', number))


def _declared():
    """Return what the known values read (a configuration, a parameter) declared."""
    return [DeclareLaunchArgument('case', default_value='none'),
            DeclareLaunchArgument('x', default_value='v'), SetParameter(name='x', value='v')]
'''

CONTEXT_HEADER = '''

def _in_context(context):
    out = []
'''

BODY = '''

def generate_launch_description():
    out = _declared()
'''

FOOTER = '''\
    out.append(OpaqueFunction(function=_in_context))
    return LaunchDescription(out)
'''


@dataclass(frozen=True)
class Modelled:
    """One callable launch files can import, as they import it."""

    module: str
    name: str
    target: Callable[..., Any]

    @property
    def label(self) -> str:
        return f"{self.module}.{self.name}"


def modelled_callables() -> list[Modelled]:
    """Return every class and function ``MODULES`` exports, each once (first module)."""
    seen: dict[int, Modelled] = {}
    for module, exports in MODULES.items():
        for name, target in exports.items():
            if (inspect.isclass(target) or inspect.isfunction(target)) \
                    and id(target) not in seen:
                seen[id(target)] = Modelled(module, name, target)
    return list(seen.values())


def parameters(target: Callable[..., Any]) -> list[inspect.Parameter] | None:
    """Return the parameters a launch file may pass by name (``None``: no signature)."""
    try:
        signature = inspect.signature(target)
    except (TypeError, ValueError):
        return None
    return [p for p in signature.parameters.values()
            if p.kind in (p.POSITIONAL_OR_KEYWORD, p.KEYWORD_ONLY)]


class NoKnownValue(LookupError):
    """A required parameter the sweep cannot give a known value."""


def known_value(parameter: inspect.Parameter) -> str:
    """Return a launch file's expression for a valid value of a required parameter."""
    if parameter.name in KNOWN_BY_NAME:
        return KNOWN_BY_NAME[parameter.name]
    annotation = str(parameter.annotation).strip("'")
    base = annotation.partition("[")[0].partition(" |")[0]
    if base in KNOWN_BY_ANNOTATION:
        return KNOWN_BY_ANNOTATION[base]
    if base in ("Iterable", "list", "Sequence"):
        return "[]"
    if base in ("Mapping", "dict"):
        return "{}"
    raise NoKnownValue(f"parameter {parameter.name!r} ({annotation}): add a known value to "
                       "KNOWN_BY_NAME")


@dataclass(frozen=True)
class Case:
    """One call with one parameter unknown, and its twin with a valid value there."""

    what: str
    unknown: str
    twin: str


def calls(modelled: Modelled) -> Iterator[Case]:
    """Yield the callable's cases: each parameter, each shape of unknown.

    The first case gives only known values (its twin is itself): the sweep fails if the
    table's values are themselves invalid.
    """
    params = parameters(modelled.target)
    if params is None:
        return
    real = real_parameters(modelled)  # required ones stay: the model needs them
    params = [p for p in params if p.default is p.empty or p.name in real]
    required = {p.name: known_value(p) for p in params if p.default is p.empty}
    required.update(TOGETHER.get(modelled.name, {}))
    plain = _call(required)
    yield Case("known values", plain, plain)
    swept = list(params)
    if isinstance(modelled.target, type) and _is_action(modelled.target):
        swept.append(inspect.Parameter("condition", inspect.Parameter.KEYWORD_ONLY,
                                       default=None))  # every action takes one
    for parameter in swept:
        name = parameter.name
        valid = required.get(name)
        item = valid if valid is not None and not valid.startswith(("[", "{")) else (
            repr(parameter.default) if isinstance(parameter.default, (str, bool, int, float))
            else "'v'")
        for shape, (expression, twin) in SHAPES.items():
            others = {k: v for k, v in required.items() if k != name}
            if twin is None:
                concrete = _call({**others, name: valid}) if valid is not None \
                    else _call(others)
            else:
                concrete = _call({**others, name: twin.format(item=item)})
            yield Case(f"{name}={shape}", _call({**others, name: expression}), concrete)


def _is_action(klass: type) -> bool:
    return any(base.__name__ == "Action" and base.__module__.endswith("base")
               for base in klass.__mro__)


def _call(arguments: dict[str, str]) -> str:
    return "target(" + ", ".join(f"{k}={v}" for k, v in arguments.items()) + ")"


def launch_file(modelled: Modelled, cases: dict[int, str]) -> str:
    """Return a launch file making the numbered calls at the top level and in a context.

    Each call is one line (``case_line`` finds it again), so that a finding's line says
    which call it is about.
    """
    header = HEADER.replace("compile(HELPERS", f"compile({HELPERS!r}")
    lines = [header, f"from {modelled.module} import {modelled.name} as target\n"]
    for header in (CONTEXT_HEADER, BODY):
        lines.append(header)
        lines.extend(f"    out.append(_case('{number}', {call}))  # case {number}\n"
                     for number, call in cases.items()
                     if header is CONTEXT_HEADER or "context" not in call)
        if header is CONTEXT_HEADER:
            lines.append("    return out\n")
    lines.append(FOOTER)
    return "".join(lines)


def case_of(text: str, line: int) -> int | None:
    """Return the case a line of a sweep's launch file calls (``None``: no call)."""
    lines = text.splitlines()
    if not 0 < line <= len(lines):
        return None
    _, marked, number = lines[line - 1].partition("# case ")
    return int(number) if marked else None


PACKAGE_XML = """<?xml version="1.0"?>
<package format="3">
  <name>sweep_pkg</name>
  <version>0.0.0</version>
  <description>The model sweep's package</description>
  <maintainer email="a@b.c">a</maintainer>
  <license>MIT</license>
  <exec_depend>demo_nodes_cpp</exec_depend>
  <exec_depend>xacro</exec_depend>
</package>
"""

XACRO_FILE = """<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="r"><link name="base"/></robot>
"""


def package(root: Path) -> Path:
    """Write the sweep's package (its launch folder holds the files to check)."""
    (root / "launch").mkdir(parents=True)
    (root / "config").mkdir()
    (root / "urdf").mkdir()
    (root / "package.xml").write_text(PACKAGE_XML)
    (root / "config" / "params.yaml").write_text("x:\n  ros__parameters:\n    a: 1\n")
    (root / "urdf" / "robot.urdf.xacro").write_text(XACRO_FILE)
    (root / "launch" / "empty.launch.py").write_text(
        "from launch import LaunchDescription\n\n\n"
        "def generate_launch_description():\n    return LaunchDescription([])\n")
    return root / "launch"
