"""The launch API models against the real classes' attribute tables.

``models/launch_api/real_api.json`` lists, for every public class the real ``launch`` and
``launch_ros`` modules launchverify models export, its public attributes (and the private
ones real launch files use, such as conditions' ``_predicate_func``) with their kinds and
parameter lists. It was generated once from launch 3.10.0 and launch_ros 0.30.1 (its
header names the sources); it holds names only, no code of the library.

A class the models do not have at all is fine (launch files get an opaque value and one
LV003); a modelled class must have every listed attribute, unless the allow-lists below
say why not. What a model lacks is still no error in a launch file: reading it gives an
unknown value and one LV003 (tested at the end).
"""

from __future__ import annotations

import ast
import inspect
import json
import textwrap
from functools import cache
from pathlib import Path
from typing import Any

import pytest

from launchverify.engine import CheckOptions, run_check
from launchverify.models.launch_api import MODULES

TABLE = Path(__file__).resolve().parent.parent / "models" / "launch_api" / "real_api.json"

# Attributes deliberately not modelled, keyed "Owner.name" by the real class that defines
# them (so one entry covers its subclasses), "*.name" for every class. Reading one from a
# launch file gives an unknown value and one LV003.
NOT_MODELLED: dict[str, str] = {
    "*.parse": "frontend parsing: launch's XML and YAML parsers call it with their Entity "
               "and Parser objects, launch files never do",
    "Node.parse_nested_parameters": "frontend parsing of <param> entities (as parse)",
    "ExecuteLocal.prepare": "performs the substitutions of the process when the launch runs; "
                            "afterwards launch's getters return the performed values, which "
                            "launchverify does not model",
    "ExecuteLocal.process_description": "launch's Executable description object is not "
                                        "modelled; the getters of ExecuteProcess are",
    "LaunchDescriptionSource.get_launch_description": "loading another launch file from a "
                                                      "launch file's code is not modelled "
                                                      "(IncludeLaunchDescription is)",
    "LaunchDescriptionSource.try_get_launch_description_without_context": "as "
                                                                          "get_launch_description",
    "ComposableLifecycleNode.init_lifecycle_event_manager": "creates launch_ros's lifecycle "
                                                            "event manager, a run-time object",
}

# Real classes whose models deliberately stand for more than one class, or for nothing.
NOT_MODELLED_CLASSES: dict[str, str] = {
    "launch.events.process.process_exited.ProcessExited": "run-time events: launch emits them "
    "when processes run, and launch files meet them only in callables given to event "
    "handlers, which launchverify does not run (LV003); modelled as a plain Event",
    "launch.events.process.process_io.ProcessIO": "run-time event (as ProcessExited)",
    "launch.events.process.process_started.ProcessStarted": "run-time event (as ProcessExited)",
    "launch.events.process.process_stderr.ProcessStderr": "run-time event (as ProcessExited)",
    "launch.events.process.process_stdout.ProcessStdout": "run-time event (as ProcessExited)",
    "launch_ros.events.lifecycle.state_transition.StateTransition": "run-time event emitted by "
    "lifecycle nodes (as ProcessExited)",
    "launch.launch_service.LaunchService": "runs a launch for real: launch files build it only "
    "in `if __name__ == '__main__'` blocks; its model answers every attribute with a no-op",
}


def load_table() -> dict[str, Any]:
    data: dict[str, Any] = json.loads(TABLE.read_text())
    return data


@cache
def assigned_attributes(klass: type) -> frozenset[str]:
    """Return the names a class's methods assign on ``self`` (``self.name = ...``)."""
    try:
        source = textwrap.dedent(inspect.getsource(klass))
    except (OSError, TypeError):
        return frozenset()
    names = set()
    for node in ast.walk(ast.parse(source)):
        targets: list[ast.expr] = []
        if isinstance(node, ast.Assign):
            targets = list(node.targets)
        elif isinstance(node, (ast.AnnAssign, ast.AugAssign)):
            targets = [node.target]
        for target in targets:
            for sub in ast.walk(target):
                if (isinstance(sub, ast.Attribute) and isinstance(sub.value, ast.Name)
                        and sub.value.id == "self"):
                    names.add(sub.attr)
    return frozenset(names)


def model_attributes(model: type) -> set[str]:
    """Return what instances of a model class have: class attributes and assigned ones."""
    names = set(dir(model))
    for klass in model.__mro__:
        if klass.__module__.startswith("launchverify."):
            names |= assigned_attributes(klass)
    return names


