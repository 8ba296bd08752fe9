"""Models of webots_ros2_driver's launch helpers: what a Webots simulation's launch starts.

Learned from webots_ros2_driver's sources (2023.1 and later, humble to rolling). Its Python
helpers probe the machine when they are built (WSL, a folder shared with Docker, where
Webots is installed, and an offer to install it that waits for an answer); those answers
are the robot's, so the models start what they start on Linux with Webots installed:

- ``WebotsLauncher(world, gui, mode, stream, ros2_supervisor, port)``: the process
  ``webots`` running the simulator on (a copy of) the world, in batch mode. With
  ``ros2_supervisor`` its ``_supervisor`` is the Ros2Supervisor node, which the launch
  file adds to its description itself (and restarts on the simulation's reset with an
  ``OnProcessExit`` handler on it).
- ``Ros2SupervisorLauncher(port, respawn=True)``: the node ``ros2_supervisor.py`` of
  webots_ros2_driver in the namespace ``Ros2Supervisor`` (the name is its code's),
  ``/Ros2Supervisor/clock`` remapped to ``/clock``, respawned.
- ``WebotsController(robot_name, namespace, parameters, remappings, respawn, port)``: the
  process ``webots_controller[_<robot_name>]`` running the robot's driver, a ROS node whose
  remappings, namespace and parameters it passes on its command line (``-r``, ``-p``,
  ``--params-file``).
- ``WaitForControllerConnection(target_driver, nodes_to_start)``: an ``OnProcessIO``
  handler on the driver's output that starts ``nodes_to_start`` once it connects.
- ``URDFSpawner(name, urdf_path, robot_description, ...)``: the process calling the
  supervisor's ``spawn_urdf_robot`` service; ``get_webots_driver_node(event, driver)``
  gives the driver once the spawn succeeded.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from launchverify.models.launch_api import launch_actions as la
from launchverify.models.launch_api import launch_events
from launchverify.models.launch_api import launch_substitutions as ls
from launchverify.models.launch_api.base import Substitution
from launchverify.models.launch_api.launch_ros import FindPackageShare, Node

PACKAGE = "webots_ros2_driver"


def _webots_home() -> Any:
    return ls.EnvironmentVariable("WEBOTS_HOME")


class Ros2SupervisorLauncher(Node):
    """``Ros2SupervisorLauncher(output='screen', respawn=True, port='1234', **Node)``."""

    def __init__(self, output: Any = "screen", respawn: Any = True, port: Any = "1234",
                 **kwargs: Any) -> None:
        super().__init__(package=PACKAGE, executable="ros2_supervisor.py",
                         namespace="Ros2Supervisor",
                         remappings=[("/Ros2Supervisor/clock", "/clock")], output=output,
                         additional_env={"WEBOTS_CONTROLLER_URL": ["ipc://", port,
                                                                   "/Ros2Supervisor"]},
                         respawn=respawn, **kwargs)


class WebotsLauncher(la.ExecuteProcess):
    """``WebotsLauncher(world=None, gui=True, mode='realtime', ros2_supervisor=False, ...)``."""

    def __init__(self, output: Any = "screen", world: Any = None, gui: Any = True,
                 mode: Any = "realtime", stream: Any = False, ros2_supervisor: Any = False,
                 port: Any = "1234", **kwargs: Any) -> None:
        self._supervisor = Ros2SupervisorLauncher(port=port) if ros2_supervisor else None
        command: list[Any] = [ls.PathJoinSubstitution([_webots_home(), "webots"])]
        if stream is True:
            command.append("--stream")
        elif stream is not False:
            command.append(["--stream=", stream])
        command.append(["--port=", port])
        if gui is False:
            command += ["--no-rendering", "--stdout", "--stderr", "--minimize"]
        if world is not None:
            command.append(world)
        command += ["--batch", ["--mode=", mode]]
        super().__init__(cmd=command, name="webots", output=output, **kwargs)


class WebotsController(la.ExecuteProcess):
    """``WebotsController(robot_name='', namespace='', parameters=[], remappings=[], ...)``."""

    def __init__(self, output: Any = "screen", respawn: Any = False,
                 remappings: Iterable[Any] = (), namespace: Any = "",
                 parameters: Iterable[Any] = (), robot_name: Any = "", port: Any = "1234",
                 **kwargs: Any) -> None:
        arguments: list[Any] = []
        for key, value in remappings:
            arguments += ["-r", [key, ":=", value]]
        if namespace:
            arguments += ["-r", ["__ns:=/", namespace]]
        files: list[Any] = []
        for item in parameters:
            if isinstance(item, dict):
                for key, value in item.items():
                    arguments += ["-p", [f"{key}:=", value if isinstance(
                        value, Substitution) else str(value)]]
            elif isinstance(item, str):
                files.append(item)
        command: list[Any] = [
            ls.PathJoinSubstitution([FindPackageShare(PACKAGE), "scripts",
                                     "webots-controller"]),
            *([["--robot-name=", robot_name]] if robot_name else []),
            "--protocol=ipc", ["--port=", port], "ros2",
            *(["--ros-args"] if arguments else []), *arguments,
            *(["--params-file"] if files else []), *files,
        ]
        name = "webots_controller" + (f"_{robot_name}" if robot_name else "")
        super().__init__(cmd=command, name=name, output=output, respawn=respawn, **kwargs)


class WaitForControllerConnection(la.RegisterEventHandler):
    """``WaitForControllerConnection(target_driver, nodes_to_start)``."""

    def __init__(self, target_driver: Any, nodes_to_start: Any, **kwargs: Any) -> None:
        super().__init__(event_handler=launch_events.OnProcessIO(
            target_action=target_driver, on_stderr=lambda event: nodes_to_start), **kwargs)


class URDFSpawner(la.ExecuteProcess):
    """``URDFSpawner(output='log', name=None, urdf_path=None, robot_description=None, ...)``."""

    def __init__(self, output: Any = "log", name: Any = None, urdf_path: Any = None,
                 robot_description: Any = None, relative_path_prefix: Any = None,
                 translation: Any = "0 0 0", rotation: Any = "0 0 1 0", normal: Any = False,
                 box_collision: Any = False, init_pos: Any = None, **kwargs: Any) -> None:
        fields = [(field, value) for field, value in (
            ("name", name), ("urdf_path", urdf_path),
            ("robot_description", None if urdf_path else robot_description),
            ("relative_path_prefix", None if urdf_path else relative_path_prefix),
            ("translation", translation), ("rotation", rotation), ("normal", normal),
            ("box_collision", box_collision), ("init_pos", init_pos)) if value]
        message: list[Any] = ["{robot: {"]
        for field, value in fields:
            message += [f'{field}: "', value if isinstance(value, Substitution)
                        else str(value), '",']
        message.append("} }")
        super().__init__(cmd=["ros2", "service", "call", "/Ros2Supervisor/spawn_urdf_robot",
                              "webots_ros2_msgs/srv/SpawnUrdfRobot", message],
                         output=output, **kwargs)


def get_webots_driver_node(event: Any, driver_node: Any) -> Any:
    """Return the driver, which its handler starts once the URDF robot is spawned."""
    return driver_node
