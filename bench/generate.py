"""Write a deterministic, realistic synthetic ROS 2 workspace for benchmarking launchverify.

The tree looks like a colcon workspace's ``src/``: about 25 packages, each with a
``package.xml``, a ``CMakeLists.txt``, a ``launch/`` folder and a ``config/`` folder of
parameter files. Launch files (~35% Python, ~45% XML, ~20% YAML) declare arguments (some with
choices), start nodes with parameters, parameter files and remaps, use groups with pushed
namespaces, conditions, ``$(eval)``, ``<let>``, ``<set_remap>`` and ``<set_parameter>``,
and include each other along a DAG at most 6 includes deep; a few "bringup" files include
many others.

The output is meant to be clean: every argument declared is read, every include passes
only arguments its target declares (and every argument it requires), every referenced
file exists, and node names are kept unique in every launch (the generator tracks the
fully qualified names each file starts and pushes a namespace when two would collide).

Standard library only; the same ``--seed`` and ``--files`` always give the same bytes.

    python bench/generate.py [--files 500] [--seed 1] [--out bench/generated]
"""

from __future__ import annotations

import argparse
import json
import random
import re
import shutil
import sys
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from render_python import render_python

HERE = Path(__file__).resolve().parent
DEFAULT_OUT = HERE / "generated"
STAMP = ".bench-stamp.json"
GENERATOR_VERSION = 4
MAX_LEVEL = 5  # non-bringup files sit on levels 0..5; bringup files on level 6
LEVEL_WEIGHTS = (0.42, 0.22, 0.14, 0.10, 0.07, 0.05)
# Launch file formats: ~35% Python, ~45% XML, ~20% YAML.
PYTHON_SHARE = 0.35
YAML_SHARE = 0.2
PREFIX = "acme"

# (topic, executables) of the fake packages; the bringup package comes first.
PACKAGES: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("bringup", ("system_monitor", "mode_manager")),
    ("base", ("base_driver", "odometry_publisher", "motor_controller", "wheel_monitor")),
    ("lidar", ("lidar_driver", "scan_filter", "scan_merger", "lidar_monitor")),
    ("camera", ("camera_driver", "image_rectifier", "image_throttle", "camera_info_server")),
    ("imu", ("imu_driver", "imu_filter", "imu_calibrator")),
    ("gps", ("gps_driver", "navsat_converter", "ntrip_client")),
    ("localization", ("ekf_node", "pose_initializer", "map_matcher", "localization_monitor")),
    ("mapping", ("map_builder", "map_server", "map_saver", "costmap_generator")),
    ("planning", ("global_planner", "local_planner", "route_server", "path_smoother")),
    ("control", ("trajectory_controller", "velocity_smoother", "collision_monitor")),
    ("teleop", ("joystick_teleop", "keyboard_teleop", "cmd_vel_mux")),
    ("arm", ("arm_driver", "arm_controller", "joint_monitor", "ik_server")),
    ("gripper", ("gripper_driver", "grasp_server")),
    ("perception", ("object_detector", "obstacle_tracker", "segmentation_node", "fusion_node")),
    ("description", ("description_server", "frame_publisher")),
    ("diagnostics", ("diagnostic_collector", "health_monitor", "heartbeat_node")),
    ("safety", ("safety_supervisor", "emergency_stop", "speed_limiter")),
    ("docking", ("dock_detector", "docking_server", "charger_interface")),
    ("battery", ("battery_monitor", "power_manager")),
    ("simulation", ("sim_clock", "sim_bridge", "world_spawner", "sensor_simulator")),
    ("web", ("web_bridge", "video_server", "rosapi_node")),
    ("logging", ("bag_recorder", "log_uploader", "event_logger")),
    ("fleet", ("fleet_adapter", "task_allocator", "fleet_state_publisher")),
    ("calibration", ("extrinsic_calibrator", "intrinsic_calibrator", "calibration_checker")),
    ("audio", ("audio_capture", "speech_player", "sound_localizer")),
)

# File stem qualifiers, combined with a package's topic.
QUALIFIERS = (
    "", "driver", "sim", "real", "front", "rear", "left", "right", "debug", "minimal",
    "full", "pipeline", "filters", "monitor", "nodes", "hw", "multi", "single", "record",
    "replay", "headless", "test", "calibration", "diagnostics", "core", "extras", "legacy",
    "experimental", "compressed", "highres", "lowres", "indoor", "outdoor", "nightly",
)
BRINGUP_STEMS = (
    "robot", "sim", "navigation", "manipulation", "perception", "field_test", "warehouse",
    "demo", "factory", "outdoor", "lab", "minimal_robot", "full_stack", "dev", "ci",
    "showroom", "mapping_run", "docking_test", "teleop_only", "headless_robot",
)