def modelled_pairs() -> list[tuple[str, dict[str, Any], type]]:
    """Return (real class, its table entry, model class) for every modelled class."""
    pairs = []
    for key, entry in load_table()["classes"].items():
        seen: set[type] = set()
        for path in entry["exported_as"]:
            module, _, name = path.rpartition(".")
            model = MODULES.get(module, {}).get(name)
            # a bare object stands for a type launch files only name in annotations
            if not isinstance(model, type) or model is object or model in seen:
                continue
            seen.add(model)
            pairs.append((key, entry, model))
    return pairs


def allowed(entry: dict[str, Any], name: str) -> bool:
    owner = entry["attributes"][name]["owner"]
    return f"{owner}.{name}" in NOT_MODELLED or f"*.{name}" in NOT_MODELLED


def test_table_names_its_sources() -> None:
    header = load_table()["header"]
    assert header["generated_from"]["launch"] == "3.10.0"
    assert header["generated_from"]["launch_ros"] == "0.30.1"
    assert not header["modules_not_imported"]
    # every module the table was generated from is still modelled
    assert set(header["modules"]) <= set(MODULES)


def test_enough_classes_are_compared() -> None:
    compared = {key for key, _, _ in modelled_pairs()}
    assert len(compared) >= 100
    for key in ("launch.conditions.if_condition.IfCondition",
                "launch.substitutions.launch_configuration.LaunchConfiguration",
                "launch_ros.actions.node.Node",
                "launch.launch_description.LaunchDescription",
                "launch.launch_context.LaunchContext"):
        assert key in compared


def test_models_have_every_attribute_of_the_real_classes() -> None:
    missing = []
    for key, entry, model in modelled_pairs():
        if key in NOT_MODELLED_CLASSES:
            continue
        have = model_attributes(model)
        for name, info in entry["attributes"].items():
            if name not in have and not allowed(entry, name):
                shown = info["kind"] + (info.get("signature") or "")
                missing.append(f"{key} (model {model.__module__}.{model.__qualname__}): "
                               f"{name} [{shown}, defined by {info['owner']}]")
    assert not missing, "modelled classes lack attributes of the real classes:\n" + "\n".join(
        missing)


def test_allow_lists_are_not_stale() -> None:
    table = load_table()["classes"]
    assert set(NOT_MODELLED_CLASSES) <= set(table)
    used = set()
    for _key, entry, model in modelled_pairs():
        have = model_attributes(model)
        for name, info in entry["attributes"].items():
            for rule in (f"{info['owner']}.{name}", f"*.{name}"):
                if rule in NOT_MODELLED and name not in have:
                    used.add(rule)
    assert set(NOT_MODELLED) == used, f"allow-listed but modelled: {set(NOT_MODELLED) - used}"


def _real_signature(text: str) -> inspect.Signature:
    tree = ast.parse(f"def f{text}: pass")
    function = tree.body[0]
    assert isinstance(function, ast.FunctionDef)
    arguments = function.args
    parameters = []
    positional = [*arguments.posonlyargs, *arguments.args]
    defaults = [None] * (len(positional) - len(arguments.defaults)) + list(arguments.defaults)
    for index, (argument, default) in enumerate(zip(positional, defaults, strict=True)):
        kind = (inspect.Parameter.POSITIONAL_ONLY if index < len(arguments.posonlyargs)
                else inspect.Parameter.POSITIONAL_OR_KEYWORD)
        parameters.append(inspect.Parameter(
            argument.arg, kind, default=inspect.Parameter.empty if default is None else 0))
    if arguments.vararg:
        parameters.append(inspect.Parameter(arguments.vararg.arg,
                                            inspect.Parameter.VAR_POSITIONAL))
    for argument, default in zip(arguments.kwonlyargs, arguments.kw_defaults, strict=True):
        parameters.append(inspect.Parameter(
            argument.arg, inspect.Parameter.KEYWORD_ONLY,
            default=inspect.Parameter.empty if default is None else 0))
    if arguments.kwarg:
        parameters.append(inspect.Parameter(arguments.kwarg.arg, inspect.Parameter.VAR_KEYWORD))
    return inspect.Signature(parameters)


