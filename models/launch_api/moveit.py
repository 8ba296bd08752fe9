"""Models of MoveIt's launch helpers: ``moveit_configs_utils`` and ``launch_param_builder``.

``MoveItConfigsBuilder(...).robot_description(...)...to_moveit_configs()`` collects the
parameters a MoveIt configuration package provides. We read its YAML files when they are
in the workspace and leave the rest (robot descriptions, files only the robot has) as
opaque values, so the nodes ``generate_*_launch`` build carry what they really carry. The
``generate_*_launch`` functions build the nodes MoveIt's own ones build.
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from pathlib import Path
from typing import Any, TypeVar

import yaml

from launchverify.ir import subst as s
from launchverify.models.launch_api.ament import get_package_share_directory
from launchverify.models.launch_api.base import Converter, Substitution, _unknown
from launchverify.models.launch_api.launch_actions import (
    DeclareLaunchArgument,
    IncludeLaunchDescription,
    LaunchDescription,
    PythonLaunchDescriptionSource,
)
from launchverify.models.launch_api.launch_ros import Node
from launchverify.models.launch_api.launch_substitutions import (
    IfCondition,
    LaunchConfiguration,
    UnlessCondition,
)
from launchverify.models.launch_api.placeholders import (
    UnknownMapping,
    has_placeholder,
    placeholder,
)
from launchverify.models.launch_api.runtime import active
from launchverify.workspace.paths import resolved


def _opaque(what: str) -> str:
    return placeholder("opaque", what)


def locate(file_path: Any) -> Path:
    """Find a package file as the package index does (install layout -> sources)."""
    path = Path(str(file_path))
    if has_placeholder(str(file_path)) or path.exists():
        return path
    return active().index.locate(path) or path


def load_yaml(file_path: Any) -> Any:
    """Return a YAML file's content when the workspace has it, else an opaque value."""
    path = locate(file_path)
    if has_placeholder(str(file_path)) or not path.is_file():
        return UnknownMapping()  # a file only the robot has
    try:
        return yaml.safe_load(path.read_text(encoding="utf-8"))
    except (OSError, yaml.YAMLError):
        return UnknownMapping()


def load_xacro(file_path: Any, mappings: Any = None) -> str:
    """Return a robot description: opaque (xacro is never run)."""
    path = locate(file_path)
    runtime = active()
    if not has_placeholder(str(file_path)) and path.is_absolute() and not path.exists() and (
        resolved(path).is_relative_to(runtime.workspace)
    ):
        raise FileNotFoundError(f"[Errno 2] No such file or directory: '{file_path}'")
    return _opaque(f"robot description from {path.name}")


def get_path(package_name: str, file_path: Any) -> Path:
    """``launch_param_builder.get_package_share_directory``-relative path."""
    return Path(get_package_share_directory(package_name)) / str(file_path)


class ParameterBuilder:
    """``launch_param_builder.ParameterBuilder(package_name)``."""

    def __init__(self, package_name: str) -> None:
        self._package_path = Path(get_package_share_directory(package_name))
        self._parameters: dict[str, Any] = {}

    def yaml(self, file_path: Any, parameter_namespace: str | None = None) -> ParameterBuilder:
        """Merge a YAML file's parameters."""
        content = load_yaml(self._package_path / str(file_path))
        if parameter_namespace:
            content = {parameter_namespace: content}
        if isinstance(content, dict):
            self._parameters.update(content)
        return self

    def xacro_parameter(self, parameter_name: str, file_path: Any,
                        mappings: Any = None) -> ParameterBuilder:
        """Set a parameter to a processed xacro file."""
        self._parameters[parameter_name] = load_xacro(self._package_path / str(file_path))
        return self

    def file_parameter(self, parameter_name: str, file_path: Any) -> ParameterBuilder:
        """Set a parameter to a file's content."""
        self._parameters[parameter_name] = _opaque(f"content of {Path(str(file_path)).name}")
        return self

    def parameter(self, parameter_name: str, parameter_value: Any) -> ParameterBuilder:
        """Set one parameter."""
        self._parameters[parameter_name] = parameter_value
        return self

    def path_parameter(self, parameter_name: str, file_path: Any) -> ParameterBuilder:
        """Set a parameter to a path inside the package."""
        self._parameters[parameter_name] = str(self._package_path / str(file_path))
        return self

    def to_dict(self) -> dict[str, Any]:
        """Return the parameters."""
        return dict(self._parameters)


