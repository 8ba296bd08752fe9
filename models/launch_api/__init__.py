"""Models of the launch API, served to Python launch files under the real module names.

``MODULES`` maps each module name a launch file may import (``launch.actions``,
``launch_ros.actions.node``...) to the names it exports. A module not listed whose parent
is listed exports what its parent exports, which covers paths like
``launch.actions.include_launch_description``.

The models follow the attribute tables of the real classes in ``real_api.json`` (checked by
``tests/test_model_api.py``); an attribute a model still lacks, read by the launch file's
code, is an opaque value reported once as LV003 (``base.Modelled``), never an
``AttributeError``.
"""

from __future__ import annotations

import typing
from typing import Any

from launchverify.models.launch_api import (
    ament,
    base,
    context,
    helpers,
    launch_events,
    launch_ros,
    moveit,
    ros_gz,
    webots,
)
from launchverify.models.launch_api import launch_actions as la
from launchverify.models.launch_api import launch_substitutions as ls
from launchverify.models.launch_api.lifecycle_msgs import State, Transition

SomeSubstitutionsType = str | base.Substitution | typing.Iterable[Any]
SomeSubstitutionsType_types_tuple = (str, base.Substitution)


# Test machinery a launch file may import but never needs to build its description: names
# without a model are opaque without being reported.
QUIET_ROOTS = frozenset({"launch_testing", "launch_testing_ros"})