# Released ROS 2 packages nodes may come from (never from the workspace).
RELEASED_NODES: tuple[tuple[str, str], ...] = (
    ("tf2_ros", "static_transform_publisher"),
    ("robot_state_publisher", "robot_state_publisher"),
    ("topic_tools", "relay"),
    ("diagnostic_aggregator", "aggregator_node"),
    ("joy", "joy_node"),
    ("teleop_twist_joy", "teleop_node"),
    ("twist_mux", "twist_mux"),
    ("pointcloud_to_laserscan", "pointcloud_to_laserscan_node"),
)

FEATURES = (
    "rviz", "diagnostics", "filters", "compression", "debug", "recording", "watchdog",
    "visualization", "teleop", "throttling", "fallback", "heartbeat", "profiling",
)
PARAM_LITERALS: tuple[tuple[str, tuple[str, ...]], ...] = (
    ("queue_size", ("1", "5", "10", "100")),
    ("timeout", ("0.5", "1.0", "2.5", "5.0")),
    ("max_range", ("10.0", "30.0", "100.0")),
    ("min_range", ("0.05", "0.1", "0.3")),
    ("enable_diagnostics", ("true", "false")),
    ("port", ("/dev/ttyUSB0", "/dev/ttyACM0", "/dev/ttyS1")),
    ("baud_rate", ("115200", "921600", "57600")),
    ("publish_tf", ("true", "false")),
    ("qos_reliability", ("reliable", "best_effort")),
    ("tolerance", ("0.01", "0.05", "0.25")),
    ("retries", ("3", "5")),
    ("mode_name", ("default", "eco", "performance")),
)
REMAPS = (
    ("scan", "scan_raw"), ("/tf", "tf"), ("/tf_static", "tf_static"), ("cmd_vel", "cmd_vel_out"),
    ("image", "camera/image_raw"), ("camera_info", "camera/camera_info"),
    ("odom", "odometry/filtered"), ("imu", "imu/data"), ("points", "lidar/points"),
    ("diagnostics", "/diagnostics"), ("map", "/map"), ("goal_pose", "/goal_pose"),
    ("joint_states", "/joint_states"), ("fix", "gps/fix"), ("battery_state", "/battery"),
)
SUB_NAMESPACES = ("sensors", "drivers", "monitoring", "processing", "internal", "hw", "tools")


# --------------------------------------------------------------------------- elements


@dataclass
class El:
    """One launch entity, rendered to XML or YAML."""

    tag: str
    attrs: dict[str, str | bool] = field(default_factory=dict)
    kids: list[El] = field(default_factory=list)
    comment: str | None = None


ACTION_CONTAINERS = frozenset({"group", "launch"})


def _xml_attr(value: str | bool) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    return value.replace("&", "&amp;").replace("<", "&lt;").replace('"', "&quot;")


def render_xml(root: El, header: bool, comment: str) -> str:
    lines = ['<?xml version="1.0"?>'] if header else []
    lines.append(f"<!-- {comment} -->")
    _xml_lines(root, 0, lines)
    return "\n".join(lines) + "\n"


def _xml_lines(el: El, depth: int, out: list[str]) -> None:
    pad = "  " * depth
    if el.comment:
        out.append(f"{pad}<!-- {el.comment} -->")
    attrs = "".join(f' {k}="{_xml_attr(v)}"' for k, v in el.attrs.items())
    if not el.kids:
        out.append(f"{pad}<{el.tag}{attrs}/>")
        return
    out.append(f"{pad}<{el.tag}{attrs}>")
    for kid in el.kids:
        _xml_lines(kid, depth + 1, out)
    out.append(f"{pad}</{el.tag}>")


_YAML_PLAIN = re.compile(r"^[A-Za-z_/][A-Za-z0-9_./ ()-]*(?<! )$")
_YAML_WORDS = frozenset({"true", "false", "yes", "no", "on", "off", "y", "n", "null"})


def _yaml_scalar(value: str | bool) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if _YAML_PLAIN.match(value) and value.lower() not in _YAML_WORDS:
        return value
    return json.dumps(value)


def _is_leaf(el: El) -> bool:
    return not el.kids and el.tag not in ACTION_CONTAINERS


_YAML_TYPED = re.compile(r"^(-?[0-9]+(\.[0-9]+)?|true|false)$")


def _yaml_value(el: El, key: str, value: str | bool) -> str:
    """Render an attribute; parameter values and delays are typed, as people write them."""
    typed = (el.tag == "param" and key == "value") or key == "respawn_delay"
    if typed and isinstance(value, str) and _YAML_TYPED.match(value):
        return value
    return _yaml_scalar(value)


def _flow(el: El) -> str:
    return "{" + ", ".join(f"{k}: {_yaml_value(el, k, v)}" for k, v in el.attrs.items()) + "}"


def render_yaml(root: El, comment: str) -> str:
    lines = [f"# {comment}", "launch:"]
    for kid in root.kids:
        _yaml_action(kid, 0, lines)
    return "\n".join(lines) + "\n"