class MoveItConfigs:
    """What ``MoveItConfigsBuilder.to_moveit_configs()`` returns."""

    def __init__(self, package_path: Path | None = None) -> None:
        self.package_path = package_path
        self.robot_description: dict[str, Any] = {}
        self.robot_description_semantic: dict[str, Any] = {}
        self.robot_description_kinematics: dict[str, Any] = {}
        self.planning_pipelines: dict[str, Any] = {}
        self.trajectory_execution: dict[str, Any] = {}
        self.planning_scene_monitor: dict[str, Any] = {}
        self.sensors_3d: dict[str, Any] = {}
        self.move_group_capabilities: dict[str, Any] = {"capabilities": "",
                                                         "disable_capabilities": ""}
        self.joint_limits: dict[str, Any] = {}
        self.moveit_cpp: dict[str, Any] = {}
        self.pilz_cartesian_limits: dict[str, Any] = {}

    def to_dict(self) -> dict[str, Any]:
        """Return every parameter of the configuration in one dict."""
        parameters: dict[str, Any] = {}
        for part in (self.robot_description, self.robot_description_semantic,
                     self.robot_description_kinematics, self.planning_pipelines,
                     self.trajectory_execution, self.planning_scene_monitor, self.sensors_3d,
                     self.joint_limits, self.moveit_cpp, self.move_group_capabilities):
            parameters.update(part)
        for key, value in self.pilz_cartesian_limits.items():  # merged into joint limits
            if isinstance(parameters.get(key), dict) and isinstance(value, dict):
                parameters[key] = {**parameters[key], **value}
            else:
                parameters[key] = value
        return parameters


def _description(path: Path, mappings: Any) -> Any:
    """Return a robot description value: an Xacro stand-in when mappings are substituted."""
    if mappings and any(not isinstance(v, str) for v in dict(mappings).values()):
        from launchverify.models.launch_api.launch_ros import ParameterValue

        return ParameterValue(Xacro(str(path), mappings=mappings), value_type=str)
    return load_xacro(path, mappings)