def _calls(real: inspect.Signature) -> list[tuple[list[Any], dict[str, Any]]]:
    """Return call shapes the real method accepts: required only, then every parameter."""
    required: tuple[list[Any], dict[str, Any]] = ([], {})
    full: tuple[list[Any], dict[str, Any]] = ([], {})
    for parameter in list(real.parameters.values())[1:]:  # self / cls
        if parameter.kind in (parameter.VAR_POSITIONAL, parameter.VAR_KEYWORD):
            continue
        if parameter.kind == parameter.KEYWORD_ONLY:
            full[1][parameter.name] = 0
            if parameter.default is parameter.empty:
                required[1][parameter.name] = 0
        else:
            full[0].append(0)
            if parameter.default is parameter.empty:
                required[0].append(0)
    return [required, full]


def test_model_methods_accept_the_real_parameters() -> None:
    wrong = []
    for key, entry, model in modelled_pairs():
        if key in NOT_MODELLED_CLASSES:
            continue
        for name, info in entry["attributes"].items():
            if info["kind"] not in ("method", "classmethod", "staticmethod"):
                continue
            member = inspect.getattr_static(model, name, None)
            if member is None:
                continue
            function = member.__func__ if isinstance(member, (classmethod, staticmethod)) \
                else member
            if not callable(function):
                wrong.append(f"{key}.{name}: not callable in the model")
                continue
            real = _real_signature(info["signature"])
            if info["kind"] == "staticmethod":  # no self: add a placeholder to skip
                real = real.replace(parameters=[inspect.Parameter(
                    "_", inspect.Parameter.POSITIONAL_ONLY), *real.parameters.values()])
            signature = inspect.signature(function)
            for args, kwargs in _calls(real):
                bound = [0] if info["kind"] != "staticmethod" else []
                try:
                    signature.bind(*bound, *args, **kwargs)
                except TypeError as error:
                    wrong.append(f"{key}.{name}{info['signature']}: the model "
                                 f"{signature} refuses it ({error})")
    assert not wrong, "\n".join(wrong)


# Constructors whose models deliberately take other arguments.
OTHER_CONSTRUCTORS: dict[str, str] = {
    "launch.actions.execute_local.ExecuteLocal": "takes launch's Executable description, "
    "which launch files do not build; modelled as ExecuteProcess (cmd=...)",
}


def test_model_constructors_accept_the_real_parameters() -> None:
    wrong = []
    for key, entry, model in modelled_pairs():
        if key in NOT_MODELLED_CLASSES or key in OTHER_CONSTRUCTORS:
            continue
        signature = inspect.signature(model.__init__)
        for args, kwargs in _calls(_real_signature(entry["init"])):
            try:
                signature.bind(0, *args, **kwargs)
            except TypeError as error:
                wrong.append(f"{key}{entry['init']}: the model {signature} refuses it ({error})")
    assert not wrong, "\n".join(wrong)


# ------------------------------------------------------------------ launch files


def _write(folder: Path, name: str, body: str) -> Path:
    path = folder / name
    path.write_text(textwrap.dedent(body))
    return path


def _findings(path: Path) -> list[tuple[str, int, str]]:
    report = run_check(CheckOptions(paths=[path], workspace=path.parent))
    return [(f.code, f.span.line, f.message) for f in report.findings]


def test_unmodelled_attribute_is_unknown_not_an_error(tmp_path: Path) -> None:
    path = _write(tmp_path, "secret.launch.py", """\
        from launch import LaunchDescription
        from launch.conditions import IfCondition
        from launch_ros.actions import Node


        def generate_launch_description():
            condition = IfCondition('true')
            secret = condition._secret(1, 2).deeper
            try:
                condition.__secret_dunder__
            except AttributeError:
                pass
            else:
                raise RuntimeError('dunder names must keep raising AttributeError')
            return LaunchDescription([
                Node(package='demo_nodes_cpp', executable='talker', name=str(secret)),
            ])
        """)
    result = _findings(path)
    assert ("LV003", 8, "IfCondition._secret is not modelled; values from it are unknown"
            ) in result
    assert not [f for f in result if f[0] in ("LV002", "LV005")], result