def _yaml_action(el: El, indent: int, out: list[str]) -> None:
    """Write ``- tag: ...`` for an action at ``indent``."""
    pad = " " * indent
    if el.comment:
        out.append(f"{pad}# {el.comment}")
    if _is_leaf(el):
        line = f"{pad}- {el.tag}: {_flow(el)}"
        if len(line) <= 96:
            out.append(line)
            return
    out.append(f"{pad}- {el.tag}:")
    _yaml_body(el, indent + 4, out)


def _yaml_body(el: El, indent: int, out: list[str]) -> None:
    """Write the mapping of an entity's attributes, nested entities and children."""
    pad = " " * indent
    for key, value in el.attrs.items():
        out.append(f"{pad}{key}: {_yaml_value(el, key, value)}")
    if el.tag in ACTION_CONTAINERS:
        out.append(f"{pad}children:")
        for kid in el.kids:
            _yaml_action(kid, indent, out)
        return
    nested: dict[str, list[El]] = {}
    for kid in el.kids:
        nested.setdefault(kid.tag, []).append(kid)
    for tag, items in nested.items():
        out.append(f"{pad}{tag}:")
        for item in items:
            _yaml_nested(item, indent, out)


def _yaml_nested(el: El, indent: int, out: list[str]) -> None:
    """Write one nested entity (a param, remap, choice, include arg) as a list item."""
    pad = " " * indent
    if not el.kids:
        line = f"{pad}- {_flow(el)}"
        if len(line) <= 96:
            out.append(line)
            return
    body: list[str] = []
    _yaml_body(el, indent + 2, body)
    out.append(f"{pad}- {body[0].lstrip()}")
    out.extend(body[1:])


# --------------------------------------------------------------------------- model


@dataclass(frozen=True)
class ArgSpec:
    name: str
    default: str | None  # None: required (no default)
    choices: tuple[str, ...] | None = None
    description: str | None = None
    kind: str = "text"  # bool, number, choice, namespace, text, required


@dataclass(eq=False)
class Package:
    name: str
    topic: str
    execs: tuple[str, ...]
    files: list[LaunchFile] = field(default_factory=list)
    depends: set[str] = field(default_factory=set)
    configs: set[str] = field(default_factory=set)


@dataclass(eq=False)
class LaunchFile:
    package: Package
    stem: str
    fmt: str  # "py", "xml" or "yaml"
    level: int
    bringup: bool = False
    declared: dict[str, ArgSpec] = field(default_factory=dict)
    # Node names this file starts (under default arguments), relative to the namespace
    # its includer gives it; a multiset is not needed as they are kept unique.
    fqns: frozenset[str] = frozenset()
    includes: list[LaunchFile] = field(default_factory=list)

    @property
    def filename(self) -> str:
        return f"{self.stem}.launch.{self.fmt}"

    @property
    def key(self) -> str:
        return f"{self.package.name}/{self.filename}"


BOOL_CHOICES = ("true", "false")


def catalog(name: str, rng: random.Random, pkg: Package) -> ArgSpec:
    """Return the declaration of an argument; one spec per name, so choices agree."""
    if name == "use_sim_time":
        return ArgSpec(name, "false", BOOL_CHOICES if rng.random() < 0.3 else None,
                       "Use the simulation clock", "bool")
    if name == "namespace":
        return ArgSpec(name, "", None, "Namespace of the nodes", "namespace")
    if name == "log_level":
        return ArgSpec(name, "info", ("debug", "info", "warn", "error"), "Log level", "choice")
    if name == "mode":
        return ArgSpec(name, "real", ("real", "sim", "replay"), "Where the data comes from",
                       "choice")
    if name == "rate":
        return ArgSpec(name, rng.choice(("10", "20", "30", "50")), None,
                       "Publish rate in Hz", "number")
    if name in ("frame_id", "base_frame"):
        return ArgSpec(name, "base_link", None, None, "text")
    if name == "robot_name":
        return ArgSpec(name, None, None, "Name of the robot (required)", "required")
    if name.startswith("use_"):
        default = "false" if name.removeprefix("use_") in ("debug", "profiling", "fallback") \
            else rng.choice(BOOL_CHOICES)
        return ArgSpec(name, default, None, f"Start the {name[4:]} nodes", "bool")
    if name.endswith("_params_file"):
        exec_name = name.removesuffix("_params_file")
        return ArgSpec(name, f"$(find-pkg-share {pkg.name})/config/{exec_name}.yaml", None,
                       f"Parameters of {exec_name}", "text")
    raise KeyError(name)


def _walk(elements: Iterable[El]) -> Iterable[El]:
    for el in elements:
        yield el
        yield from _walk(el.kids)


def join(*parts: str) -> str:
    return "/".join(p for p in parts if p)


# --------------------------------------------------------------------------- files