class MoveItConfigsBuilder(ParameterBuilder):
    """``MoveItConfigsBuilder(robot_name, robot_description='robot_description', ...)``."""

    def __init__(self, robot_name: str, robot_description: str = "robot_description",
                 package_name: str | None = None) -> None:
        super().__init__(package_name or f"{robot_name}_moveit_config")
        self._robot_name = robot_name
        self._description_name = robot_description
        self._configs = MoveItConfigs(self._package_path)
        config = self._package_path / "config"
        self._urdf: Path | None = None
        self._srdf: Path | None = None
        xacro = config / f"{robot_name}.urdf.xacro"
        if xacro.exists():
            self._urdf = xacro
        assistant = self._package_path / ".setup_assistant"
        if assistant.is_file():
            content = load_yaml(assistant)
            settings = content.get("moveit_setup_assistant_config", {}) if isinstance(
                content, dict) else {}
            urdf = settings.get("urdf", settings.get("URDF")) or {}
            if self._urdf is None and urdf.get("package") and urdf.get("relative_path"):
                self._urdf = Path(get_package_share_directory(str(urdf["package"]))) / str(
                    urdf["relative_path"])
            srdf = settings.get("srdf", settings.get("SRDF")) or {}
            if srdf.get("relative_path"):
                self._srdf = self._package_path / str(srdf["relative_path"])
        self._urdf = self._urdf or config / f"{robot_name}.urdf"
        self._srdf = self._srdf or config / f"{robot_name}.srdf"

    def _file(self, file_path: Any, default: str) -> Path:
        if file_path is None:
            return self._package_path / default
        path = Path(str(file_path))
        return path if path.is_absolute() else self._package_path / path

    def robot_description(self, file_path: Any = None, mappings: Any = None
                          ) -> MoveItConfigsBuilder:
        """Load the robot description; a missing file only warns, as in MoveIt."""
        path = self._urdf if file_path is None else self._file(file_path, "")
        assert path is not None
        try:
            value = _description(path, mappings)
        except FileNotFoundError:
            value = _opaque(f"robot description from {path.name}")
        self._configs.robot_description = {self._description_name: value}
        return self

    def robot_description_semantic(self, file_path: Any = None, mappings: Any = None
                                   ) -> MoveItConfigsBuilder:
        """Load the SRDF."""
        path = self._srdf if file_path is None else self._file(file_path, "")
        assert path is not None
        self._configs.robot_description_semantic = {
            self._description_name + "_semantic": _description(path, mappings)}
        return self

    def _yaml_part(self, attribute: str, key: str | None, file_path: Any, default: str
                   ) -> MoveItConfigsBuilder:
        path = locate(self._file(file_path, default))
        if file_path is None and not path.exists():
            return self  # a default that this package does not have
        _require(path)
        content = load_yaml(path)
        value = {key: content} if key else (content if isinstance(content, dict) else {})
        setattr(self._configs, attribute, value)
        return self

    def robot_description_kinematics(self, file_path: Any = None) -> MoveItConfigsBuilder:
        """Load kinematics.yaml."""
        return self._yaml_part("robot_description_kinematics",
                               self._description_name + "_kinematics", file_path,
                               "config/kinematics.yaml")

    def joint_limits(self, file_path: Any = None) -> MoveItConfigsBuilder:
        """Load joint_limits.yaml."""
        return self._yaml_part("joint_limits", self._description_name + "_planning",
                               file_path, "config/joint_limits.yaml")

    def moveit_cpp(self, file_path: Any = None) -> MoveItConfigsBuilder:
        """Load the MoveItCpp configuration."""
        return self._yaml_part("moveit_cpp", None, file_path, "config/moveit_cpp.yaml")

    def trajectory_execution(self, file_path: Any = None, moveit_manage_controllers: bool = True
                             ) -> MoveItConfigsBuilder:
        """Load the controllers MoveIt uses (``config/*_controllers.yaml`` by default)."""
        if file_path is None:
            found = sorted((self._package_path / "config").glob("*_controllers.yaml"))
            moveit = [f for f in found if f.name in ("moveit_controllers.yaml",
                                                     "moveit2_controllers.yaml")]
            chosen = moveit[0] if moveit else (found[0] if len(found) == 1 else None)
            file_path = chosen
        self._configs.trajectory_execution = {"moveit_manage_controllers":
                                              moveit_manage_controllers}
        if file_path is not None:
            content = load_yaml(self._file(file_path, ""))
            if isinstance(content, dict):
                self._configs.trajectory_execution.update(content)
        return self

    def planning_scene_monitor(self, publish_planning_scene: bool = True,
                               publish_geometry_updates: bool = True,
                               publish_state_updates: bool = True,
                               publish_transforms_updates: bool = True,
                               publish_robot_description: bool = False,
                               publish_robot_description_semantic: bool = False
                               ) -> MoveItConfigsBuilder:
        """Set the planning scene monitor options."""
        self._configs.planning_scene_monitor = {
            "publish_planning_scene": publish_planning_scene,
            "publish_geometry_updates": publish_geometry_updates,
            "publish_state_updates": publish_state_updates,
            "publish_transforms_updates": publish_transforms_updates,
            "publish_robot_description": publish_robot_description,
            "publish_robot_description_semantic": publish_robot_description_semantic,
        }
        return self

    def sensors_3d(self, file_path: Any = None) -> MoveItConfigsBuilder:
        """Load the 3D sensor configuration."""
        return self._yaml_part("sensors_3d", None, file_path, "config/sensors_3d.yaml")

    def planning_pipelines(self, default_planning_pipeline: str | None = None,
                           pipelines: Any = None, load_all: bool = True
                           ) -> MoveItConfigsBuilder:
        """Collect the planning pipelines and each one's ``config/<name>_planning.yaml``."""
        if isinstance(pipelines, str):
            pipelines = [pipelines]
        config = self._package_path / "config"
        if pipelines is None:
            found = [f.name[: -len("_planning.yaml")]
                     for f in sorted(config.glob("*_planning.yaml"))]
            defaults = ["ompl", "chomp", "pilz_industrial_motion_planner", "stomp"]
            pipelines = found + [p for p in defaults if load_all and p not in found]
        names = list(pipelines)
        if default_planning_pipeline is None:
            default_planning_pipeline = "ompl" if "ompl" in names else names[0]
        if default_planning_pipeline not in names and not any(  # a vendor's name: may be one
                has_placeholder(str(name)) for name in [default_planning_pipeline, *names]):
            raise RuntimeError(f"default_planning_pipeline: `{default_planning_pipeline}` "
                               f"doesn't name any of the input pipelines `{names}`")
        parameters: dict[str, Any] = {"planning_pipelines": names,
                                      "default_planning_pipeline": default_planning_pipeline}
        for name in names:
            # missing here: MoveIt falls back to its own default_configs (unknown to us)
            content = load_yaml(config / f"{name}_planning.yaml")
            parameters[name] = content if isinstance(content, dict) else UnknownMapping()
        self._configs.planning_pipelines = parameters
        return self

    def pilz_cartesian_limits(self, file_path: Any = None) -> MoveItConfigsBuilder:
        """Load the Pilz cartesian limits."""
        return self._yaml_part("pilz_cartesian_limits", self._description_name + "_planning",
                               file_path, "config/pilz_cartesian_limits.yaml")

    def to_moveit_configs(self) -> MoveItConfigs:
        """Return the configuration (parts not loaded explicitly get their defaults)."""
        configs = self._configs
        if not configs.robot_description:
            self.robot_description()
        if not configs.robot_description_semantic:
            self.robot_description_semantic()
        if not configs.robot_description_kinematics:
            self.robot_description_kinematics()
        if not configs.planning_pipelines:
            self.planning_pipelines()
        if not configs.trajectory_execution:
            self.trajectory_execution()
        if not configs.planning_scene_monitor:
            self.planning_scene_monitor()
        if not configs.sensors_3d:
            self.sensors_3d()
        if not configs.joint_limits:
            self.joint_limits()
        if ("pilz_industrial_motion_planner" in configs.planning_pipelines.get(
                "planning_pipelines", []) and not configs.pilz_cartesian_limits):
            self.pilz_cartesian_limits()
        return configs

    def to_dict(self, include_moveit_configs: bool = True) -> dict[str, Any]:
        """Return the parameters."""
        parameters = super().to_dict()
        if include_moveit_configs:
            parameters.update(self.to_moveit_configs().to_dict())
        return parameters


