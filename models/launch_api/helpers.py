"""Models of helper libraries real launch files use: nav2_common, xacro.

``RewrittenYaml`` and ``ReplaceString`` write a temporary file at launch time; statically
they are named by their source file, and what they substitute counts as read; what
``RewrittenYaml`` does to parameters is kept for the file's readers
(``models/rewritten_yaml.py``). ``xacro`` documents become an opaque robot description.
"""

from __future__ import annotations

import inspect
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from launchverify.ir import subst as s
from launchverify.models import distros, rewritten_yaml
from launchverify.models.launch_api.base import Converter, Substitution, _unknown
from launchverify.models.launch_api.placeholders import has_placeholder, placeholder
from launchverify.models.launch_api.runtime import active
from launchverify.workspace.paths import resolved


def _values(mapping: Mapping[Any, Any] | None) -> list[Any]:
    if _unknown(mapping):
        return [mapping]  # a vendor's mapping: what it holds is an unknown input
    if not mapping:
        return []
    return [item for pair in mapping.items() for item in pair]


def _text_keys(mapping: Mapping[Any, Any] | None) -> list[tuple[str, Any]]:
    if _unknown(mapping):
        return []  # its keys are unknown: ``_other_keys`` keeps it as an input
    return [(key, value) for key, value in (mapping or {}).items() if isinstance(key, str)]


def _other_keys(mapping: Mapping[Any, Any] | None) -> list[Any]:
    """Return the entries whose key is not text, flattened (read, not followed)."""
    if _unknown(mapping):
        return [mapping]
    return [item for key, value in (mapping or {}).items() if not isinstance(key, str)
            for item in (key, value)]


class RewrittenYaml(Substitution):
    """``nav2_common.launch.RewrittenYaml(source_file, param_rewrites, root_key=None, ...)``."""

    def __init__(self, source_file: Any, param_rewrites: Mapping[Any, Any],
                 root_key: Any = None, key_rewrites: Mapping[Any, Any] | None = None,
                 value_rewrites: Mapping[Any, Any] | None = None, convert_types: bool = False,
                 out_dir: Any = None) -> None:
        super().__init__()
        self.source_file = source_file
        self.params = _text_keys(param_rewrites)
        self.values = _text_keys(value_rewrites)
        self.inputs = [*_other_keys(param_rewrites), *_other_keys(value_rewrites),
                       *_values(key_rewrites)]
        # what else it rewrites is not followed, nor values of types not known here
        self.exact = not self.inputs and isinstance(convert_types, bool)
        self.root_key = root_key
        self.convert = convert_types is True

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.Rewritten(cv.sub(self.source_file), tuple(cv.sub(x) for x in self.inputs),
                           rewritten_yaml.HELPER, cv.opt_sub(self.root_key),
                           tuple((key, cv.sub(value)) for key, value in self.params),
                           tuple((key, cv.sub(value)) for key, value in self.values),
                           self.exact, self.convert)


class ReplaceString(Substitution):
    """``nav2_common.launch.ReplaceString(source_file, replacements, condition=None)``."""

    def __init__(self, source_file: Any, replacements: Mapping[Any, Any],
                 condition: Any = None) -> None:
        super().__init__()
        self.source_file = source_file
        self.inputs = _values(replacements)

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.Rewritten(cv.sub(self.source_file), tuple(cv.sub(x) for x in self.inputs),
                           "ReplaceString")


class LaunchConfigAsBool(Substitution):
    """``nav2_common.launch.LaunchConfigAsBool(name)``."""

    def __init__(self, name: str) -> None:
        super().__init__()
        self.name = name

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.AsBool(s.LaunchConfig(cv.sub(self.name)))


class HasNodeParams(Substitution):
    """``nav2_common.launch.HasNodeParams(source_file, node_name)``: depends on file content."""

    def __init__(self, source_file: Any, node_name: str) -> None:
        super().__init__()
        self.source_file, self.node_name = source_file, node_name

    def to_sub(self, cv: Converter) -> s.Sub:
        # 'True' when the file's top-level keys include the node name (read when known)
        return s.Rewritten(s.Opaque(f"HasNodeParams {self.node_name}"),
                           (cv.sub(self.source_file), s.Text(str(self.node_name))),
                           "HasNodeParams")


class ParseMultiRobotPose(Substitution):
    """``nav2_common.launch.ParseMultiRobotPose(robots_substitution)``."""

    def __init__(self, robots_substitution: Any) -> None:
        super().__init__()
        self.robots_substitution = robots_substitution

    def value(self) -> dict[str, dict[str, float]]:
        """Return the parsed robots; unknown statically, so none."""
        return {}

    def to_sub(self, cv: Converter) -> s.Sub:
        return s.Opaque("ParseMultiRobotPose")