def test_launch_api_getters_and_evaluation_in_opaque_function(tmp_path: Path) -> None:
    path = _write(tmp_path, "getters.launch.py", """\
        from launch import LaunchContext, LaunchDescription
        from launch.actions import DeclareLaunchArgument, LogInfo, OpaqueFunction
        from launch.conditions import IfCondition, LaunchConfigurationEquals, UnlessCondition
        from launch.substitutions import (
            LaunchConfiguration, PathJoinSubstitution, PythonExpression, TextSubstitution,
            ThisLaunchFileDir)
        from launch.utilities import perform_substitutions
        from launch_ros.actions import Node


        def setup(context):
            robot = LaunchConfiguration('robot')
            values = [
                IfCondition(PythonExpression(["'", robot, "' == 'alpha'"]))._predicate_func(
                    context),
                UnlessCondition('false').evaluate(context),
                LaunchConfigurationEquals('robot', 'alpha')._predicate_func(context),
                robot.perform(context),
                robot.describe(),
                perform_substitutions(context, robot.variable_name),
                TextSubstitution(text='t').describe(),
                PathJoinSubstitution(['a', robot]).perform(context),
            ]
            node = Node(package='demo_nodes_cpp', executable='talker', name='talker')
            values += [node.node_package, node.node_executable, node.condition]
            try:
                node.node_name
            except RuntimeError:
                values.append('no name before execution')
            fresh = LaunchContext()
            fresh.extend_globals({'answer': 42})
            values.append(fresh.locals.answer)
            return [LogInfo(msg=repr(values))]


        def generate_launch_description():
            description = LaunchDescription([
                DeclareLaunchArgument('robot', default_value='alpha')])
            description.add_action(OpaqueFunction(function=setup))
            assert description.entities[0].name == 'robot'
            assert [a.name for a in description.get_launch_arguments()] == ['robot']
            assert description.describe_sub_entities() is description.entities
            assert not description.deprecated
            assert isinstance(ThisLaunchFileDir() / 'config', PathJoinSubstitution)
            return description
        """)
    report = run_check(CheckOptions(paths=[path], workspace=tmp_path))
    assert not [f for f in report.findings if f.code in ("LV002", "LV003", "LV005")], [
        (f.code, f.span.line, f.message) for f in report.findings]
    from launchverify.frontends.python import load_python
    from launchverify.problems import ProblemSink

    launch_file = load_python(path, ProblemSink(), None, tmp_path)
    assert launch_file is not None
    result = launch_file.actions[-1].run({"robot": "alpha"}, path)  # type: ignore[attr-defined]
    assert not result.problems
    (log,) = result.actions
    text = "".join(getattr(part, "text", "?") for part in getattr(
        log.message, "parts", [log.message]))
    assert text == repr([True, True, True, "alpha", "LaunchConfig('robot')", "robot", "'t'",
                         "a/alpha", "demo_nodes_cpp", "talker", None,
                         "no name before execution", 42])


def test_only_the_launch_files_code_gets_unknown_values(tmp_path: Path) -> None:
    """launchverify's own probes (``getattr(x, name, default)``) keep their AttributeError."""
    from launchverify.models.launch_api import base, runtime
    from launchverify.models.launch_api.launch_substitutions import IfCondition
    from launchverify.models.launch_api.unknown import Opaque
    from launchverify.workspace.packages import PackageIndex

    reported: list[str] = []
    condition = IfCondition("true")
    with pytest.raises(AttributeError):  # outside an evaluation: plain Python
        condition._secret  # noqa: B018
    runtime.current = runtime.Runtime(PackageIndex(), tmp_path,
                                      lambda what, span: reported.append(what),
                                      tmp_path / "x.launch.py")
    try:
        assert not base._unknown(condition)  # launchverify's hasattr(value, '_description')
        assert getattr(condition, "__wrapped__", "none") == "none"  # dunders: never
        value = condition._secret  # this file is not launchverify's: the launch file's code
        assert isinstance(value, Opaque)
    finally:
        runtime.current = None
    assert reported == ["IfCondition._secret is not modelled; values from it are unknown"]


def test_user_substitution_without_base_init_is_unknown_not_broken(tmp_path: Path) -> None:
    """rtabmap_ros's ConditionalText skips Substitution.__init__: launchverify's probe of
    its ``_span`` must still fall back (an LV003 at the user's line, nothing else)."""
    path = _write(tmp_path, "custom.launch.py", """\
        from launch import LaunchDescription, Substitution
        from launch_ros.actions import Node


        class ConditionalText(Substitution):
            def __init__(self, text_if, text_else, condition):
                self.text_if, self.text_else, self.condition = text_if, text_else, condition

            def perform(self, context):
                return self.text_if if self.condition else self.text_else


        def generate_launch_description():
            return LaunchDescription([
                Node(package='demo_nodes_cpp', executable='talker',
                     name=ConditionalText('a', 'b', True)),
            ])
        """)
    result = _findings(path)
    assert [code for code, _, _ in result] == ["LV003"], result
    assert result[0][2] == "substitution ConditionalText is not modelled; its value is unknown"