def _require(path: Path) -> None:
    """Raise like MoveIt's loaders for a file missing from the workspace."""
    runtime = active()
    path = locate(path)
    text = str(path)
    if not has_placeholder(text) and path.is_absolute() and not path.exists() and (
            resolved(path).is_relative_to(runtime.workspace)):
        raise FileNotFoundError(f"File {text} doesn't exist")


# ----------------------------------------------------------------------------- launches


def DeclareBooleanLaunchArg(name: str, *, default_value: bool = False,
                            **kwargs: Any) -> DeclareLaunchArgument:
    """``moveit_configs_utils.launch_utils.DeclareBooleanLaunchArg``."""
    return DeclareLaunchArgument(name, default_value=str(default_value),
                                 choices=["true", "false", "True", "False"], **kwargs)


def add_debuggable_node(ld: LaunchDescription, package: str, executable: str,
                        condition_name: str = "debug", commands_file: Any = None,
                        extra_debug_args: Any = None, **kwargs: Any) -> None:
    """``moveit_configs_utils.launch_utils.add_debuggable_node``: the node, run or debugged."""
    if _unknown(ld):
        return  # a description of code launchverify cannot see: what it holds stays unknown
    debug = LaunchConfiguration(condition_name)
    ld.add_action(Node(package=package, executable=executable,
                       condition=UnlessCondition(debug), **kwargs))
    ld.add_action(Node(package=package, executable=executable, prefix=["gdb -x ", commands_file
                                                                       or "", " --ex run --args"],
                       condition=IfCondition(debug), **kwargs))



_Launch = TypeVar("_Launch", bound=Callable[..., Any])