class XacroDocument:
    """What ``xacro.process_file`` returns: an opaque robot description."""

    def __init__(self, source: str) -> None:
        self.source = source

    def toxml(self, *args: Any, **kwargs: Any) -> str:
        """Return the description (unknown statically)."""
        return placeholder("opaque", f"robot description from {Path(self.source).name}")

    toprettyxml = toxml


def process_file(input_file_name: Any, **kwargs: Any) -> XacroDocument:
    """``xacro.process_file``: checks the file exists, never runs xacro."""
    name = str(input_file_name)
    runtime = active()
    path = Path(name)
    if not has_placeholder(name) and path.is_absolute() and not path.exists() and (
        resolved(path).is_relative_to(runtime.workspace)
    ):
        raise FileNotFoundError(f"[Errno 2] No such file or directory: '{name}'")
    return XacroDocument(name)


def process_doc(doc: Any, **kwargs: Any) -> None:
    """``xacro.process_doc``: nothing to do statically."""


def open_output(output_filename: Any) -> Any:
    """``xacro.open_output``: writing is not allowed while evaluating; return a sink."""
    import io

    return io.StringIO()


def parse(inp: Any, filename: Any = None, **kwargs: Any) -> XacroDocument:
    """``xacro.parse``."""
    return XacroDocument(str(filename or "robot.xacro"))


# ----------------------------------------------------------------------------- ros2_control


def generate_controllers_spawner_launch_description(
    controller_names: list[str], *args: Any, **kwargs: Any,
) -> Any:
    """``controller_manager.launch_utils``: one spawner for the controllers."""
    controller_params_files, extra_spawner_args = _spawner_options(
        "controller_params_files", args, kwargs)
    from launchverify.models.launch_api.launch_actions import (
        DeclareLaunchArgument,
        LaunchDescription,
    )
    from launchverify.models.launch_api.launch_ros import Node
    from launchverify.models.launch_api.launch_substitutions import (
        LaunchConfiguration,
        PythonExpression,
    )

    arguments: list[Any] = [*controller_names, "--controller-manager",
                            LaunchConfiguration("controller_manager_name")]
    files = controller_params_files
    for file in (files if isinstance(files, (list, tuple)) else [files] if files else []):
        if file:
            arguments += ["--param-file", file]
    # "--unload-on-kill" when the unload_on_kill argument is "true", else an empty word
    unload = PythonExpression(['"--unload-on-kill" if "true" == "',
                               LaunchConfiguration("unload_on_kill"), '" else ""'])
    arguments += [unload, *(extra_spawner_args or [])]
    return LaunchDescription([
        DeclareLaunchArgument("controller_manager_name", default_value="controller_manager"),
        DeclareLaunchArgument("unload_on_kill", default_value="false"),
        Node(package="controller_manager", executable="spawner", arguments=arguments,
             shell=True, output="screen"),
    ])


def generate_controllers_spawner_launch_description_from_dict(
    controller_info_dict: dict[str, Any], extra_spawner_args: list[Any] | None = None,
) -> Any:
    """``controller_manager.launch_utils``: spawners from ``{name: params file}``."""
    if _unknown(controller_info_dict):  # a vendor's table: unknown controllers, unknown files
        return generate_controllers_spawner_launch_description(
            [controller_info_dict],  # type: ignore[list-item]  # an unknown name
            extra_spawner_args=extra_spawner_args)
    files = [f for f in controller_info_dict.values() if f]
    return generate_controllers_spawner_launch_description(
        list(controller_info_dict), controller_params_files=files or None,
        extra_spawner_args=extra_spawner_args)


def generate_load_controller_launch_description(
    controller_name: str, *args: Any, **kwargs: Any,
) -> Any:
    """``controller_manager.launch_utils``: a spawner for one controller."""
    controller_params_file, extra_spawner_args = _spawner_options(
        "controller_params_file", args, kwargs)
    return generate_controllers_spawner_launch_description(
        [controller_name], controller_params_files=controller_params_file,
        extra_spawner_args=extra_spawner_args)


def _spawner_options(files: str, args: tuple[Any, ...],
                     kwargs: dict[str, Any]) -> tuple[Any, list[Any] | None]:
    """Bind the arguments after the controllers' names as the checked distribution does.

    humble and iron take a ``controller_type`` second (unused); jazzy dropped it. With no
    distribution known, a call naming ``controller_type`` is taken as humble's.
    """
    distro = distros.current()
    typed = distro in ("humble", "iron") or (distro is None and "controller_type" in kwargs)
    names = (*(("controller_type",) if typed else ()), files, "extra_spawner_args")
    signature = inspect.Signature([
        inspect.Parameter(name, inspect.Parameter.POSITIONAL_OR_KEYWORD, default=None)
        for name in names])
    bound = signature.bind(*args, **kwargs).arguments  # a TypeError as Python's
    return bound.get(files), bound.get("extra_spawner_args")