class FileBuilder:
    """Builds the body of one launch file and tracks what it declares and starts."""

    def __init__(self, rng: random.Random, lf: LaunchFile, workspace: Workspace) -> None:
        self.rng = rng
        self.lf = lf
        self.pkg = lf.package
        self.ws = workspace
        self.declared: dict[str, ArgSpec] = {}
        self.fqns: set[str] = set()
        self.prefix: list[str] = []  # namespaces pushed by groups of this file
        self.lets: set[str] = set()
        self.pushed: set[str] = set()
        self.set_param_scope = False
        self.preamble: list[El] = []
        self.local_includes: list[tuple[El, LaunchFile]] = []

    # ---- arguments

    def var(self, name: str) -> str:
        if name not in self.declared:
            self.declared[name] = catalog(name, self.rng, self.pkg)
        return f"$(var {name})"

    def feature(self) -> str:
        return self.var(f"use_{self.rng.choice(FEATURES)}")

    def condition(self) -> dict[str, str]:
        """Return an ``if``/``unless`` attribute, or nothing (most actions are plain)."""
        roll = self.rng.random()
        if roll < 0.55:
            return {}
        if roll < 0.75:
            return {"if": self.feature()}
        if roll < 0.83:
            return {"unless": self.var("use_sim_time")}
        if roll < 0.90:
            return {"if": f"$(equals {self.var('mode')} {self.rng.choice(('real', 'sim'))})"}
        if roll < 0.95:
            threshold = self.rng.choice(("10", "20", "25", "40"))
            return {"if": f"$(eval '{self.var('rate')} >= {threshold}')"}
        return {"unless": f"$(eval \"'{self.var('mode')}' == 'replay'\")"}

    # ---- names

    def claim(self, fqn_parts: Iterable[str]) -> bool:
        fqn = join(*self.prefix, *fqn_parts)
        if fqn in self.fqns:
            return False
        self.fqns.add(fqn)
        return True

    def unique_name(self, base: str, namespace: str = "") -> str:
        for suffix in ("", "_2", "_3", "_aux", "_backup", "_secondary"):
            name = base + suffix
            if self.claim((namespace, name)):
                return name
        index = 4
        while not self.claim((namespace, f"{base}_{index}")):
            index += 1
        return f"{base}_{index}"

    def fresh_namespace(self, base: str) -> str:
        """Return a namespace token not yet pushed at this level of this file."""
        token = base
        index = 2
        while self.taken(join(*self.prefix, token)):
            token = f"{base}_{index}"
            index += 1
        self.pushed.add(join(*self.prefix, token))
        return token

    def taken(self, namespace: str) -> bool:
        """Return whether a namespace is pushed already or holds a node of this file."""
        return namespace in self.pushed or any(
            f.startswith(namespace + "/") for f in self.fqns)

    # ---- nodes

    def params(self, node_pkg: Package | None, exec_name: str) -> list[El]:
        rng = self.rng
        out: list[El] = []
        if node_pkg is not None and rng.random() < 0.7:
            node_pkg.configs.add(exec_name)
            if rng.random() < 0.35 and node_pkg is self.pkg:
                path = self.var(f"{exec_name}_params_file")
            else:
                path = f"$(find-pkg-share {node_pkg.name})/config/{exec_name}.yaml"
                if node_pkg is not self.pkg:
                    self.pkg.depends.add(node_pkg.name)
            out.append(El("param", {"from": path}))
        if not self.set_param_scope and rng.random() < 0.6:
            out.append(El("param", {"name": "use_sim_time", "value": self.var("use_sim_time")}))
        for pname, values in rng.sample(PARAM_LITERALS, rng.randint(0, 3)):
            out.append(El("param", {"name": pname, "value": rng.choice(values)}))
        roll = rng.random()
        if roll < 0.25:
            out.append(El("param", {"name": "publish_rate", "value": self.var("rate")}))
        elif roll < 0.4:
            out.append(El("param", {"name": "frame_id", "value": self.var("frame_id")}))
        elif roll < 0.5:
            let = self.let_period()
            out.append(El("param", {"name": "period", "value": f"$(var {let})"}))
        if rng.random() < 0.12:
            out.append(El("param", {"name": "qos"}, [
                El("param", {"name": "depth", "value": rng.choice(("1", "10", "50"))}),
                El("param", {"name": "durability", "value": "volatile"}),
            ]))
        if "robot_name" in self.declared and rng.random() < 0.8:
            out.append(El("param", {"name": "robot_name", "value": "$(var robot_name)"}))
        return out

    def let_period(self) -> str:
        """Return a configuration computed once per file with ``<let>`` and ``$(eval)``."""
        name = f"{self.pkg.topic}_period"
        if name not in self.lets:
            self.lets.add(name)
            self.preamble.append(El("let", {
                "name": name, "value": f"$(eval '1.0 / {self.var('rate')}')"}))
        return name

    def remaps(self) -> list[El]:
        count = self.rng.choice((0, 0, 1, 1, 1, 2, 3))
        return [El("remap", {"from": a, "to": b}) for a, b in self.rng.sample(REMAPS, count)]

    def own_node(self, namespace: str = "", attrs: dict[str, str] | None = None,
                 name: str | None = None, exec_name: str | None = None) -> El:
        rng = self.rng
        roll = rng.random()
        node_pkg: Package | None
        if roll < 0.8 or exec_name is not None:
            node_pkg = self.pkg
        elif roll < 0.9:
            node_pkg = rng.choice(self.ws.packages)
        else:
            node_pkg = None
        if node_pkg is None:
            package, exec_name = rng.choice(RELEASED_NODES)
            base = name or f"{self.pkg.topic}_{exec_name.removesuffix('_node')}"
        else:
            package = node_pkg.name
            exec_name = exec_name or rng.choice(node_pkg.execs)
            base = name or exec_name
            if node_pkg is not self.pkg:
                self.pkg.depends.add(node_pkg.name)
        node_attrs: dict[str, str | bool] = {"pkg": package, "exec": exec_name}
        node_attrs["name"] = self.unique_name(base, namespace) if name is None else name
        if namespace:
            node_attrs["namespace"] = namespace
        if rng.random() < 0.6:
            node_attrs["output"] = rng.choice(("screen", "log", "both"))
        if rng.random() < 0.25:
            node_attrs["ros_args"] = f"--log-level {self.var('log_level')}"
        if rng.random() < 0.08:
            node_attrs["respawn"] = True
            node_attrs["respawn_delay"] = rng.choice(("1.0", "2.0", "5.0"))
        if package == "tf2_ros":
            child = rng.choice(("laser", "camera", "imu", "gps", "arm_base", "dock"))
            node_attrs["args"] = (
                f"--x {rng.choice(('0.0', '0.1', '0.25'))} --y 0.0 "
                f"--z {rng.choice(('0.05', '0.2', '0.5'))} "
                f"--frame-id base_link --child-frame-id {child}_link"
            )
        elif package == "topic_tools":
            node_attrs["args"] = f"{self.pkg.topic}/status {self.pkg.topic}/status_relay"
        node_attrs.update(attrs or {})
        kids = self.params(node_pkg, exec_name) if package != "tf2_ros" else []
        kids += self.remaps()
        return El("node", node_attrs, kids)

    # ---- blocks

    def node_block(self) -> list[El]:
        rng = self.rng
        roll = rng.random()
        if roll < 0.55:
            return [self.own_node(rng.choice(("",) * 5 + SUB_NAMESPACES), self.condition())]
        if roll < 0.72:  # a conditional group
            group = El("group", self.condition() or {"if": self.feature()})
            group.kids = [self.own_node() for _ in range(rng.randint(1, 3))]
            return [group]
        if roll < 0.87:  # a namespaced, scoped group with remaps and parameters
            token = self.fresh_namespace(rng.choice(SUB_NAMESPACES))
            group = El("group", self.condition())
            group.kids.append(El("push_ros_namespace", {"namespace": token}))
            for a, b in rng.sample(REMAPS, rng.randint(0, 2)):
                group.kids.append(El("set_remap", {"from": a, "to": b}))
            if rng.random() < 0.3:
                group.kids.append(El("set_parameter", {
                    "name": "use_sim_time", "value": self.var("use_sim_time")}))
            self.prefix.append(token)
            group.kids += [self.own_node() for _ in range(rng.randint(1, 3))]
            self.prefix.pop()
            return [group]
        if roll < 0.95:  # the same node name in exclusive sim/real groups
            exec_name = rng.choice(self.pkg.execs)
            name = self.unique_name(exec_name)
            sim_flag = self.var("use_sim_time")
            return [
                El("group", {"if": sim_flag},
                   [self.own_node(name=name, exec_name=exec_name)],
                   comment="simulated and real variants share a name"),
                El("group", {"unless": sim_flag}, [self.own_node(name=name, exec_name=exec_name)]),
            ]
        if rng.random() < 0.5:
            return [El("executable", {
                "cmd": f"ros2 bag record -o {self.pkg.topic}_bag /{self.pkg.topic}/status",
                "output": "screen", "if": self.var("use_recording")})]
        return [El("log", {"message": f"starting {self.lf.stem} of {self.pkg.name}"})]

    def include_block(self, target: LaunchFile) -> list[El]:
        rng = self.rng
        self.lf.includes.append(target)
        if target.package is not self.pkg:
            self.pkg.depends.add(target.package.name)
        folder = f"$(find-pkg-share {target.package.name})/launch"
        include = El("include", {"file": f"{folder}/{target.filename}"})
        if target.package is self.pkg:
            self.local_includes.append((include, target))
        inner_ns = ""
        for name, spec in target.declared.items():
            value: str | None = None
            if spec.kind == "required":
                value = self.var(name) if name in self.declared else \
                    rng.choice(("robot1", "atlas", "rover"))
            elif spec.kind == "namespace":
                inner_ns = self.fresh_namespace(target.stem)
                value = inner_ns
            elif name == "use_sim_time":
                value = self.var(name) if rng.random() < 0.9 else None
            elif name == "log_level":
                value = self.var(name) if rng.random() < 0.5 else None
            elif rng.random() < 0.2:
                if spec.choices:
                    value = rng.choice(spec.choices)
                elif spec.kind == "bool":
                    value = rng.choice(BOOL_CHOICES)
                elif spec.kind == "number":
                    value = rng.choice(("5", "15", "25", "60"))
                elif name in ("frame_id", "base_frame"):
                    value = rng.choice(("base_link", "base_footprint", "odom"))
            if value is not None:
                include.kids.append(El("arg", {"name": name, "value": value}))
        # A scoped group per include keeps its arguments from leaking to the next one;
        # push a namespace when names would collide (or, often, for tidiness).
        group = El("group", self.condition() if rng.random() < 0.6 else {})
        push = ""
        names = {join(*self.prefix, inner_ns, f) for f in target.fqns}
        if names & self.fqns or rng.random() < (0.1 if inner_ns else 0.4):
            push = self.fresh_namespace(target.package.topic if inner_ns else target.stem)
            group.kids.append(El("push_ros_namespace", {"namespace": push}))
            names = {join(*self.prefix, push, inner_ns, f) for f in target.fqns}
        if names & self.fqns:  # cannot happen with a fresh namespace; keep it loud
            raise AssertionError(f"duplicate names including {target.key} from {self.lf.key}")
        self.fqns |= names
        group.kids.append(include)
        return [group]

    # ---- whole file

    def build(self, targets: list[LaunchFile]) -> El:
        rng = self.rng
        lf = self.lf
        body: list[El] = []
        if rng.random() < 0.08 and not lf.bringup and lf.level == 0:
            self.var("robot_name")  # a file meant to be included: required argument
        if rng.random() < 0.35:
            self.set_param_scope = True
            body.append(El("set_parameter", {"name": "use_sim_time",
                                             "value": self.var("use_sim_time")}))
        if rng.random() < 0.3:
            for a, b in rng.sample(REMAPS[:3], rng.randint(1, 2)):
                body.append(El("set_remap", {"from": a, "to": b}))
        use_ns = not lf.bringup and rng.random() < 0.35
        if use_ns:
            self.var("namespace")
        own = rng.randint(1, 5) if lf.level == 0 else rng.randint(0, 3)
        if lf.bringup:
            own = rng.randint(2, 4)
        blocks: list[list[El]] = [self.node_block() for _ in range(own)]
        for target in targets:
            blocks.insert(rng.randint(0, len(blocks)), self.include_block(target))
        for block in blocks:
            body.extend(block)
        self.use_dirname(blocks)
        if "robot_name" in self.declared:
            self.read_robot_name(body)
        if lf.bringup:
            body.insert(len(body) - sum(map(len, blocks)), El("node", {
                "pkg": "robot_state_publisher", "exec": "robot_state_publisher",
                "name": self.unique_name("robot_state_publisher"), "output": "screen"}, [
                El("param", {"name": "use_sim_time", "value": self.var("use_sim_time")}),
                El("param", {"name": "publish_frequency", "value": "50.0"}),
            ]))
        if use_ns:
            body = [El("group", {}, [
                El("push_ros_namespace", {"namespace": "$(var namespace)"}), *body])]
        decls = [self.declaration(spec) for spec in self.declared.values()]
        return El("launch", {}, [*decls, *self.preamble, *body])

    def read_robot_name(self, body: list[El]) -> None:
        """Make sure a declared ``robot_name`` is read (a node parameter, else a log)."""
        wanted = "$(var robot_name)"
        elements = list(_walk(body))
        if any(wanted in str(v) for el in elements for v in el.attrs.values()):
            return
        nodes = [el for el in elements if el.tag == "node" and el.attrs["pkg"] != "tf2_ros"]
        if nodes:
            nodes[0].kids.insert(0, El("param", {"name": "robot_name", "value": wanted}))
        else:
            body.append(El("log", {"message": f"{self.lf.stem} ready on {wanted}"}))

    def use_dirname(self, blocks: list[list[El]]) -> None:
        """Write the file's first include as ``$(dirname)/...`` when it is a sibling file.

        Only the first: until rolling, launch does not restore ``$(dirname)`` after an
        include (ros2/launch#618), so a later ``$(dirname)`` names the last included
        file's folder.
        """
        first = next((el for block in blocks for el in _walk(block) if el.tag == "include"),
                     None)
        for include, target in self.local_includes:
            if include is first and self.rng.random() < 0.5:
                include.attrs["file"] = f"$(dirname)/{target.filename}"

    def declaration(self, spec: ArgSpec) -> El:
        attrs: dict[str, str | bool] = {"name": spec.name}
        if spec.default is not None:
            attrs["default"] = spec.default
        if spec.description and self.rng.random() < 0.6:
            attrs["description"] = spec.description
        kids = [El("choice", {"value": c}) for c in spec.choices or ()]
        return El("arg", attrs, kids)