def _configured(generate: _Launch) -> _Launch:
    """Make ``generate_*_launch(unknown)`` an unknown description, not an error.

    A configuration from code launchverify cannot see answers none of our questions: what
    the generated description holds is unknown (the frontend makes it an unknown action).
    """
    @functools.wraps(generate)
    def launch(moveit_config: Any, *args: Any, **kwargs: Any) -> Any:
        if _unknown(moveit_config):
            from launchverify.models.launch_api.unknown import Opaque

            return LaunchDescription([Opaque(f"{generate.__name__}(an unknown configuration)")])
        return generate(moveit_config, *args, **kwargs)

    return launch  # type: ignore[return-value]

@_configured
def generate_rsp_launch(moveit_config: MoveItConfigs) -> LaunchDescription:
    """robot_state_publisher with the robot description."""
    ld = LaunchDescription()
    ld.add_action(DeclareLaunchArgument("publish_frequency", default_value="15.0"))
    ld.add_action(Node(package="robot_state_publisher", executable="robot_state_publisher",
                       respawn=True, output="screen",
                       parameters=[moveit_config.robot_description,
                                   {"publish_frequency": LaunchConfiguration(
                                       "publish_frequency")}]))
    return ld


@_configured
def generate_moveit_rviz_launch(moveit_config: MoveItConfigs) -> LaunchDescription:
    """RViz with the MoveIt configuration."""
    ld = LaunchDescription()
    ld.add_action(DeclareBooleanLaunchArg("debug", default_value=False))
    ld.add_action(DeclareLaunchArgument(
        "rviz_config", default_value=str(_package(moveit_config) / "config/moveit.rviz")))
    add_debuggable_node(ld, package="rviz2", executable="rviz2", output="log", respawn=False,
                        arguments=["-d", LaunchConfiguration("rviz_config")],
                        parameters=[moveit_config.planning_pipelines,
                                    moveit_config.robot_description_kinematics])
    return ld


@_configured
def generate_setup_assistant_launch(moveit_config: MoveItConfigs) -> LaunchDescription:
    """The setup assistant."""
    ld = LaunchDescription()
    ld.add_action(DeclareBooleanLaunchArg("debug", default_value=False))
    add_debuggable_node(ld, package="moveit_setup_assistant",
                        executable="moveit_setup_assistant",
                        arguments=[["--config_pkg=", str(_package(moveit_config))]])
    return ld


@_configured
def generate_static_virtual_joint_tfs_launch(moveit_config: MoveItConfigs
                                             ) -> LaunchDescription:
    """Static transforms for the SRDF's virtual joints (unknown statically: none)."""
    return LaunchDescription()


@_configured
def generate_spawn_controllers_launch(moveit_config: MoveItConfigs) -> LaunchDescription:
    """A spawner per controller named in the configuration."""
    ld = LaunchDescription()
    names = moveit_config.trajectory_execution.get("moveit_simple_controller_manager", {})
    controllers = names.get("controller_names", []) if isinstance(names, dict) else []
    for controller in [*controllers, "joint_state_broadcaster"]:
        ld.add_action(Node(package="controller_manager", executable="spawner",
                           arguments=[controller], output="screen"))
    return ld


@_configured
def generate_warehouse_db_launch(moveit_config: MoveItConfigs) -> LaunchDescription:
    """The MongoDB warehouse."""
    ld = LaunchDescription()
    ld.add_action(DeclareLaunchArgument("moveit_warehouse_database_path",
                                        default_value=str(_package(moveit_config)
                                                          / "default_warehouse_mongo_db")))
    ld.add_action(DeclareBooleanLaunchArg("reset", default_value=False))
    ld.add_action(DeclareLaunchArgument("moveit_warehouse_port", default_value="33829"))
    ld.add_action(DeclareLaunchArgument("moveit_warehouse_host", default_value="localhost"))
    ld.add_action(Node(package="warehouse_ros_mongo", executable="mongo_wrapper_ros.py",
                       parameters=[{
                           "overwrite": False,
                           "database_path": LaunchConfiguration(
                               "moveit_warehouse_database_path"),
                           "warehouse_port": LaunchConfiguration("moveit_warehouse_port"),
                           "warehouse_host": LaunchConfiguration("moveit_warehouse_host"),
                       }], output="screen"))
    ld.add_action(Node(package="moveit_ros_warehouse", executable="moveit_init_demo_warehouse",
                       output="screen", condition=IfCondition(LaunchConfiguration("reset"))))
    return ld