class _Unused:
    """A class launch files import but that never matters statically (``LaunchService``)."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        pass

    def __getattr__(self, name: str) -> Any:
        return lambda *args, **kwargs: 0


def _exports(module: Any, *names: str) -> dict[str, Any]:
    return {name: getattr(module, name) for name in names}


ACTIONS = _exports(
    la, "AppendEnvironmentVariable", "DeclareLaunchArgument", "EmitEvent", "ExecuteLocal",
    "ExecuteProcess", "GroupAction", "IncludeLaunchDescription", "Log", "LogInfo",
    "ForEach", "ForLoop", "OpaqueCoroutine", "OpaqueFunction", "PopEnvironment",
    "PopLaunchConfigurations",
    "PushEnvironment", "PushLaunchConfigurations", "RegisterEventHandler", "ResetEnvironment",
    "ResetLaunchConfigurations", "SetEnvironmentVariable", "SetLaunchConfiguration", "Shutdown",
    "TimerAction", "UnregisterEventHandler", "UnsetEnvironmentVariable",
    "UnsetLaunchConfiguration",
)
SUBSTITUTIONS = _exports(
    ls, "AllSubstitution", "AndSubstitution", "AnonName", "AnySubstitution", "Command",
    "EnvironmentVariable", "EqualsSubstitution", "FileContent", "FindExecutable", "ForEachVar",
    "ForLoopIndex", "IfElseSubstitution", "LaunchConfiguration", "LaunchLogDir",
    "LocalSubstitution", "NotEqualsSubstitution", "NotSubstitution", "OrSubstitution",
    "PathJoinSubstitution", "PathSubstitution", "PythonExpression", "StringJoinSubstitution",
    "TextSubstitution",
    "ThisLaunchFile", "ThisLaunchFileDir",
)
CONDITIONS = _exports(
    ls, "IfCondition", "UnlessCondition", "LaunchConfigurationEquals",
    "LaunchConfigurationNotEquals",
)
EVENT_HANDLERS = _exports(
    launch_events, "EventHandler", "OnExecutionComplete", "OnIncludeLaunchDescription",
    "OnProcessExit", "OnProcessIO", "OnProcessStart", "OnShutdown",
)
SOURCES = _exports(
    la, "AnyLaunchDescriptionSource", "FrontendLaunchDescriptionSource",
    "LaunchDescriptionSource", "PythonLaunchDescriptionSource",
)
UTILITIES = _exports(
    context, "normalize_to_list_of_substitutions", "perform_substitutions",
    "perform_typed_substitution",
)
ROS_ACTIONS = _exports(
    launch_ros, "ComposableNodeContainer", "LifecycleNode", "LifecycleTransition",
    "LoadComposableNodes", "Node", "PushROSNamespace", "PushRosNamespace", "ROSTimer",
    "RosTimer", "SetParameter", "SetParametersFromFile", "SetRemap", "SetROSLogDir",
    "SetUseSimTime",
)
ROS_DESCRIPTIONS = _exports(
    launch_ros, "ComposableLifecycleNode", "ComposableNode", "Parameter", "ParameterFile",
    "ParameterValue",
)
ROS_SUBSTITUTIONS = {
    **_exports(launch_ros, "ExecutableInPackage", "FindPackage", "FindPackagePrefix",
               "FindPackageShare"),
    "Parameter": launch_ros.ParameterSubstitution,
}
AMENT = _exports(
    ament, "PackageNotFoundError", "get_package_prefix", "get_package_share_directory",
    "get_package_xml_path", "get_packages_with_prefixes", "has_resource", "get_resource",
    "get_package_share_path",
)

MODULES: dict[str, dict[str, Any]] = {
    "launch": {
        "LaunchDescription": la.LaunchDescription, "LaunchContext": context.LaunchContext,
        "Action": base.Action, "Substitution": base.Substitution,
        "Condition": ls.FunctionCondition,
        "LaunchDescriptionEntity": base.LaunchDescriptionEntity,
        "LaunchDescriptionSource": la.LaunchDescriptionSource,
        "SomeSubstitutionsType": SomeSubstitutionsType,
        "SomeSubstitutionsType_types_tuple": SomeSubstitutionsType_types_tuple,
        "EventHandler": launch_events.EventHandler, "Event": launch_events.Event,
        "LaunchService": _Unused,
    },
    "launch.actions": ACTIONS,
    "launch.substitutions": SUBSTITUTIONS,
    "launch.conditions": CONDITIONS,
    "launch.event_handlers": EVENT_HANDLERS,
    "launch.events": {"Shutdown": launch_events.Shutdown,
                      "matches_action": launch_events.matches_action},
    "launch.events.process": {
        **_exports(launch_events, "ShutdownProcess", "SignalProcess"),
        "ProcessExited": launch_events.Event, "ProcessStarted": launch_events.Event,
        "ProcessIO": launch_events.Event, "ProcessStdout": launch_events.Event,
        "ProcessStderr": launch_events.Event,
    },
    "launch.launch_description_sources": SOURCES,
    "launch.launch_description": {"LaunchDescription": la.LaunchDescription},
    "launch.launch_context": {"LaunchContext": context.LaunchContext},
    "launch.action": {"Action": base.Action},
    "launch.substitution": {"Substitution": base.Substitution},
    "launch.condition": {"Condition": ls.FunctionCondition},
    "launch.utilities": UTILITIES,
    "launch.some_substitutions_type": {
        "SomeSubstitutionsType": SomeSubstitutionsType,
        "SomeSubstitutionsType_types_tuple": SomeSubstitutionsType_types_tuple,
    },
    "launch.frontend": {"expose_action": lambda name: (lambda cls: cls),
                        "expose_substitution": lambda name: (lambda cls: cls),
                        "Entity": object, "Parser": object},
    "launch.logging": {"get_logger": lambda name=None: _Logger()},
    "launch_ros": {},
    "launch_ros.actions": ROS_ACTIONS,
    "launch_ros.descriptions": ROS_DESCRIPTIONS,
    "launch_ros.parameter_descriptions": _exports(
        launch_ros, "Parameter", "ParameterFile", "ParameterValue"),
    "launch_ros.substitutions": ROS_SUBSTITUTIONS,
    "launch_ros.event_handlers": {"OnStateTransition": launch_events.OnStateTransition},
    "launch_ros.events": {"matches_node_name": launch_events.matches_node_name},
    "launch_ros.events.lifecycle": _exports(launch_events, "ChangeState", "StateTransition",
                                            "matches_node_name"),  # moved, still exported
    "launch_ros.events.matchers": {"matches_node_name": launch_events.matches_node_name},
    "launch_ros.utilities": {},
    "launch_xml": {},
    "launch_xml.launch_description_sources": {
        "XMLLaunchDescriptionSource": la.XMLLaunchDescriptionSource},
    "launch_yaml": {},
    "launch_yaml.launch_description_sources": {
        "YAMLLaunchDescriptionSource": la.YAMLLaunchDescriptionSource},
    "ament_index_python": AMENT,
    "ament_index_python.packages": AMENT,
    "nav2_common": {},
    "nav2_common.launch": _exports(
        helpers, "HasNodeParams", "LaunchConfigAsBool", "ParseMultiRobotPose", "ReplaceString",
        "RewrittenYaml"),
    "xacro": _exports(helpers, "open_output", "parse", "process_doc", "process_file"),
    "controller_manager": {},
    "controller_manager.launch_utils": _exports(
        helpers, "generate_controllers_spawner_launch_description",
        "generate_controllers_spawner_launch_description_from_dict",
        "generate_load_controller_launch_description"),
    "moveit_configs_utils": _exports(moveit, "MoveItConfigs", "MoveItConfigsBuilder"),
    "moveit_configs_utils.launches": _exports(
        moveit, "generate_demo_launch", "generate_move_group_launch",
        "generate_moveit_rviz_launch", "generate_rsp_launch", "generate_setup_assistant_launch",
        "generate_spawn_controllers_launch", "generate_static_virtual_joint_tfs_launch",
        "generate_warehouse_db_launch"),
    "moveit_configs_utils.substitutions": {"Xacro": moveit.Xacro},
    "moveit_configs_utils.launch_utils": _exports(
        moveit, "DeclareBooleanLaunchArg", "add_debuggable_node"),
    "launch_param_builder": _exports(
        moveit, "ParameterBuilder", "get_path", "load_xacro", "load_yaml"),
    "launch_testing": {"LaunchTestService": _Unused},
    "launch_testing.actions": {"ReadyToTest": la.NoGraphEffect},
    "launch_testing.markers": {"keep_alive": lambda function: function},
    "launch_testing_ros": {},
    "lifecycle_msgs": {},
    "lifecycle_msgs.msg": {"State": State, "Transition": Transition},
    "ros_gz_sim": {},
    "ros_gz_sim.actions": _exports(ros_gz, "GzServer", "GzSpawnModel"),
    "ros_gz_bridge": {},
    "ros_gz_bridge.actions": _exports(ros_gz, "RosGzBridge"),
    "webots_ros2_driver": {},
    "webots_ros2_driver.webots_launcher": _exports(
        webots, "WebotsLauncher", "Ros2SupervisorLauncher"),
    "webots_ros2_driver.webots_controller": _exports(webots, "WebotsController"),
    "webots_ros2_driver.wait_for_controller_connection": _exports(
        webots, "WaitForControllerConnection"),
    "webots_ros2_driver.urdf_spawner": _exports(
        webots, "URDFSpawner", "get_webots_driver_node"),
}


class _Logger:
    """A logger that drops everything (``launch.logging.get_logger``)."""

    def __getattr__(self, name: str) -> Any:
        return lambda *args, **kwargs: None


def exports_for(name: str) -> dict[str, Any] | None:
    """Return what module ``name`` exports, or ``None`` when it is not modelled."""
    probe = name
    while probe:
        if probe in MODULES:
            return MODULES[probe]
        probe = probe.rpartition(".")[0]
    return None


def is_modelled(name: str) -> bool:
    """Return whether imports of ``name`` are served by the models."""
    return exports_for(name) is not None