# --------------------------------------------------------------------------- workspace


class Workspace:
    """All packages and launch files, planned then built level by level."""

    def __init__(self, files: int, seed: int) -> None:
        self.rng = random.Random(seed)
        self.packages = [
            Package(f"{PREFIX}_{topic}", topic, execs) for topic, execs in PACKAGES
        ]
        self.files: list[LaunchFile] = []
        self.rendered: dict[LaunchFile, str] = {}
        self.plan(files)
        self.build()

    def plan(self, total: int) -> None:
        rng = self.rng
        bringups = min(len(BRINGUP_STEMS), max(2, total // 100))
        bringup_pkg = self.packages[0]
        for stem in BRINGUP_STEMS[:bringups]:
            self.add(bringup_pkg, stem, 6, bringup=True)
        weights = [1.0] + [rng.uniform(0.6, 1.4) for _ in self.packages[1:]]
        used: dict[str, set[str]] = {p.name: {f.stem for f in p.files} for p in self.packages}
        remaining = total - bringups
        levels = self.level_counts(remaining)
        order = [lvl for lvl, count in enumerate(levels) for _ in range(count)]
        rng.shuffle(order)
        for level in order:
            pkg = rng.choices(self.packages, weights)[0]
            self.add(pkg, self.stem(pkg, used[pkg.name]), level)

    def level_counts(self, total: int) -> list[int]:
        counts = [max(1, int(total * w)) for w in LEVEL_WEIGHTS]
        counts[0] += total - sum(counts)
        return counts

    def stem(self, pkg: Package, used: set[str]) -> str:
        rng = self.rng
        for _ in range(30):
            qualifier = rng.choice(QUALIFIERS)
            stem = join(pkg.topic, qualifier).replace("/", "_")
            if stem not in used:
                used.add(stem)
                return stem
        index = 2
        while f"{pkg.topic}_{index}" in used:
            index += 1
        used.add(f"{pkg.topic}_{index}")
        return f"{pkg.topic}_{index}"

    def add(self, pkg: Package, stem: str, level: int, bringup: bool = False) -> None:
        roll = self.rng.random()
        fmt = ("py" if roll < PYTHON_SHARE
               else "yaml" if roll < PYTHON_SHARE + YAML_SHARE else "xml")
        lf = LaunchFile(pkg, stem, fmt, level, bringup)
        pkg.files.append(lf)
        self.files.append(lf)

    def choose_targets(self, lf: LaunchFile, by_level: list[list[LaunchFile]]) -> list[LaunchFile]:
        rng = self.rng
        if lf.level == 0:
            return []

        def pick(levels: Iterable[int]) -> LaunchFile | None:
            pool = [f for lvl in levels for f in by_level[lvl]]
            if not pool:
                return None
            local = [f for f in pool if f.package is lf.package]
            if local and rng.random() < 0.5:
                return rng.choice(local)
            return rng.choice(pool)

        targets: list[LaunchFile] = []
        if lf.bringup:
            deepest = max((lvl for lvl in range(MAX_LEVEL + 1) if by_level[lvl]), default=0)
            first = pick([deepest])
            if first:
                targets.append(first)
            for _ in range(rng.randint(8, 15)):
                candidate = pick(range(max(0, deepest - 3), deepest + 1))
                if candidate and candidate not in targets:
                    targets.append(candidate)
            return targets
        first = pick([lf.level - 1])
        if first is None:
            return []
        targets.append(first)
        for _ in range(rng.choice((0, 0, 1, 1, 2))):
            candidate = pick(range(lf.level))
            if candidate and candidate not in targets:
                targets.append(candidate)
        return targets

    def build(self) -> None:
        by_level: list[list[LaunchFile]] = [[] for _ in range(MAX_LEVEL + 2)]
        for level in range(MAX_LEVEL + 2):
            for lf in [f for f in self.files if f.level == level]:
                builder = FileBuilder(self.rng, lf, self)
                root = builder.build(self.choose_targets(lf, by_level))
                lf.declared = builder.declared
                lf.fqns = frozenset(builder.fqns)
                comment = f"{lf.stem} of {lf.package.name} (generated by bench/generate.py)"
                if lf.fmt == "xml":
                    text = render_xml(root, self.rng.random() < 0.5, comment)
                elif lf.fmt == "yaml":
                    text = render_yaml(root, comment)
                else:
                    text = render_python(root, comment)
                self.rendered[lf] = text
                by_level[level].append(lf)

    def depth(self) -> int:
        memo: dict[str, int] = {}

        def depth_of(lf: LaunchFile) -> int:
            if lf.key not in memo:
                memo[lf.key] = max((1 + depth_of(t) for t in lf.includes), default=0)
            return memo[lf.key]

        return max(depth_of(lf) for lf in self.files)

    # ---- writing

    def write(self, out: Path) -> None:
        src = out / "src"
        for pkg in self.packages:
            folder = src / pkg.name
            (folder / "launch").mkdir(parents=True, exist_ok=True)
            (folder / "package.xml").write_text(package_xml(pkg), encoding="utf-8")
            (folder / "CMakeLists.txt").write_text(cmakelists(pkg), encoding="utf-8")
            if pkg.configs:
                (folder / "config").mkdir(exist_ok=True)
            for exec_name in sorted(pkg.configs):
                (folder / "config" / f"{exec_name}.yaml").write_text(
                    param_file(self.rng, exec_name), encoding="utf-8")
            for lf in pkg.files:
                (folder / "launch" / lf.filename).write_text(self.rendered[lf], encoding="utf-8")


def package_xml(pkg: Package) -> str:
    depends = "".join(f"  <exec_depend>{d}</exec_depend>\n" for d in sorted(pkg.depends))
    return (
        '<?xml version="1.0"?>\n'
        '<?xml-model href="http://download.ros.org/schema/package_format3.xsd" '
        'schematypens="http://www.w3.org/2001/XMLSchema"?>\n'
        '<package format="3">\n'
        f"  <name>{pkg.name}</name>\n"
        "  <version>0.3.1</version>\n"
        f"  <description>ACME robot: {pkg.topic} nodes and launch files.</description>\n"
        '  <maintainer email="robots@acme.example">ACME Robotics</maintainer>\n'
        "  <license>Apache-2.0</license>\n"
        "  <buildtool_depend>ament_cmake</buildtool_depend>\n"
        f"{depends}"
        "  <export>\n    <build_type>ament_cmake</build_type>\n  </export>\n"
        "</package>\n"
    )


def cmakelists(pkg: Package) -> str:
    dirs = "launch config" if pkg.configs else "launch"
    executables = "".join(f"add_executable({e} src/{e}.cpp)\n" for e in pkg.execs)
    return (
        "cmake_minimum_required(VERSION 3.8)\n"
        f"project({pkg.name})\n\n"
        "find_package(ament_cmake REQUIRED)\n"
        "find_package(rclcpp REQUIRED)\n\n"
        f"{executables}"
        f"install(TARGETS {' '.join(pkg.execs)}\n  DESTINATION lib/${{PROJECT_NAME}})\n"
        f"install(DIRECTORY {dirs} DESTINATION share/${{PROJECT_NAME}})\n\n"
        "ament_package()\n"
    )


def param_file(rng: random.Random, exec_name: str) -> str:
    # nodes loading the file may be renamed or namespaced: a wildcard block fits them all
    rng.random()  # (kept: the same seed gives the same tree as before otherwise)
    header = "/**"
    lines = [f"{header}:", "  ros__parameters:"]
    for pname, values in rng.sample(PARAM_LITERALS, rng.randint(2, 6)):
        value = rng.choice(values)
        lines.append(f"    {pname}: {json.dumps(value) if value.startswith('/') else value}")
    if rng.random() < 0.3:
        lines += ["    limits:", f"      max_velocity: {rng.choice(('0.5', '1.0', '2.0'))}",
                  f"      max_acceleration: {rng.choice(('0.5', '1.5'))}"]
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------- main


def stamp_of(files: int, seed: int) -> dict[str, int]:
    return {"generator": GENERATOR_VERSION, "files": files, "seed": seed}


def is_current(out: Path, files: int, seed: int) -> bool:
    """Return whether ``out`` already holds the tree for these settings."""
    try:
        found = json.loads((out / STAMP).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return False
    return bool(found == stamp_of(files, seed))


def generate(out: Path, files: int = 500, seed: int = 1) -> Workspace:
    """Replace ``out`` with a freshly generated workspace and return its model."""
    if out.exists():
        if not (out / STAMP).is_file() and any(out.iterdir()):
            raise SystemExit(f"refusing to replace {out}: not a generated tree (no {STAMP})")
        shutil.rmtree(out)
    workspace = Workspace(files, seed)
    workspace.write(out)
    (out / STAMP).write_text(json.dumps(stamp_of(files, seed)) + "\n", encoding="utf-8")
    return workspace


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--files", type=int, default=500, help="launch files (default 500)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--out", type=Path, default=DEFAULT_OUT)
    args = parser.parse_args(argv)
    if args.files < 10:
        parser.error("--files must be at least 10")
    ws = generate(args.out, args.files, args.seed)
    count = {fmt: sum(1 for f in ws.files if f.fmt == fmt) for fmt in ("py", "xml", "yaml")}
    edges = sum(len(f.includes) for f in ws.files)
    print(f"wrote {len(ws.files)} launch files ({count['py']} Python, {count['xml']} XML, "
          f"{count['yaml']} YAML) in "
          f"{len(ws.packages)} packages to {args.out}; {edges} includes, depth {ws.depth()}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