@_configured
def generate_move_group_launch(moveit_config: MoveItConfigs) -> LaunchDescription:
    """move_group with the whole configuration."""
    ld = LaunchDescription()
    for name, default in (("debug", False), ("allow_trajectory_execution", True),
                          ("publish_monitored_planning_scene", True),
                          ("monitor_dynamics", False)):
        ld.add_action(DeclareBooleanLaunchArg(name, default_value=default))
    ld.add_action(DeclareLaunchArgument("capabilities", default_value=""))
    ld.add_action(DeclareLaunchArgument("disable_capabilities", default_value=""))
    configuration = {
        "publish_robot_description_semantic": True,
        "allow_trajectory_execution": LaunchConfiguration("allow_trajectory_execution"),
        "capabilities": LaunchConfiguration("capabilities"),
        "disable_capabilities": LaunchConfiguration("disable_capabilities"),
        "publish_planning_scene": LaunchConfiguration("publish_monitored_planning_scene"),
        "publish_geometry_updates": LaunchConfiguration("publish_monitored_planning_scene"),
        "publish_state_updates": LaunchConfiguration("publish_monitored_planning_scene"),
        "publish_transforms_updates": LaunchConfiguration("publish_monitored_planning_scene"),
        "monitor_dynamics": LaunchConfiguration("monitor_dynamics"),
    }
    add_debuggable_node(ld, package="moveit_ros_move_group", executable="move_group",
                        output="screen", parameters=[moveit_config.to_dict(), configuration],
                        additional_env={"DISPLAY": _opaque("DISPLAY")})
    return ld


@_configured
def generate_demo_launch(moveit_config: MoveItConfigs, launch_package_path: Any = None
                         ) -> LaunchDescription:
    """The demo: the configuration package's own launch files, plus ros2_control."""
    package = Path(str(launch_package_path)) if launch_package_path else _package(moveit_config)
    ld = LaunchDescription()
    ld.add_action(DeclareBooleanLaunchArg("db", default_value=False))
    ld.add_action(DeclareBooleanLaunchArg("debug", default_value=False))
    ld.add_action(DeclareBooleanLaunchArg("use_rviz", default_value=True))
    virtual_joints = package / "launch/static_virtual_joint_tfs.launch.py"
    if virtual_joints.exists():
        ld.add_action(_include(virtual_joints))
    ld.add_action(_include(package / "launch/rsp.launch.py"))
    ld.add_action(_include(package / "launch/move_group.launch.py"))
    ld.add_action(_include(package / "launch/moveit_rviz.launch.py",
                           IfCondition(LaunchConfiguration("use_rviz"))))
    ld.add_action(_include(package / "launch/warehouse_db.launch.py",
                           IfCondition(LaunchConfiguration("db"))))
    ld.add_action(Node(package="controller_manager", executable="ros2_control_node",
                       parameters=[str(package / "config/ros2_controllers.yaml")],
                       remappings=[("/controller_manager/robot_description",
                                    "/robot_description")]))
    ld.add_action(_include(package / "launch/spawn_controllers.launch.py"))
    return ld


def _include(path: Path, condition: Any = None) -> IncludeLaunchDescription:
    return IncludeLaunchDescription(PythonLaunchDescriptionSource(str(path)), condition=condition)


def _package(moveit_config: MoveItConfigs) -> Path:
    return moveit_config.package_path or Path(_opaque("moveit config package"))


class Xacro(Substitution):
    """``moveit_configs_utils.substitutions.Xacro(file_path, *, mappings=None)``.

    A robot description xacro'd at launch time: opaque, but the file and the mappings'
    values are read (so the configurations they name count as used).
    """

    def __init__(self, file_path: Any, *, mappings: Any = None) -> None:
        super().__init__()
        self.file_path = file_path
        self.mappings = dict(mappings or {})

    def to_sub(self, cv: Converter) -> s.Sub:
        inputs = (cv.sub(self.file_path),
                  *(cv.sub(v) for v in self.mappings.values() if v is not None))
        return s.Rewritten(s.Opaque("robot description (xacro)"), inputs, "Xacro")
